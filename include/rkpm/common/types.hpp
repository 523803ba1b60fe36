// Basic numeric types shared by every part of the simulator.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include <cstdint>

namespace rkpm {

using Vec3 = Eigen::Vector3d;
using Vec3f = Eigen::Vector3f;  // single-precision storage of operator entries; arithmetic stays in double
using Mat3 = Eigen::Matrix3d;
using Index = std::int32_t;  // particle / integration-point ids; 2^31 is far beyond one node's memory

}  // namespace rkpm
