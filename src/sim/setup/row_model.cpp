#include "sim/setup/row_model.hpp"

#include <algorithm>
#include <optional>

namespace rkpm::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Particles of a support ellipsoid with semi-axes r (a ball: all equal) around a point
// of a cloud with spacings h, clipped along each axis to the body's extent L (a thin wall
// holds only its layers): (4/3) pi r0 r1 r2 / (h0 h1 h2), times min(1, (L_i + h_i) / 2 r_i)
// along each axis.
double support_count(const Vec3& r, const Vec3& h, const Vec3& extent) {
  double count = 4.0 / 3.0 * kPi * r[0] * r[1] * r[2] / (h[0] * h[1] * h[2]);
  for (int i = 0; i < 3; ++i) count *= std::min(1.0, (extent[i] + h[i]) / (2.0 * r[i]));
  return std::max(count, 1.0);
}

}  // namespace

RowModel row_model(const scene::BodySpec& spec, const clouds::CloudSize& grid, rk::SupportShape shape) {
  // A ball reaches support x the longest edge along every axis; an ellipsoid support x the
  // spacing along each (scaled as the longest edge is to the longest mean spacing: the
  // stretched cells near a cubed sphere's corners).
  const Vec3 reach_unit = shape == rk::SupportShape::Ellipsoid
                              ? Vec3(grid.spacing * std::max(1.0, grid.longest_edge / grid.spacing.maxCoeff()))
                              : Vec3::Constant(grid.longest_edge);
  const Vec3 support = spec.rk.real("support") * reach_unit;
  // A smoothing cell's facets reach half a spacing beyond its particle.
  const bool scni = spec.rk.choice("integration") == "scni";
  const Vec3 cell_reach = scni ? Vec3(0.5 * reach_unit) : Vec3::Zero();
  return {support_count(support + cell_reach, grid.spacing, grid.extent),
          support_count(support, grid.spacing, grid.extent)};
}

namespace {

// A declared shape, or none for "auto" on a generated cloud.
std::optional<rk::SupportShape> fixed_support_shape(const scene::BodySpec& spec) {
  const std::string& declared = spec.rk.choice("support_shape");
  if (declared == "ellipsoid") return rk::SupportShape::Ellipsoid;
  if (declared == "sphere" || !clouds::can_rescale(spec)) return rk::SupportShape::Sphere;  // or an imported mesh
  return std::nullopt;
}

}  // namespace

rk::SupportShape resolved_support_shape(const scene::BodySpec& spec) {
  if (const auto fixed = fixed_support_shape(spec)) return *fixed;
  return resolved_support_shape(spec, clouds::estimate_cloud(spec));
}

rk::SupportShape resolved_support_shape(const scene::BodySpec& spec, const clouds::CloudSize& grid) {
  if (const auto fixed = fixed_support_shape(spec)) return *fixed;
  const double balls = row_model(spec, grid, rk::SupportShape::Sphere).interpolation;
  const double ellipsoids = row_model(spec, grid, rk::SupportShape::Ellipsoid).interpolation;
  return balls > kAutoEllipsoidRowRatio * ellipsoids ? rk::SupportShape::Ellipsoid : rk::SupportShape::Sphere;
}

}  // namespace rkpm::sim
