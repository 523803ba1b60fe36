// Checks shared by the materials' validate() functions: each throws
// std::invalid_argument naming the model, the parameter, its value and what was
// expected, so the scene layer can prefix the file and key.
#pragma once

#include <string_view>

namespace rkpm::materials::detail {

void require_finite(std::string_view model, std::string_view name, double value);
void require_positive(std::string_view model, std::string_view name, double value);
void require_non_negative(std::string_view model, std::string_view name, double value);

}  // namespace rkpm::materials::detail
