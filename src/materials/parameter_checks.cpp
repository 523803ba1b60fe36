#include "parameter_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace rkpm::materials::detail {

void require_finite(std::string_view model, std::string_view name, double value) {
  if (!std::isfinite(value))
    throw std::invalid_argument(fmt::format("{} material: {} = {} is not a finite number", model, name, value));
}

void require_positive(std::string_view model, std::string_view name, double value) {
  require_finite(model, name, value);
  if (!(value > 0.0))
    throw std::invalid_argument(fmt::format("{} material: {} = {} must be > 0", model, name, value));
}

void require_non_negative(std::string_view model, std::string_view name, double value) {
  require_finite(model, name, value);
  if (!(value >= 0.0))
    throw std::invalid_argument(fmt::format("{} material: {} = {} must be >= 0", model, name, value));
}

}  // namespace rkpm::materials::detail
