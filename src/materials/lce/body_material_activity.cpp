// The activity field of an LCE body (compiled into rkpm_sim).
#include "materials/lce/body_material_activity.hpp"

#include "rkpm/rk/element_edges.hpp"
#include "rkpm/sim/build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rkpm::materials::lce {

using sim::SetupError;

namespace {

// Each particle's depth below the surface `bit`: the fewest element edges between it
// and a particle of that surface (a breadth-first search from all of them at once), or
// -1 where none is reached.
std::vector<int> edge_depth(const particles::Cloud& cloud, const std::vector<std::vector<Index>>& neighbours,
                            std::uint32_t bit) {
  std::vector<int> depth(cloud.size(), -1);
  std::vector<Index> front, next;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (cloud.surface_mask[i] & bit) {
      depth[i] = 0;
      front.push_back(static_cast<Index>(i));
    }
  for (int d = 1; !front.empty(); ++d) {
    next.clear();
    for (const Index i : front)
      for (const Index j : neighbours[static_cast<std::size_t>(i)])
        if (depth[static_cast<std::size_t>(j)] < 0) {
          depth[static_cast<std::size_t>(j)] = d;
          next.push_back(j);
        }
    front.swap(next);
  }
  return depth;
}

// Share of a particle's mass on the side of `surface` in a shell's wall: 1 nearer that
// surface than the other one, 0 farther, 1/2 on the mid-surface. Depth is counted in
// element edges from each surface (edge_depth): on a generated shell that is the
// particle's layer, so with an odd layer count the middle layer is exactly on the
// mid-surface at any resolution and curvature. The Euclidean distance to each surface's
// nearest particle, used before, is not: the generated layers are ellipsoids whose
// semi-axes shrink by the same length, not offset surfaces, and the surfaces' particles
// sit an in-plane spacing apart, so the RBC scene's middle layer lay 0.46-0.54 of the
// way through the wall and an exact-tie test gave 1/2 to 130 of its 6,146 particles, the
// rest wholly to one half (docs/verification/rbc.md, "How the driver is placed in a five-layer wall").
std::vector<double> wall_side(const particles::Cloud& cloud, const std::string& surface) {
  const std::string other = surface == "inner" ? "outer" : "inner";
  std::vector<std::vector<Index>> neighbours(cloud.size());
  const auto& mesh = cloud.mesh;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const std::int32_t* nodes = mesh.element_nodes(e);
    for (const auto& [a, b] : rk::element_edges(mesh.type[static_cast<std::size_t>(e)])) {
      neighbours[static_cast<std::size_t>(nodes[a])].push_back(nodes[b]);
      neighbours[static_cast<std::size_t>(nodes[b])].push_back(nodes[a]);
    }
  }
  const auto near = edge_depth(cloud, neighbours, cloud.surface_bit(surface));
  const auto far = edge_depth(cloud, neighbours, cloud.surface_bit(other));
  std::vector<double> side(cloud.size());
  // A particle reached from neither surface (a piece of the mesh without one) is counted
  // as on the mid-surface, like one equally deep below both.
  for (std::size_t i = 0; i < cloud.size(); ++i)
    side[i] = near[i] == far[i] ? 0.5 : (near[i] >= 0 && (far[i] < 0 || near[i] < far[i]) ? 1.0 : 0.0);
  return side;
}

// Distance of each reference position from the axis line through the volume centroid,
// divided by the largest such distance (rho in [0, 1]).
std::vector<double> relative_axis_distance(const particles::Cloud& cloud, const Vec3& axis) {
  Vec3 centre = Vec3::Zero();
  double volume = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    centre += cloud.volume[i] * cloud.X[i];
    volume += cloud.volume[i];
  }
  centre /= volume;
  std::vector<double> rho(cloud.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vec3 r = cloud.X[i] - centre;
    rho[i] = (r - r.dot(axis) * axis).norm();
    largest = std::max(largest, rho[i]);
  }
  if (largest > 0.0)
    for (auto& x : rho) x /= largest;
  return rho;
}

// Multiplies a profile by the through-the-wall factor that the choice `key` names:
// all = 1; inner / outer = the half of a shell's wall nearer that surface (that half grows
// or shrinks in-plane, the other does not: the wall bends like a bimetal strip);
// bending = +1 in the inner half and -1 in the outer half (a pure bending moment).
// `bending_scale` (T / T_ref, 1 without a reference thickness) scales the part of the
// factor that differs between the two halves and keeps their mean: inner / outer give
// 1/2 + scale (side - 1/2), bending scale (2 side - 1). A bimetal wall's curvature is
// 3 de / (2 T) for a growth difference de between its halves, so this keeps the
// curvature the activity asks for, and the in-plane growth, at any wall thickness.
void apply_layer(const particles::Cloud& cloud, const std::string& layer, double bending_scale,
                 const scene::ParamSet& m, const std::string& key, std::vector<double>& profile) {
  if (layer == "all") return;
  if (cloud.surface_bit("inner") == 0u || cloud.surface_bit("outer") == 0u)
    throw SetupError(fmt::format("{}:{}: [body.material] {} = \"{}\": expected \"all\" for a cloud "
                                 "without inner and outer surfaces (a shell has them)",
                                 m.file(), m.line(key), key, layer));
  const bool bending = layer == "bending";
  const auto side = wall_side(cloud, bending ? "inner" : layer);
  for (std::size_t i = 0; i < profile.size(); ++i)
    profile[i] *= bending ? bending_scale * (2.0 * side[i] - 1.0) : 0.5 + bending_scale * (side[i] - 0.5);
}

// The factor (1 - f) + f (T / T_ref)^3 on zeta_rim, f = zeta_rim_fold_share. The rim's
// activity does two jobs: it shrinks the rim in-plane, which does not depend on the
// wall's thickness T, and it holds the wall's tight equatorial fold open against the
// wall's bending stiffness, which grows as T^3. f is the second job's share at T_ref.
// Not derived: the 0.3-0.75 um walls of the RBC scene ask for a rim that is flat up to
// T_ref and doubles by 1.5 T_ref, which a pure power of T does not give (docs/verification/rbc.md).
double rim_thickness_factor(const Settings& settings, const scene::ParamSet& m, double thickness_ratio) {
  const double share = settings.zeta_rim_fold_share;
  if (share == 0.0) return 1.0;
  if (!(settings.zeta_reference_thickness > 0.0))
    throw SetupError(fmt::format("{}:{}: [body.material] zeta_rim_fold_share = {}: expected "
                                 "zeta_reference_thickness > 0 (the wall thickness T_ref the share is given for)",
                                 m.file(), m.line("zeta_rim_fold_share"), share));
  return (1.0 - share) + share * thickness_ratio * thickness_ratio * thickness_ratio;
}

}  // namespace

// zeta_L = zeta w_face(X_L) w_layer(X_L) + zeta_rim w_rim(X_L) + zeta_fold w_fold(X_L):
//   w_face  = 1 (uniform), |c|^p (axial), |s|^p (equatorial) or (1 - rho^2)^p (radial),
//             c = h0 . a and s = sqrt(1 - c^2) for the reference director h0 and axis a;
//   w_layer = 1 (all), the inner or outer half of a shell's wall, or +1 / -1 in the
//             inner / outer half (bending); the difference between the halves scaled
//             by T / T_ref when zeta_reference_thickness = T_ref is given (apply_layer);
//   w_rim   = |s|^q: where the wall normal is perpendicular to the axis (a cell's rim),
//             q = zeta_rim_power, times its own through-the-wall factor (zeta_rim_layer);
//             zeta_rim times (1 - f) + f (T / T_ref)^3 when zeta_rim_fold_share = f
//             (rim_thickness_factor);
//   w_fold  = |s|^k, k = zeta_fold_power, a narrower band times its own through-the-wall
//             factor (zeta_fold_layer): with "outer" and zeta_fold < 0 the outer half grows
//             in-plane at the equator and the fold there opens.
std::vector<double> activity_field(const Settings& settings, const scene::ParamSet& m, const sim::Body& body,
                                   const std::vector<Vec3>& h0, double wall_thickness, double& reference_zeta) {
  const std::string& profile = settings.zeta_profile;
  const double zeta = settings.zeta;
  reference_zeta = zeta != 0.0 ? zeta : settings.zeta_rim;
  double bending_scale = 1.0;
  if (settings.zeta_reference_thickness > 0.0) {
    if (!(wall_thickness > 0.0))
      throw SetupError(fmt::format("{}:{}: [body.material] zeta_reference_thickness = {}: expected a cloud with a "
                                   "wall thickness (generator = \"shell\" and its thickness)",
                                   m.file(), m.line("zeta_reference_thickness"), settings.zeta_reference_thickness));
    bending_scale = wall_thickness / settings.zeta_reference_thickness;
  }
  const double zeta_rim = settings.zeta_rim * rim_thickness_factor(settings, m, bending_scale);
  const double zeta_fold = settings.zeta_fold;
  if (reference_zeta == 0.0) reference_zeta = zeta_fold;
  if (profile == "uniform" && settings.zeta_layer == "all" && zeta_rim == 0.0 && zeta_fold == 0.0) return {};
  if (reference_zeta == 0.0) return {};

  const Vec3 axis_raw = settings.zeta_axis;
  // stableNorm: tiny or huge components still give a direction (the plain norm squares
  // them to 0 or infinity).
  if (!(axis_raw.stableNorm() > 0.0))
    throw SetupError(fmt::format("{}:{}: [body.material] zeta_axis = [0, 0, 0]: expected a non-zero vector",
                                 m.file(), m.line("zeta_axis")));
  const Vec3 axis = axis_raw.stableNormalized();
  const std::size_t n = body.size();
  auto cos2 = [&](std::size_t i) { return std::min(1.0, std::pow(h0[i].dot(axis), 2)); };

  std::vector<double> face(n, 1.0);
  const double power = settings.zeta_power;
  if (profile == "radial") {
    const auto rho = relative_axis_distance(body.cloud, axis);
    for (std::size_t i = 0; i < n; ++i) face[i] = std::pow(std::max(0.0, 1.0 - rho[i] * rho[i]), power);
  } else if (profile == "axial") {
    for (std::size_t i = 0; i < n; ++i) face[i] = std::pow(cos2(i), 0.5 * power);
  } else if (profile == "equatorial") {
    for (std::size_t i = 0; i < n; ++i) face[i] = std::pow(1.0 - cos2(i), 0.5 * power);
  }

  // |s|^q, s the sine of the wall normal's angle to the axis: a band at the equator, the
  // narrower the larger q; zero everywhere when the band's amplitude is.
  auto equatorial_band = [&](double amplitude, double q) {
    std::vector<double> band(n, 0.0);
    if (amplitude != 0.0)
      for (std::size_t i = 0; i < n; ++i) band[i] = std::pow(1.0 - cos2(i), 0.5 * q);
    return band;
  };
  std::vector<double> rim = equatorial_band(zeta_rim, settings.zeta_rim_power);
  std::vector<double> fold = equatorial_band(zeta_fold, settings.zeta_fold_power);
  apply_layer(body.cloud, settings.zeta_layer, bending_scale, m, "zeta_layer", face);
  apply_layer(body.cloud, settings.zeta_rim_layer, bending_scale, m, "zeta_rim_layer", rim);
  // Only when the band is used: its default layer ("outer") needs a shell, and a scene
  // without the key must load on any cloud.
  if (zeta_fold != 0.0) apply_layer(body.cloud, settings.zeta_fold_layer, bending_scale, m, "zeta_fold_layer", fold);

  std::vector<double> activity(n);
  for (std::size_t i = 0; i < n; ++i)
    activity[i] = (zeta * face[i] + zeta_rim * rim[i] + zeta_fold * fold[i]) / reference_zeta;
  return activity;
}

}  // namespace rkpm::materials::lce
