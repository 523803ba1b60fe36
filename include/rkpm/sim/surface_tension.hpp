// Isotropic surface tension on a body's surface (the Gurtin-Murdoch surface stress
// varsigma = gamma * (identity on the surface) of the MDWM, seed Eq. 15-17).
//
// For an isotropic surface stress the surface weak form of Eq. 17 is the variation of
// the energy E = gamma * A(x): the current area of the surface. A is measured on the
// boundary faces of the cloud's mesh at the generalized positions x = X + d (body.hpp):
//   * a triangle (a, b, c): |(b - a) x (c - a)| / 2;
//   * a quadrilateral (0, 1, 2, 3): the mean of its two triangulations,
//     (A012 + A023 + A123 + A130) / 2 - symmetric in the nodes and exact when planar.
// The force is the exact gradient, f_I = -gamma dA/dx_I, acting on the face nodes'
// generalized coordinates: for a triangle dA/da = n x (c - b) / 2 with n the unit
// normal (and cyclically). A is homogeneous of degree 2 in x, so at equilibrium the
// discrete virial sum_L v_L tr(sigma_L) = -2 gamma A holds: the mean pressure inside
// a body is 2 gamma A / (3 v), i.e. 2 gamma / R for a sphere (Young-Laplace).
#pragma once

#include "rkpm/sim/world.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace rkpm::sim {

// Area of one boundary face at positions x; adds dA/dx of its nodes to grad[k]
// (k = the face's node slot) when grad is not null.
double face_area(const particles::BoundaryFace& face, const std::vector<Vec3>& x, Vec3* grad);

class SurfaceTension final : public Term {
 public:
  // surface = "all": every boundary face; otherwise the faces all of whose nodes lie
  // on that named surface of the cloud (std::invalid_argument if it has none such).
  SurfaceTension(Body& body, const std::string& surface, double gamma);
  std::string name() const override { return "surface_tension"; }
  void add_forces(World& world) override;
  double stored_energy(const World&) const override { return gamma_ * area_; }
  void report(const World&, io::Json& summary) const override;

  double area() const { return area_; }                  // at the last force evaluation [m^2]
  double initial_area() const { return initial_area_; }  // at construction [m^2]
  // Current area at the body's present positions (no forces).
  double measure_area() const;

 private:
  Body& body_;
  std::string surface_;
  std::vector<std::int32_t> faces_;  // indices into cloud.boundary_faces
  double gamma_;
  double area_ = 0.0, initial_area_ = 0.0;
};

}  // namespace rkpm::sim
