#include "materials/mooney_rivlin/mooney_rivlin.hpp"

#include "materials/parameter_checks.hpp"

namespace rkpm::materials {

void MooneyRivlin::validate() const {
  constexpr std::string_view model = "mooney_rivlin";
  detail::require_finite(model, "c1", c1);
  detail::require_finite(model, "c2", c2);
  // c1 or c2 alone may be negative (some fits have c2 < 0); the small-strain
  // shear modulus may not.
  detail::require_positive(model, "shear modulus 2 (c1 + c2)", shear_modulus());
  detail::require_positive(model, "lambda", lambda);
}

}  // namespace rkpm::materials
