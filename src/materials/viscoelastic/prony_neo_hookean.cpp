#include "materials/viscoelastic/prony_neo_hookean.hpp"

#include "materials/parameter_checks.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace rkpm::materials {

void PronyNeoHookean::validate() const {
  constexpr std::string_view model = "viscoelastic";
  detail::require_positive(model, "mu", equilibrium.mu);
  detail::require_positive(model, "lambda", equilibrium.lambda);
  if (branch_count < 0 || branch_count > kMaxBranches)
    throw std::invalid_argument(
        fmt::format("{} material: branch_count = {} must be in [0, {}] (Maxwell branches)", model, branch_count,
                    kMaxBranches));
  for (int i = 0; i < branch_count; ++i) {
    detail::require_non_negative(model, fmt::format("beta[{}]", i), branches[i].beta);
    detail::require_positive(model, fmt::format("tau[{}]", i), branches[i].tau);
  }
}

}  // namespace rkpm::materials
