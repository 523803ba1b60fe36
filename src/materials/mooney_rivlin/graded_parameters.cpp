#include "materials/mooney_rivlin/graded_parameters.hpp"

#include "materials/parameter_checks.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace rkpm::materials {

void LinearGrading::validate() const {
  constexpr std::string_view model = "graded";
  if (axis < 0 || axis > 2)
    throw std::invalid_argument(fmt::format("graded material: axis = {} must be 0 (x), 1 (y) or 2 (z)", axis));
  detail::require_finite(model, "x_min", x_min);
  detail::require_positive(model, "length L0", length);
  detail::require_finite(model, "slope a", slope);
  detail::require_finite(model, "offset b", offset);
  const double at_start = offset;
  const double at_end = slope + offset;
  if (!(at_start > 0.0) || !(at_end > 0.0))
    throw std::invalid_argument(fmt::format(
        "graded material: factor a (X - x_min) / L0 + b must be > 0 over the graded range, "
        "got {} at x_min and {} at x_min + L0 (a = {}, b = {})",
        at_start, at_end, slope, offset));
}

void GradedMooneyRivlin::validate() const {
  grading.validate();
  base.validate();
}

MooneyRivlin GradedMooneyRivlin::at(const Vec3& X) const {
  const double f = grading.factor(X);
  if (!(f > 0.0))
    throw std::invalid_argument(fmt::format(
        "graded material: factor {} at reference point ({}, {}, {}) is not positive "
        "(point outside the graded range [{}, {}] along axis {})",
        f, X.x(), X.y(), X.z(), grading.x_min, grading.x_min + grading.length, grading.axis));
  return MooneyRivlin{f * base.c1, f * base.c2, f * base.lambda};
}

}  // namespace rkpm::materials
