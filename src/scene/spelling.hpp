// "Did you mean" suggestions for misspelt keys, sections and choices.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rkpm::scene {

// The candidate closest to `word` in edit distance (case-insensitive), if it is
// close enough to be a plausible typo (distance <= 2, and less than half the
// word); "" otherwise.
std::string closest_spelling(std::string_view word, const std::vector<std::string>& candidates);

// `candidates` joined as `a, b, c`, and ` (did you mean "x"?)` when one is close.
std::string list_with_suggestion(std::string_view word, const std::vector<std::string>& candidates,
                                 bool quote);

}  // namespace rkpm::scene
