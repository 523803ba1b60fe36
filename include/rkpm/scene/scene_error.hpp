// The one error type of the scene layer: a scene file that cannot be used.
//
// Every message starts with `FILE:LINE:` so editors and terminals can jump to it,
// then names the section, the key, the value as written and what was expected:
//   cell.toml:14: [body.material] mu = -3: expected a real > 0 [Pa]
// The program reports it and exits with code 2 before writing anything.
#pragma once

#include <stdexcept>
#include <string>

namespace rkpm::scene {

class SceneError : public std::runtime_error {
 public:
  // A message that is already complete (e.g. a file that cannot be opened).
  SceneError(std::string file, int line, const std::string& message);

  // The standard form: `FILE:LINE: [section] key = value: expected ...`.
  // An empty `value` (a missing key) drops the ` = value` part; an empty `key`
  // (a whole section) drops the key as well.
  SceneError(std::string file, int line, const std::string& section, const std::string& key,
             const std::string& value, const std::string& expected);

  const std::string& file() const { return file_; }
  int line() const { return line_; }  // 0 when the error is about the file as a whole

 private:
  std::string file_;
  int line_ = 0;
};

}  // namespace rkpm::scene
