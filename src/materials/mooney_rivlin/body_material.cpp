// A Mooney-Rivlin body's parameters from its [body.material] table (compiled into rkpm_sim).
#include "materials/mooney_rivlin/body_material.hpp"

#include "materials/catalog.hpp"
#include "materials/mooney_rivlin/graded_parameters.hpp"
#include "materials/mooney_rivlin/settings.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/body.hpp"

#include <algorithm>
#include <cmath>

namespace rkpm::materials::mooney_rivlin {

std::string build(const scene::BodySpec& spec, sim::Body& body) {
  const Settings s = settings_table().read(spec.material);
  const auto& cloud = body.cloud;
  MooneyRivlin base;
  base.c1 = s.c1;
  base.c2 = s.c2;
  base.lambda = s.lambda;
  base.validate();
  BodyMaterial material;
  if (s.grade_axis < 0) {
    material.at_point.assign(cloud.size(), base);
    body.material = std::move(material);
    return {};
  }
  // Eq. 18: value = base * (a (X_axis - X_min) / L0 + b), L0 = the body's extent by default.
  GradedMooneyRivlin graded;
  graded.base = base;
  graded.grading.axis = s.grade_axis;
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& X : cloud.X) {
    lo = std::min(lo, X[graded.grading.axis]);
    hi = std::max(hi, X[graded.grading.axis]);
  }
  graded.grading.x_min = lo;
  graded.grading.length = s.grade_length > 0.0 ? s.grade_length : hi - lo;
  graded.grading.slope = s.grade_a;
  graded.grading.offset = s.grade_b;
  graded.validate();
  material.at_point.reserve(cloud.size());
  for (const auto& X : cloud.X) material.at_point.push_back(graded.at(X));
  body.material = std::move(material);
  return {};
}

}  // namespace rkpm::materials::mooney_rivlin
