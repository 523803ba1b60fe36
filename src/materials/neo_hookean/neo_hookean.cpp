#include "materials/neo_hookean/neo_hookean.hpp"

#include "materials/parameter_checks.hpp"

namespace rkpm::materials {

void NeoHookean::validate() const {
  constexpr std::string_view model = "neo_hookean";
  detail::require_positive(model, "mu", mu);
  detail::require_positive(model, "lambda", lambda);
}

}  // namespace rkpm::materials
