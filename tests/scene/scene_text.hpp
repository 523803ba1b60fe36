// Small valid scenes that the tests modify, and helpers to edit them.
#pragma once

#include <stdexcept>
#include <string>

namespace rkpm::scene::testing {

// A minimal valid scene: one Mooney-Rivlin block. Line numbers matter to the
// tests: the text ends on line 14, so anything appended starts on line 15 and
// belongs to [body.material] unless it opens a new table.
inline const std::string kBase = R"([scene]
name = "t"
[integrator]
t_end = 1.0
[[body]]
name = "cell"
[body.cloud]
generator = "block"
size = [1, 1, 1]
cells = [2, 2, 2]
[body.material]
model = "mooney_rivlin"
c1 = 1000
lambda = 1e5
)";

// A second body, an LCE sphere, to append to kBase (its [[body]] is on the first
// appended line).
inline const std::string kLceBody = R"([[body]]
name = "gel"
[body.cloud]
generator = "sphere"
radius = 5e-6
[body.material]
model = "lce"
mu = 1000
bulk = 1e5
)";

// `text` with the first occurrence of `from` replaced by `to`; throws if absent
// so that a test cannot silently test the unmodified scene.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::invalid_argument("replaced: '" + from + "' not in the scene");
  return text.replace(at, from.size(), to);
}

}  // namespace rkpm::scene::testing
