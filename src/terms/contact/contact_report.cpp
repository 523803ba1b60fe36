#include "terms/contact/contact_report.hpp"

#include "rkpm/sim/body_points.hpp"

#include "rkpm/rk/neighbor_search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rkpm::sim {

// beta, or for beta = 0 the body's particle number density N / V (as the pair sum's
// "one molecule per particle"), summed in the one-rank order.
double molecule_density(const Body& body, double beta) {
  if (beta > 0.0) return beta;
  double total = 0.0;
  for (Index i : one_rank_order(body)) total += body.cloud.volume[i];
  return static_cast<double>(body.size()) / total;
}

// Closest point of triangle (a, b, c) to p and its barycentric weights (Ericson,
// Real-Time Collision Detection, 5.1.5, written with the weights kept).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, std::array<double, 3>& w) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) {
    w = {1, 0, 0};
    return a;
  }
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) {
    w = {0, 1, 0};
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    w = {1 - t, t, 0};
    return a + t * ab;
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) {
    w = {0, 0, 1};
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    w = {1 - t, 0, t};
    return a + t * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    w = {0, 1 - t, t};
    return b + t * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, u = vc * denom;
  w = {1 - v - u, v, u};
  return a + ab * v + ac * u;
}

ContactReport::ContactReport(const Body& cell, const Body& substrate, const std::string& surface, double contact_gap,
                             double range, const par::Comm& comm)
    : cell_(cell), substrate_(substrate), surface_(surface), contact_gap_(contact_gap), range_(range), comm_(comm) {
  const auto& cloud = substrate.cloud;
  const std::uint32_t bit = surface == "all" ? 0u : cloud.surface_bit(surface);
  if (surface != "all" && bit == 0u)
    throw std::invalid_argument("contact report: body '" + substrate.name + "' has no surface named '" + surface + "'");
  for (const auto& face : cloud.boundary_faces) {
    bool on = true;
    for (int k = 0; k < face.n_nodes && bit != 0u; ++k) on = on && (cloud.surface_mask[face.nodes[k]] & bit);
    if (!on) continue;
    triangles_.push_back({face.nodes[0], face.nodes[1], face.nodes[2]});
    if (face.n_nodes == 4) triangles_.push_back({face.nodes[0], face.nodes[2], face.nodes[3]});
  }
  if (triangles_.empty())
    throw std::invalid_argument("contact report: surface '" + surface + "' of body '" + substrate.name + "' has no faces");
  for (const auto& t : triangles_) corners_.insert(corners_.end(), t.begin(), t.end());
  std::sort(corners_.begin(), corners_.end());
  corners_.erase(std::unique(corners_.begin(), corners_.end()), corners_.end());
  const auto& boundary = cell.cloud.boundary_particles;
  cell_particles_.assign(boundary.begin(), boundary.end());
  if (substrate.distributed()) shared_corners_.build(comm, substrate.ghosts.offset(), corners_);
  if (cell.distributed()) shared_cell_.build(comm, cell.ghosts.offset(), cell_particles_);
}

ContactSample ContactReport::measure() const {
  ContactSample s;
  double mass = 0.0;
  for (Index i = cell_.owned_begin(); i < cell_.owned_end(); ++i) {
    s.centroid += cell_.mass[i] * nodal_position(cell_, i);
    mass += cell_.mass[i];
  }
  for (int c = 0; c < 3; ++c) s.centroid[c] = comm_.sum(s.centroid[c]);
  s.centroid /= comm_.sum(mass);

  // Current triangles: physical corners, centroids in a kd-tree, largest circumradius.
  std::vector<Vec3> sub;
  physical_points(substrate_, corners_, sub);
  if (shared_corners_.built()) shared_corners_.update(sub);
  std::vector<Vec3> centre(triangles_.size());
  double reach = 0.0;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& n = triangles_[t];
    centre[t] = (sub[n[0]] + sub[n[1]] + sub[n[2]]) / 3.0;
    for (int k = 0; k < 3; ++k) reach = std::max(reach, (sub[n[k]] - centre[t]).norm());
  }
  const rk::NeighborSearch search(centre);

  std::vector<Vec3> cell;
  physical_points(cell_, cell_particles_, cell);
  if (shared_cell_.built()) shared_cell_.update(cell);

  s.min_gap = range_;
  std::vector<std::pair<Index, double>> found;
  std::vector<Vec3> patch, patch_normal;
  for (Index i : cell_particles_) {
    search.query(cell[i], range_ + reach, found);
    double best = std::numeric_limits<double>::infinity(), signed_gap = 0.0;
    Vec3 normal = Vec3::Zero();
    for (const auto& f : found) {
      const auto& n = triangles_[f.first];
      std::array<double, 3> weights;
      const Vec3 q = closest_on_triangle(cell[i], sub[n[0]], sub[n[1]], sub[n[2]], weights);
      const double distance = (cell[i] - q).norm();
      if (distance < best) {
        best = distance;
        normal = (sub[n[1]] - sub[n[0]]).cross(sub[n[2]] - sub[n[0]]).normalized();
        signed_gap = (cell[i] - q).dot(normal) < 0.0 ? -distance : distance;
      }
    }
    if (!std::isfinite(best)) continue;  // no face within range
    if (signed_gap < s.min_gap) {
      s.min_gap = signed_gap;
      s.deepest = i;
      s.deepest_position = cell[i];
    }
    if (signed_gap < contact_gap_) {
      patch.push_back(cell[i]);
      patch_normal.push_back(normal);
    }
  }
  corner_positions_ = std::move(sub);
  s.contact_particles = static_cast<std::int64_t>(patch.size());
  if (!patch.empty()) {
    Vec3 c = Vec3::Zero(), n = Vec3::Zero();
    for (std::size_t k = 0; k < patch.size(); ++k) {
      c += patch[k];
      n += patch_normal[k];
    }
    c /= static_cast<double>(patch.size());
    n.normalize();
    for (const auto& p : patch) {
      const Vec3 r = p - c;
      s.contact_radius = std::max(s.contact_radius, (r - r.dot(n) * n).norm());
    }
  }
  return s;
}

// The solid angle each triangle subtends at p (Van Oosterom & Strackee 1983), summed
// over the surface and divided by 4 pi: +-1 inside a closed surface, 0 outside.
bool ContactReport::encloses(const Vec3& p) const {
  double solid_angle = 0.0;
  for (const auto& t : triangles_) {
    const Vec3 a = corner_positions_[t[0]] - p, b = corner_positions_[t[1]] - p, c = corner_positions_[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return std::abs(solid_angle) > 2.0 * M_PI;
}

ContactReportLog::ContactReportLog(const Body& cell, const Body& substrate, const ContactSettings& s,
                                   const par::Comm& comm) {
  // Gaps are searched up to 4 cutoffs: beyond, the bodies do not interact anyway.
  if (!s.report_surface.empty())
    report_.emplace(cell, substrate, s.report_surface, s.contact_gap > 0.0 ? s.contact_gap : s.s0, 4.0 * s.cutoff,
                    comm);
}

ContactSample ContactReportLog::sample() const {
  const ContactSample s = report_->measure();  // physical positions of the present state
  if (!first_sample_) {
    first_sample_ = s;
    smallest_gap_ = s.min_gap;
  }
  smallest_gap_ = std::min(smallest_gap_, s.min_gap);
  last_sample_ = s;
  return s;
}

std::vector<std::string> ContactReportLog::history_columns() const {
  if (!declared()) return {};
  return {"centroid_x", "centroid_y", "centroid_z", "min_gap", "contact_radius", "contact_particles"};
}

std::string ContactReportLog::history_values() const {
  if (!declared()) return {};
  const ContactSample s = sample();
  return fmt::format(",{:.10g},{:.10g},{:.10g},{:.6g},{:.6g},{}", s.centroid.x(), s.centroid.y(), s.centroid.z(),
                     s.min_gap, s.contact_radius, s.contact_particles);
}

void ContactReportLog::add_to(io::Json& term_summary) const {
  if (!report_ || !last_sample_) return;
  auto vec = [](const Vec3& v) {
    io::Json a = io::Json::array();
    for (int k = 0; k < 3; ++k) a.push_back(v[k]);
    return a;
  };
  io::Json r = io::Json::object();
  r.set("surface", report_->surface());
  r.set("contact_gap", report_->contact_gap());
  r.set("centroid_initial", vec(first_sample_->centroid));
  r.set("centroid", vec(last_sample_->centroid));
  r.set("drift", vec(last_sample_->centroid - first_sample_->centroid));
  r.set("min_gap", last_sample_->min_gap);
  r.set("min_gap_over_frames", smallest_gap_);
  r.set("contact_radius", last_sample_->contact_radius);
  r.set("contact_particles", last_sample_->contact_particles);
  term_summary.set("report", r);
}

std::vector<materials::OutputField> contact_force_fields(const Body& body, const Body& a, const Body& b,
                                                         const std::array<std::vector<Vec3>, 2>& force) {
  const int k = &body == &a ? 0 : &body == &b ? 1 : -1;
  if (k < 0) return {};
  const Body& other = k == 0 ? b : a;
  const std::vector<Vec3>& f = force[static_cast<std::size_t>(k)];
  return {{"contact_force_" + other.name, 3, f.empty() ? nullptr : f.front().data()}};
}

std::string interpenetration_message(std::int64_t step, const Body& inside, const Body& other, std::int64_t id,
                                     const Vec3& X, const Vec3& x, double depth, double s0) {
  if (step == 0)
    return fmt::format(
        "body '{}' starts inside body '{}': its particle {} at ({:.4g}, {:.4g}, {:.4g}) m lies {:.4g} m inside "
        "its surface (more than s0/2 = {:.4g} m). Place the bodies apart ([body.cloud] of each).",
        inside.name, other.name, id, x.x(), x.y(), x.z(), depth, 0.5 * s0);
  return fmt::format(
      "body '{}' has passed through the surface of body '{}': its particle {} (reference position ({:.4g}, "
      "{:.4g}, {:.4g}) m, current ({:.4g}, {:.4g}, {:.4g}) m) lies {:.4g} m inside it (more than s0/2 = {:.4g} m). "
      "The contact law (s0 = {:.4g} m) did not keep the bodies apart: their surface particles are too far apart "
      "for s0 where they met, or the load exceeded what the potential can bear; a finer cloud or a larger s0 "
      "holds them (docs/theory/contact.md).",
      inside.name, other.name, id, X.x(), X.y(), X.z(), x.x(), x.y(), x.z(), depth, 0.5 * s0, s0);
}

}  // namespace rkpm::sim
