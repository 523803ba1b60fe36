// The [body.material] table of model = "mooney_rivlin" (compiled into rkpm_scene).
#include "materials/catalog.hpp"
#include "materials/mooney_rivlin/settings.hpp"

#include "rkpm/scene/param_set.hpp"

namespace rkpm::materials::mooney_rivlin {

using scene::ParamSet;
using scene::ParamSpec;

namespace {

void check(ParamSet& p) {
  if (p.real("c1") + p.real("c2") <= 0.0) throw p.error("c2", "c1 + c2 > 0 (both are zero)");
  const char* grade_keys[] = {"grade_a", "grade_b", "grade_length"};
  if (p.choice("grade_axis") == "none") {
    for (const char* key : grade_keys) {
      if (p.given(key)) throw p.error(key, "no grading key unless grade_axis is \"x\", \"y\" or \"z\"");
    }
    return;
  }
  // The factor a*s + b (s = 0 at the body's minimum, 1 at grade_length) scales
  // positive moduli; it must stay positive at both ends of the body.
  const double a = p.real("grade_a"), b = p.real("grade_b");
  if (b <= 0.0) throw p.error("grade_b", "grade_b > 0 (the factor a*s + b must stay positive at s = 0)");
  if (a + b <= 0.0) throw p.error("grade_a", "grade_a + grade_b > 0 (the factor a*s + b must stay positive at s = 1)");
}

int axis_index(const std::string& axis) { return axis == "none" ? -1 : axis == "x" ? 0 : axis == "y" ? 1 : 2; }

}  // namespace

const scene::SettingsTable<Settings>& settings_table() {
  static const auto table =
      scene::SettingsTable<Settings>(
          material_table("mooney_rivlin",
                         "Compressible Mooney-Rivlin solid (seed Eq. 9-11), optionally graded along an "
                         "axis (Eq. 18): every modulus is multiplied by a*s + b, s = (X_axis - X_min) / L0."))
          .bind(&Settings::c1,
                ParamSpec::real("c1", "Pa").at_least(0).mark_required().help("First Mooney-Rivlin constant (Eq. 9)."))
          .bind(&Settings::c2,
                ParamSpec::real("c2", "Pa").at_least(0).defaults(0.0).help("Second Mooney-Rivlin constant (Eq. 9)."))
          .bind(&Settings::lambda, ParamSpec::real("lambda", "Pa").greater_than(0).mark_required()
                                       .help("Volumetric constant of the (ln I3)^2 term (Eq. 9)."))
          .bind(&Settings::grade_axis,
                ParamSpec::choice("grade_axis", {"none", "x", "y", "z"}).defaults(std::string("none"))
                    .help("Axis along which the moduli vary (Eq. 18 uses y); none = homogeneous."),
                [](const std::string& axis) { return axis_index(axis); })
          .bind(&Settings::grade_a, ParamSpec::real("grade_a", "-").defaults(0.0)
                                        .help("Slope a of the grading factor a*s + b (Eq. 18: 4)."))
          .bind(&Settings::grade_b, ParamSpec::real("grade_b", "-").defaults(1.0)
                                        .help("Offset b of the grading factor a*s + b (Eq. 18: 0.5)."))
          .bind(&Settings::grade_length,
                ParamSpec::real("grade_length", "m").at_least(0).defaults(0.0)
                    .help("Length L0 over which s goes from 0 to 1; 0 = the body's extent along the axis."))
          .finish(check);
  return table;
}

scene::ParamTable table() { return settings_table().table(); }

}  // namespace rkpm::materials::mooney_rivlin
