#include "terms/surface_tension/surface_tension.hpp"

#include "terms/catalog.hpp"
#include "terms/surface_tension/settings.hpp"
#include "terms/term_support.hpp"

#include "rkpm/sim/body_points.hpp"

#include "rkpm/io/json.hpp"

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rkpm::sim {

namespace {

// Area of triangle (a, b, c); adds its gradient to ga, gb, gc (scaled by `weight`).
double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c, double weight, Vec3* ga, Vec3* gb, Vec3* gc) {
  const Vec3 n = (b - a).cross(c - a);
  const double twice = n.norm();
  if (ga && twice > 0.0) {
    const Vec3 unit = n / twice;
    // d|n|/da = unit x (c - b), cyclically; A = |n| / 2.
    *ga += (0.5 * weight) * unit.cross(c - b);
    *gb += (0.5 * weight) * unit.cross(a - c);
    *gc += (0.5 * weight) * unit.cross(b - a);
  }
  return 0.5 * twice;
}

}  // namespace

double face_area(const particles::BoundaryFace& face, const std::vector<Vec3>& x, Vec3* grad) {
  const auto* n = face.nodes;
  if (face.n_nodes == 3) {
    return triangle_area(x[n[0]], x[n[1]], x[n[2]], 1.0, grad, grad ? grad + 1 : nullptr, grad ? grad + 2 : nullptr);
  }
  // Quadrilateral: mean of the two triangulations (diagonal 0-2 and diagonal 1-3).
  auto g = [grad](int k) { return grad ? grad + k : nullptr; };
  double area = 0.0;
  area += triangle_area(x[n[0]], x[n[1]], x[n[2]], 0.5, g(0), g(1), g(2));
  area += triangle_area(x[n[0]], x[n[2]], x[n[3]], 0.5, g(0), g(2), g(3));
  area += triangle_area(x[n[1]], x[n[2]], x[n[3]], 0.5, g(1), g(2), g(3));
  area += triangle_area(x[n[1]], x[n[3]], x[n[0]], 0.5, g(1), g(3), g(0));
  return 0.5 * area;
}

SurfaceTension::SurfaceTension(Body& body, const std::string& surface, double gamma, const par::Comm& comm)
    : body_(body), comm_(comm), surface_(surface), gamma_(gamma) {
  const auto& cloud = body.cloud;
  const std::uint32_t surface_bit = surface_selector(body, surface);
  if (surface != "all" && surface_bit == 0u)
    throw std::invalid_argument("surface_tension: body '" + body.name + "' has no surface named '" + surface + "'");
  for (std::size_t f = 0; f < cloud.boundary_faces.size(); ++f) {
    const auto& face = cloud.boundary_faces[f];
    bool on = true;
    for (int k = 0; k < face.n_nodes && surface_bit != 0u; ++k) on = on && (cloud.surface_mask[face.nodes[k]] & surface_bit);
    if (on) faces_.push_back(static_cast<std::int32_t>(f));
  }
  if (faces_.empty())
    throw std::invalid_argument("surface_tension: surface '" + surface + "' of body '" + body.name + "' has no faces");
  // Faces in order of their lowest node (then as listed): each rank's faces, those whose
  // lowest node it owns, are then one range of the one-process order.
  const auto lowest_node = [&](std::int32_t f) {
    const auto& face = cloud.boundary_faces[static_cast<std::size_t>(f)];
    return *std::min_element(face.nodes, face.nodes + face.n_nodes);
  };
  std::stable_sort(faces_.begin(), faces_.end(),
                   [&](std::int32_t a, std::int32_t b) { return lowest_node(a) < lowest_node(b); });
  for (auto f : faces_)
    for (int k = 0; k < cloud.boundary_faces[f].n_nodes; ++k) nodes_.push_back(cloud.boundary_faces[f].nodes[k]);
  std::sort(nodes_.begin(), nodes_.end());
  nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  if (body.distributed()) {
    // Keep the faces whose lowest node this rank owns; their other nodes are ghosts here.
    std::vector<Index> ghosts;
    std::vector<std::int32_t> mine;
    for (auto f : faces_) {
      const auto& face = cloud.boundary_faces[f];
      const Index lowest = lowest_node(f);
      if (lowest < body.owned_begin() || lowest >= body.owned_end()) continue;
      mine.push_back(f);
      ghosts.insert(ghosts.end(), face.nodes, face.nodes + face.n_nodes);
    }
    faces_ = std::move(mine);
    face_ghosts_.build(comm, body.ghosts.offset(), std::move(ghosts));
  }
  plan_term_rows(face_sums_, body, 0, static_cast<Index>(faces_.size()), 2,
                 [this](Index r, int, const std::function<void(Index)>& emit) {
                   const auto& face = body_.cloud.boundary_faces[static_cast<std::size_t>(faces_[static_cast<std::size_t>(r)])];
                   for (int k = 0; k < face.n_nodes; ++k) emit(face.nodes[k]);
                 },
                 &face_ghosts_);
  points_.assign(body.size(), Vec3::Zero());
  gradient_.assign(body.size(), Vec3::Zero());
  initial_area_ = area_ = measure_area();
}

void SurfaceTension::update_points() const {
  physical_points(body_, nodes_, points_);
  if (face_ghosts_.built()) face_ghosts_.pull(points_);
}

double SurfaceTension::measure_area() const {
  update_points();
  ExactSum area;
  for (auto f : faces_) area.add(face_area(body_.cloud.boundary_faces[f], points_, nullptr));
  return comm_.sum(area);
}

void SurfaceTension::add_forces(World&) {
  // Serial over faces and nodes, ordered over the ranks (plan_term_rows).
  update_points();
  const auto& faces = body_.cloud.boundary_faces;
  for (Index J : nodes_) gradient_[J].setZero();
  ExactSum area;
  face_sums_.clear(0);
  for (std::size_t r = 0; r < faces_.size(); ++r) {
    const auto& face = faces[static_cast<std::size_t>(faces_[r])];
    Vec3 grad[4] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    area.add(face_area(face, points_, grad));
    const auto sink = face_sums_.sink(0, 0, static_cast<Index>(r));
    for (int k = 0; k < face.n_nodes; ++k) sink(face.nodes[k], grad[k]);
  }
  add_term_rows(face_sums_, 0, 1.0, gradient_);
  // f_I = -gamma sum_J Psi_I(X_J) dA/dp_J (distributed: at the owned nodes).
  add_point_forces(
      body_, nodes_, -gamma_, [&](std::size_t i) -> const Vec3& { return gradient_[nodes_[i]]; }, transfer_);
  area_ = comm_.sum(area);
}

double SurfaceTension::stable_dt(const World&) const {
  if (gamma_ == 0.0) return std::numeric_limits<double>::infinity();
  update_points();
  const auto& faces = body_.cloud.boundary_faces;
  // Each node's row sum of the faces' stiffness, in x (the scatter's channel 1).
  std::vector<Vec3> row(body_.size(), Vec3::Zero());
  face_sums_.clear(0);
  for (std::size_t r = 0; r < faces_.size(); ++r) {
    const auto& face = faces[static_cast<std::size_t>(faces_[r])];
    double longest2 = 0.0;
    for (int p = 0; p < face.n_nodes; ++p)
      for (int q = p + 1; q < face.n_nodes; ++q)
        longest2 = std::max(longest2, (points_[face.nodes[p]] - points_[face.nodes[q]]).squaredNorm());
    const double area = face_area(face, points_, nullptr);
    // A collapsed face adds nothing (the blow-up check reports it).
    const double k = area > 0.0 ? face.n_nodes * gamma_ * longest2 / area : 0.0;
    const auto sink = face_sums_.sink(0, 1, static_cast<Index>(r));
    for (int p = 0; p < face.n_nodes; ++p) sink(face.nodes[p], Vec3(k, 0.0, 0.0));
  }
  add_term_rows(face_sums_, 1, 1.0, row);
  double omega2 = 0.0;
  for (Index i = body_.owned_begin(); i < body_.owned_end(); ++i)
    if (row[i].x() > 0.0) omega2 = std::max(omega2, row[i].x() / body_.inertia[i]);
  omega2 = comm_.max(omega2);
  return omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : std::numeric_limits<double>::infinity();
}

void SurfaceTension::report(const World&, io::Json& summary) const {
  io::Json j = io::Json::object();
  j.set("body", body_.name);
  j.set("surface", surface_);
  j.set("gamma", gamma_);
  j.set("initial_area", initial_area_);
  j.set("area", area_);
  j.set("energy", gamma_ * area_);
  // One entry per term: a scene may declare several tensions (one per interface).
  summary.set("surface_tension " + body_.name + " " + surface_, j);
}

}  // namespace rkpm::sim

namespace rkpm::terms::surface_tension {

std::unique_ptr<sim::Term> build(const scene::ParamSet& params, sim::World& world) {
  const sim::SurfaceTensionSettings s = settings_table().read(params);
  sim::Body& body = named_body(world, params, s.body);
  return constructed(params,
                     [&] { return std::make_unique<sim::SurfaceTension>(body, s.surface, s.gamma, *world.comm); });
}

}  // namespace rkpm::terms::surface_tension
