// The [body.material] table of model = "viscoelastic" (compiled into rkpm_scene).
#include "materials/catalog.hpp"
#include "materials/viscoelastic/prony_neo_hookean.hpp"
#include "materials/viscoelastic/settings.hpp"

#include <fmt/format.h>

namespace rkpm::materials::viscoelastic {

using scene::ParamSpec;

namespace {
// One relaxation time per branch modulus, and at most the branches the state holds.
void check(scene::ParamSet& p) {
  const auto& beta = p.reals("beta");
  const auto& tau = p.reals("tau");
  if (tau.size() != beta.size())
    throw p.error("tau", fmt::format("one relaxation time per branch: {} value(s), as beta has", beta.size()));
  if (beta.size() > static_cast<std::size_t>(PronyNeoHookean::kMaxBranches))
    throw p.error("beta", fmt::format("at most {} Maxwell branches", PronyNeoHookean::kMaxBranches));
}
}  // namespace

const scene::SettingsTable<Settings>& settings_table() {
  static const auto table =
      scene::SettingsTable<Settings>(
          material_table("viscoelastic",
                         "Finite-strain viscoelastic solid: a compressible neo-Hookean equilibrium branch (mu, "
                         "lambda) in parallel with up to 4 Maxwell branches in shear (a Prony series), branch i of "
                         "modulus beta_i mu relaxing with time tau_i. Small strain: relaxation modulus "
                         "G(t) = mu (1 + sum_i beta_i exp(-t/tau_i)); the bulk modulus lambda + 2 mu/3 does not "
                         "relax. docs/theory/materials.md, \"Viscoelastic\"."))
          .bind(&Settings::mu, ParamSpec::real("mu", "Pa").greater_than(0).mark_required()
                                   .help("Long-term shear modulus: the equilibrium branch's, what is left once "
                                         "every branch has relaxed."))
          .bind(&Settings::lambda, ParamSpec::real("lambda", "Pa").greater_than(0).mark_required()
                                       .help("Lame's first parameter of the equilibrium branch; the bulk "
                                             "modulus is lambda + 2 mu/3 at every rate."))
          .bind(&Settings::beta, ParamSpec::real_list("beta", "-").at_least(0).defaults(std::vector<double>{})
                                     .help("Each Maxwell branch's shear modulus relative to mu (the "
                                           "instantaneous shear modulus is mu (1 + sum beta)); [] = elastic."))
          .bind(&Settings::tau, ParamSpec::real_list("tau", "s").greater_than(0).defaults(std::vector<double>{})
                                    .help("Each branch's relaxation time, one per beta."))
          .finish(check);
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::materials::viscoelastic
