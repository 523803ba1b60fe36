// NumPy arrays of a body's fields: views of the state where it is stored contiguously
// (read-only, kept alive by the Simulation they belong to), copies of what is computed.
#pragma once

#include "rkpm/common/types.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

namespace rkpm::python {

namespace py = pybind11;

// (n, 3) float64 view of Vec3s, or (n,) of doubles; `owner` keeps the memory alive.
py::array vectors_view(const std::vector<Vec3>& values, py::handle owner);
py::array scalars_view(const std::vector<double>& values, py::handle owner);
// (n, 3, 3) float64 view of 3 x 3 matrices (Eigen stores them column by column).
py::array matrices_view(const std::vector<Mat3>& values, py::handle owner);
// (n, components) float64 view of n x components packed doubles, or (n,) for 1.
py::array field_view(const double* values, std::size_t n, int components, py::handle owner);
// A copy of n x components values as an (n, components) array, or (n,) for 1, (n, 3, 3) for 9.
py::array copied(std::vector<double>&& values, int components);

}  // namespace rkpm::python
