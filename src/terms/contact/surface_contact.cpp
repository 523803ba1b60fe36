#include "terms/contact/surface_contact.hpp"

#include "rkpm/sim/body_points.hpp"

#include "rkpm/common/parallel.hpp"
#include "rkpm/io/json.hpp"
#include "rkpm/rk/neighbor_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rkpm::sim {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

SurfaceContact::SurfaceContact(Body& a, Body& b, const ContactSettings& s, const par::Comm& comm)
    : a_(a), b_(b), law_(s.epsilon, s.s0, s.cutoff), s0_(s.s0), gap_floor_(0.25 * s.s0),
      density_product_(molecule_density(a, s.beta[0]) * molecule_density(b, s.beta[1])), log_(a, b, s, comm) {
  if (&a == &b) throw std::invalid_argument("contact: the two bodies must be different (got '" + a.name + "' twice)");
  if (a.distributed() || b.distributed())
    throw std::invalid_argument("contact: formulation = \"surface\" runs on one rank only");
  const auto& cloud_a = a.cloud;
  for (std::size_t k = 0; k < cloud_a.boundary_particles.size(); ++k) {
    surface_.push_back(cloud_a.boundary_particles[k]);
    area_.push_back(cloud_a.boundary_area[k]);
  }
  for (const auto& face : b.cloud.boundary_faces)
    faces_.push_back({face.nodes[0], face.nodes[1], face.nodes[2], face.n_nodes == 4 ? face.nodes[3] : -1});
  if (surface_.empty() || faces_.empty())
    throw std::invalid_argument("contact: formulation = \"surface\" needs both bodies' clouds to have a surface");
  for (const auto& f : faces_)
    for (const Index c : f)
      if (c >= 0) corners_.push_back(c);
  std::sort(corners_.begin(), corners_.end());
  corners_.erase(std::unique(corners_.begin(), corners_.end()), corners_.end());
  if (s.law == StiffnessLaw::linear) {
    const int k = s.substrate == a.name ? 0 : 1;
    const Body& sub = k == 0 ? a : b;
    mu_reference_ = s.stiffness_reference > 0.0 ? s.stiffness_reference : mean_shear_modulus(sub);
    stiffness_factor_[k].resize(sub.size());
    for (std::size_t i = 0; i < sub.size(); ++i)
      stiffness_factor_[k][i] = shear_modulus(sub, static_cast<Index>(i)) / mu_reference_;
  }
  points_a_.resize(a.size());
  points_b_.resize(b.size());
  corner_normals_.resize(b.size());
  force_[0].assign(a.size(), Vec3::Zero());
  force_[1].assign(b.size(), Vec3::Zero());
  feet_.resize(surface_.size());
}

double SurfaceContact::factor_at(const Foot& foot, Index a_particle) const {
  if (!stiffness_factor_[0].empty()) return stiffness_factor_[0][a_particle];
  if (stiffness_factor_[1].empty()) return 1.0;
  const auto& face = faces_[foot.face];
  double factor = 0.0;
  for (int k = 0; k < 4; ++k)
    if (face[k] >= 0) factor += foot.weight[k] * stiffness_factor_[1][face[k]];
  return factor;
}

Vec3 SurfaceContact::factor_gradient(const Vec3& p0, const Vec3& p1, const Vec3& p2, const std::array<Index, 4>& face,
                                     int k, int k1, int corners) const {
  const auto& f = stiffness_factor_[1];
  if (f.empty()) return Vec3::Zero();
  // The factor at the triangle's corners: two of the face's and, on a quadrilateral,
  // its centre (the corners' mean), or the triangle's third.
  double third = f[face[2]];
  if (corners == 4) third = 0.25 * (f[face[0]] + f[face[1]] + f[face[2]] + f[face[3]]);
  const double f0 = f[face[k]], f1 = f[face[k1]];
  // grad of the linear interpolant in the plane: [(f1 - f0)(e2 x n) + (f2 - f0)(n x e1)] / |n|^2.
  const Vec3 e1 = p1 - p0, e2 = p2 - p0, n = e1.cross(e2);
  return ((f1 - f0) * e2.cross(n) + (third - f0) * n.cross(e1)) / n.squaredNorm();
}

void SurfaceContact::find_feet() {
  physical_points(a_, surface_, points_a_);
  physical_points(b_, corners_, points_b_);
  centres_.resize(faces_.size());
  double reach = 0.0;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto& face = faces_[f];
    const int corners = face[3] >= 0 ? 4 : 3;
    Vec3 centre = Vec3::Zero();
    for (int k = 0; k < corners; ++k) centre += points_b_[face[k]];
    centres_[f] = centre / corners;
    for (int k = 0; k < corners; ++k) reach = std::max(reach, (points_b_[face[k]] - centres_[f]).norm());
  }
  // Each corner's normal: the area-weighted mean of its faces' (a quadrilateral's as the
  // sum of its four triangles about the centre).
  for (const Index c : corners_) corner_normals_[c].setZero();
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto& face = faces_[f];
    const int corners = face[3] >= 0 ? 4 : 3;
    Vec3 area = Vec3::Zero();
    if (corners == 4) {
      for (int k = 0; k < 4; ++k)
        area += (points_b_[face[k]] - centres_[f]).cross(points_b_[face[(k + 1) % 4]] - centres_[f]);
    } else {
      area = (points_b_[face[1]] - points_b_[face[0]]).cross(points_b_[face[2]] - points_b_[face[0]]);
    }
    for (int k = 0; k < corners; ++k) corner_normals_[face[k]] += area;
  }
  for (const Index c : corners_) corner_normals_[c].normalize();
  const rk::NeighborSearch search(centres_);
  const double rc = law_.cutoff();
  const auto n = static_cast<Index>(surface_.size());
#pragma omp parallel if (worth_threads(n))
  {
    std::vector<std::pair<Index, double>> found;
#pragma omp for schedule(dynamic, 64)
    for (Index i = 0; i < n; ++i) {
      const Vec3& x = points_a_[surface_[i]];
      Foot foot;
      double best = rc;
      search.query(x, rc + reach, found);  // sorted by face: ties go to the lowest
      for (const auto& candidate : found) {
        const auto f = static_cast<int>(candidate.first);
        const auto& face = faces_[f];
        // A triangle is itself; a quadrilateral four triangles (k, k + 1, centre).
        const int corners = face[3] >= 0 ? 4 : 3;
        for (int k = 0; k < (corners == 4 ? 4 : 1); ++k) {
          const int k1 = (k + 1) % corners;
          const Vec3& p0 = points_b_[face[k]];
          const Vec3& p1 = points_b_[face[k1]];
          const Vec3& p2 = corners == 4 ? centres_[f] : points_b_[face[2]];
          std::array<double, 3> w;
          const Vec3 q = closest_on_triangle(x, p0, p1, p2, w);
          const double distance = (x - q).norm();
          if (!(distance < best)) continue;
          best = distance;
          const Vec3 normal = (p1 - p0).cross(p2 - p0).normalized();
          const double side = (x - q).dot(normal) < 0.0 ? -1.0 : 1.0;
          foot.face = f;
          foot.weight = {0.0, 0.0, 0.0, 0.0};
          if (corners == 4) {
            for (int c = 0; c < 4; ++c) foot.weight[c] = 0.25 * w[2];
            foot.weight[k] += w[0];
            foot.weight[k1] += w[1];
          } else {
            foot.weight = {w[0], w[1], w[2], 0.0};
          }
          foot.gap = side * distance;
          foot.scale_gradient = factor_gradient(p0, p1, p2, face, k, k1, corners);
          // The corners' normals interpolated at the nearest point: continuous across
          // the facets' edges, where the distance's own gradient turns by their angle.
          Vec3 smooth = Vec3::Zero();
          for (int c = 0; c < corners; ++c) smooth += foot.weight[c] * corner_normals_[face[c]];
          foot.direction = smooth.normalized();
        }
      }
      if (foot.face >= 0) {
        foot.scale = area_[i] * density_product_ * factor_at(foot, surface_[i]);
        foot.scale_gradient *= area_[i] * density_product_;
      }
      feet_[i] = foot;
    }
  }
}

void SurfaceContact::add_forces(World&) {
  const auto start = std::chrono::steady_clock::now();
  find_feet();
  const double g_min = gap_floor_;
  const double floor_energy = law_.energy(g_min), floor_traction = law_.traction(g_min);
  std::fill(force_[1].begin(), force_[1].end(), Vec3::Zero());
  double energy = 0.0;  // serial, in the order of the first body's surface
  std::size_t active = 0;
  for (std::size_t i = 0; i < surface_.size(); ++i) {
    const Foot& foot = feet_[i];
    Vec3& f = force_[0][surface_[i]];
    if (foot.face < 0) {
      f.setZero();
      continue;
    }
    ++active;
    const double g = foot.gap;
    const double w = g >= g_min ? law_.energy(g) : floor_energy + floor_traction * (g_min - g);
    const double sigma = g >= g_min ? law_.traction(g) : floor_traction;
    energy += foot.scale * w;
    f = (foot.scale * sigma) * foot.direction - w * foot.scale_gradient;
    const auto& face = faces_[foot.face];
    for (int k = 0; k < 4; ++k)
      if (face[k] >= 0) force_[1][face[k]] -= foot.weight[k] * f;
  }
  add_point_forces(a_, surface_, 1.0, [&](std::size_t i) -> const Vec3& { return force_[0][surface_[i]]; },
                   scatter_a_);
  add_point_forces(b_, corners_, 1.0, [&](std::size_t i) -> const Vec3& { return force_[1][corners_[i]]; },
                   scatter_b_);
  energy_ = energy;
  active_ = active;
  ++evaluations_;
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double SurfaceContact::spring(const Foot& foot) const {
  const double g = std::max(foot.gap, gap_floor_);
  return foot.scale * std::max(std::abs(law_.traction_slope(g)), std::abs(law_.traction(g)) / g);
}

double SurfaceContact::stable_dt(const World&) const {
  if (evaluations_ == 0) return kInfinity;
  std::vector<double> corner_row(b_.size(), 0.0);
  double omega2 = 0.0;
  for (std::size_t i = 0; i < surface_.size(); ++i) {
    const Foot& foot = feet_[i];
    if (foot.face < 0) continue;
    const double k = spring(foot);
    const double ma = a_.inertia[surface_[i]];
    const auto& face = faces_[foot.face];
    double row = 1.0 / ma;
    for (int c = 0; c < 4; ++c) {
      if (face[c] < 0) continue;
      const double mb = b_.inertia[face[c]];
      row += foot.weight[c] / std::sqrt(ma * mb);
      corner_row[face[c]] += k * foot.weight[c] * (foot.weight[c] / mb + 1.0 / std::sqrt(ma * mb));
    }
    omega2 = std::max(omega2, k * row);
  }
  for (const double row : corner_row) omega2 = std::max(omega2, row);
  return omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : kInfinity;
}

std::string SurfaceContact::diagnose(const World& world) {
  std::size_t deepest = surface_.size();
  for (std::size_t i = 0; i < surface_.size(); ++i)
    if (feet_[i].face >= 0 && feet_[i].gap < -0.5 * s0_ &&
        (deepest == surface_.size() || feet_[i].gap < feet_[deepest].gap))
      deepest = i;
  if (deepest == surface_.size()) return {};
  const Index p = surface_[deepest];
  return interpenetration_message(world.step, a_, b_, p, a_.cloud.X[p], points_a_[p], -feet_[deepest].gap, s0_);
}

void SurfaceContact::report(const World&, io::Json& summary) const {
  io::Json j = io::Json::object();
  j.set("formulation", "surface");
  j.set("energy", energy_);
  j.set("active_particles", active_);
  Vec3 total = Vec3::Zero();
  for (const Index i : surface_) total += force_[0][i];
  io::Json force = io::Json::array();
  for (int k = 0; k < 3; ++k) force.push_back(total[k]);
  j.set("force_on_" + a_.name, force);
  if (mu_reference_ > 0.0) j.set("stiffness_reference", mu_reference_);
  j.set("force_evaluations", evaluations_);
  j.set("seconds", seconds_);
  log_.add_to(j);
  summary.set("contact " + a_.name + " " + b_.name, j);
}

std::vector<materials::OutputField> SurfaceContact::output_fields(const Body& body) const {
  return contact_force_fields(body, a_, b_, force_);
}

}  // namespace rkpm::sim
