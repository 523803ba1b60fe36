// A .geo file is a program in Gmsh's language, and a scene shared by a colleague should
// not run commands on the reader's machine, end the process, read or write other files,
// or mesh past what the scene declares. This screen reads the script's words (comments
// and strings skipped) and refuses the commands that act outside the geometry itself
// before Gmsh sees the file; a scene that trusts its file ([body.cloud] trusted = true)
// skips it.
#include "rkpm/particles/cloud.hpp"
#include "rkpm/particles/generators.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

namespace rkpm::particles {
namespace {

// Commands that act outside the geometry: processes (SystemCall, OnelabRun), the
// process's end (Exit, Abort), time (Sleep), files (CreateDir, Include, Merge, Save,
// Print, Printf's redirection, Plugin), control flow that can run without bound (For,
// While, Macro, Call, Function), meshing inside the script (Mesh), and element sizes or
// counts of the script's own, which would mesh past the size the scene declares
// (Field, Characteristic Length, MeshSize, Transfinite, extrusion Layers).
constexpr std::array<std::string_view, 25> kRefusedWords = {
    "SystemCall", "NonBlockingSystemCall", "OnelabRun", "Exit",           "Abort",         "Sleep",
    "CreateDir",  "Include",               "Merge",     "MergeWithBoundingBox", "Save",    "Print",
    "Printf",     "Plugin",                "For",       "While",          "Macro",         "Call",
    "Function",   "Mesh",                  "Field",     "Characteristic", "MeshSize",      "Transfinite",
    "Layers"};

// Option prefixes whose settings would change how the file is meshed (the element size
// the scene declares and the pre-flight counts with) or what the process does.
constexpr std::array<std::string_view, 3> kRefusedOptionPrefixes = {"Mesh.", "General.", "Solver."};

bool starts_word(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool in_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

[[noreturn]] void refuse(const std::string& path, int line, const std::string& word) {
  throw CloudError("Gmsh file '" + path + "' line " + std::to_string(line) + ": '" + word +
                   "' is not allowed in an untrusted .geo script (it acts outside the geometry or changes "
                   "the declared mesh size); expected a geometry only, or [body.cloud] trusted = true for a "
                   "file you wrote or checked");
}

}  // namespace

void screen_geo_script(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CloudError("Gmsh file '" + path + "': cannot be read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();

  int line = 1;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      const std::size_t stop = end == std::string::npos ? text.size() : end + 2;
      line += static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(i),
                                          text.begin() + static_cast<std::ptrdiff_t>(stop), '\n'));
      i = stop;
    } else if (c == '"') {
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\') ++i;
        else if (text[i] == '\n') ++line;
      }
      ++i;
    } else if (starts_word(c)) {
      const std::size_t begin = i;
      while (i < text.size() && in_word(text[i])) ++i;
      const std::string word = text.substr(begin, i - begin);
      if (std::find(kRefusedWords.begin(), kRefusedWords.end(), word) != kRefusedWords.end()) refuse(path, line, word);
      for (const auto prefix : kRefusedOptionPrefixes)
        if (word.compare(0, prefix.size(), prefix) == 0) refuse(path, line, word);
    } else {
      ++i;
    }
  }
}

}  // namespace rkpm::particles
