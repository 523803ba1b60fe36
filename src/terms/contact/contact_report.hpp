// What a scene with adhesive contact reports over time: where the first body (the
// cell) is, how close it comes to the second (the substrate), and how large their
// contact patch is. Declared by the contact term's `report_surface` key; a scene
// without it (or without contact) computes none of this.
//
// Measured on the physical positions X + u(X) (body.hpp):
//   * centroid: the first body's centre of mass, sum m_I x_I / M (generalized
//     positions: with lumped masses this is the point whose motion the total force
//     drives);
//   * gap of a boundary particle of the first body: its signed distance to the
//     nearest triangle of the second body's `report_surface` (quadrilateral faces
//     split along their 0-2 diagonal), positive on the side the face's outward normal
//     points to; negative = interpenetration;
//   * min_gap: the smallest such gap;
//   * contact patch: the boundary particles whose gap is below `contact_gap` (the
//     potential's s0 by default: the flat-body equilibrium gap is 0.64 s0);
//     contact_radius is their largest distance from the patch's centre, measured in
//     the plane normal to the mean normal of their nearest faces.
#pragma once

#include "rkpm/par/shared_particles.hpp"
#include "rkpm/sim/body.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rkpm::sim {

struct ContactSample {
  Vec3 centroid = Vec3::Zero();
  double min_gap = 0.0;          // [m]; = search range when nothing is within it
  double contact_radius = 0.0;   // [m]
  std::int64_t contact_particles = 0;
  Index deepest = -1;            // the cell's boundary particle at min_gap (-1: none within range)
  Vec3 deepest_position = Vec3::Zero();  // its physical position [m]
};

class ContactReport {
 public:
  // `surface` must name a surface of `substrate` (std::invalid_argument otherwise).
  // Faces farther than `range` from a particle are not searched.
  // Distributed: `comm` holds the bodies' ranks; each measure gathers the points it
  // reads to every rank (a surface: small next to the bodies) and is collective.
  ContactReport(const Body& cell, const Body& substrate, const std::string& surface, double contact_gap,
                double range, const par::Comm& comm = par::Comm::self());
  ContactSample measure() const;
  // Whether `p` lies inside the closed surface the substrate's faces form at the last
  // measure() (generalized winding number, |w| > 1/2): a check of the nearest face's
  // sign where faces meet at a sharp edge. Meaningful only for surface = "all".
  bool encloses(const Vec3& p) const;

  const std::string& surface() const { return surface_; }
  double contact_gap() const { return contact_gap_; }

 private:
  const Body& cell_;
  const Body& substrate_;
  std::string surface_;
  double contact_gap_, range_;
  const par::Comm& comm_;
  std::vector<std::array<Index, 3>> triangles_;  // substrate particles, outward order
  std::vector<Index> corners_;                   // their particles, increasing
  std::vector<Index> cell_particles_;            // the cell's boundary particles
  par::SharedParticles shared_corners_, shared_cell_;  // distributed: gathered to every rank
  mutable std::vector<Vec3> corner_positions_;         // physical, at the last measure()
};

}  // namespace rkpm::sim
