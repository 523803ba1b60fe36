// The physics terms a scene can declare in [[term]] tables, created by name.
#pragma once

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/world.hpp"

#include <memory>

namespace rkpm::sim {

// Creates the term a [[term]] table declares. Throws SetupError for a term type
// this version cannot build.
std::unique_ptr<Term> make_term(const scene::TermSpec& spec, World& world);

// Uniform acceleration (gravity, a centrifuge): f_I = m_I g.
class BodyForce final : public Term {
 public:
  BodyForce(Body& body, const Vec3& acceleration) : body_(body), g_(acceleration) {}
  std::string name() const override { return "body_force"; }
  void add_forces(World&) override;
  double power(const World&) const override;

 private:
  Body& body_;
  Vec3 g_;
};

// Follower pressure on a named surface: traction -p n in the current configuration,
// integrated with the boundary quadrature of the SCNI cells. By Nanson's formula the
// current area vector of a facet of cell L is J_L F_L^-T A, with the smoothed F_L:
//   f_I = -p sum_f Psi_I(X_f) J_L F_L^-T A_f.
class SurfacePressure final : public Term {
 public:
  SurfacePressure(Body& body, std::uint32_t surface_bit, double pressure);
  std::string name() const override { return "surface_pressure"; }
  void add_forces(World&) override;
  double power(const World&) const override;

 private:
  Body& body_;
  std::vector<std::size_t> facets_;  // boundary-quadrature points on the surface
  double pressure_;
  std::vector<Vec3> force_;          // last forces, for the power
};

}  // namespace rkpm::sim
