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

#include "terms/contact/settings.hpp"
#include "rkpm/io/json.hpp"
#include "rkpm/par/shared_particles.hpp"
#include "rkpm/sim/body.hpp"

#include <array>
#include <cstdint>
#include <optional>
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

// Molecules per reference volume of a body: beta, or for beta = 0 the body's particle
// number density N / V ("one molecule per particle"), summed in the one-rank order.
double molecule_density(const Body& body, double beta);

// Closest point of triangle (a, b, c) to p, with its barycentric weights in w.
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, std::array<double, 3>& w);

// A contact term's report over a run (its `report_surface` key, either formulation):
// samples the present state for history.csv and keeps the first sample and the
// smallest gap for the summary. Without the key nothing is measured.
class ContactReportLog {
 public:
  ContactReportLog(const Body& cell, const Body& substrate, const ContactSettings& settings, const par::Comm& comm);
  bool declared() const { return report_.has_value(); }
  // Measures the present state (collective when distributed); declared() must hold.
  ContactSample sample() const;
  std::vector<std::string> history_columns() const;
  std::string history_values() const;
  // The "report" object of the term's summary (nothing before the first sample).
  void add_to(io::Json& term_summary) const;

 private:
  std::optional<ContactReport> report_;
  mutable std::optional<ContactSample> first_sample_, last_sample_;
  mutable double smallest_gap_ = 0.0;
};

// A contact term's output fields for `body`: "contact_force_<other body>", the forces
// on the physical points of a (force[0]) or of b (force[1]); none for another body.
std::vector<materials::OutputField> contact_force_fields(const Body& body, const Body& a, const Body& b,
                                                         const std::array<std::vector<Vec3>, 2>& force);

// The diagnosis of a boundary particle found `depth` inside the other body's surface
// (more than s0/2): at step 0 the scene placed the bodies overlapping, later the
// contact law did not hold them apart.
std::string interpenetration_message(std::int64_t step, const Body& inside, const Body& other, std::int64_t id,
                                     const Vec3& reference, const Vec3& current, double depth, double s0);

}  // namespace rkpm::sim
