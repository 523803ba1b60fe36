// Isotropic surface tension on a body's surface (the Gurtin-Murdoch surface stress
// varsigma = gamma * (identity on the surface) of the MDWM, seed Eq. 15-17).
//
// For an isotropic surface stress the surface weak form of Eq. 17 is the variation of
// the energy E = gamma * A(x): the current area of the surface. A is measured on the
// boundary faces of the cloud's mesh at the PHYSICAL positions of the face nodes,
// p_J = X_J + u(X_J) = X_J + sum_I Psi_I(X_J) d_I (body.hpp):
//   * a triangle (a, b, c): |(b - a) x (c - a)| / 2;
//   * a quadrilateral (0, 1, 2, 3): the mean of its two triangulations,
//     (A012 + A023 + A123 + A130) / 2 - symmetric in the nodes and exact when planar.
// The force is the exact gradient with respect to the generalized coordinates,
// f_I = -gamma sum_J Psi_I(X_J) dA/dp_J: for a triangle dA/da = n x (c - b) / 2 with
// n the unit normal (and cyclically). Why the physical positions: the tension pulls
// every surface node inwards; applied to the generalized positions X + d it also
// drives the boundary nodes' d away from the field they interpolate, a mode only the
// stabilization (proportional to mu) resists, and a body soft against gamma / R
// (a drop, a cube becoming a sphere) lets its faceted surface collapse inwards while
// its volume stays. On the physical surface the energy depends on the field alone.
// A is homogeneous of degree 2 in the positions, so at equilibrium the mean pressure
// inside a body is about 2 gamma A / (3 v), i.e. 2 gamma / R for a sphere (Young-Laplace).
// Bodies built without RK operators (tests) use p = X + d.
// Distributed: a face belongs to the rank that owns its lowest node. That rank pulls the
// physical points of the face's other nodes from their owners and pushes the area
// gradient it puts on them back; the area and the step limit are reduced over the ranks.
#pragma once

#include "rkpm/par/ghost_exchange.hpp"
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
  SurfaceTension(Body& body, const std::string& surface, double gamma, const par::Comm& comm = par::Comm::self());
  std::string name() const override { return "surface_tension"; }
  bool distributed() const override { return true; }
  void add_forces(World& world) override;
  double stored_energy(const World&) const override { return gamma_ * area_; }
  // Critical step of the tension's stiffness. Moving a node of a face by delta out of
  // its plane changes the area by delta^2 e^2 / (8 A) (e the opposite edge), so a
  // face's Hessian blocks are bounded by k_f = gamma D_f^2 / A_f, D_f its longest node
  // distance (a quadrilateral's diagonal); Gershgorin over the n_f nodes of each face:
  // omega^2 <= max_I sum_{f at I} n_f k_f / m_I, dt = 2 / omega. It is conservative by
  // about 4 on a flat square grid; it matters when the tension is stiff against the
  // material (soft bodies, drops).
  double stable_dt(const World&) const override;
  void report(const World&, io::Json& summary) const override;

  double area() const { return area_; }                  // at the last force evaluation [m^2]
  double initial_area() const { return initial_area_; }  // at construction [m^2]
  // Current area at the body's present positions (no forces; collective).
  double measure_area() const;

 private:
  // Physical positions of the nodes of this rank's faces (entries of other particles
  // are untouched).
  void update_points() const;

  Body& body_;
  const par::Comm& comm_;
  std::string surface_;
  std::vector<std::int32_t> faces_;  // this rank's faces: indices into cloud.boundary_faces
  std::vector<Index> nodes_;         // particles on every rank's faces, increasing
  par::GhostExchange face_ghosts_;   // distributed: the nodes of this rank's faces it does not own
  mutable std::vector<Vec3> points_; // physical positions, indexed by particle
  std::vector<Vec3> gradient_;       // dA/dp at the face nodes, indexed by particle
  // The faces' sums at their nodes (channel 0: dA/dp; 1: the stiffness rows of the
  // stable step), and the transfer to the particles, in the one-process order.
  mutable rk::RowScatter face_sums_;
  rk::RowScatter transfer_;
  double gamma_;
  double area_ = 0.0, initial_area_ = 0.0;
};

}  // namespace rkpm::sim
