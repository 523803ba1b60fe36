#include "spelling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace rkpm::scene {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Levenshtein distance with one rolling row.
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closest_spelling(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = 3;  // only distances 0..2 count as typos
  for (const auto& candidate : candidates) {
    const std::size_t d = edit_distance(word, candidate);
    if (d < best_distance && 2 * d < std::max(word.size(), candidate.size())) {
      best = candidate;
      best_distance = d;
    }
  }
  return best;
}

std::string list_with_suggestion(std::string_view word, const std::vector<std::string>& candidates,
                                 bool quote) {
  std::string out;
  for (const auto& c : candidates) {
    if (!out.empty()) out += ", ";
    out += quote ? fmt::format("\"{}\"", c) : c;
  }
  const std::string suggestion = closest_spelling(word, candidates);
  if (!suggestion.empty()) out += fmt::format(" (did you mean \"{}\"?)", suggestion);
  return out;
}

}  // namespace rkpm::scene
