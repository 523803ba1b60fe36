// A .geo file is a program in Gmsh's language, and a scene shared by a colleague should
// not run commands on the reader's machine, end the process, read or write other files,
// or mesh past what the scene declares. This screen reads the script as Gmsh's lexer
// does (its two kinds of quotes, no escapes, `//` and `/* */` comments) and refuses,
// before Gmsh sees the file, the commands and constructs that act outside the geometry
// itself. It is a list of what is refused, so it is a guard, not a sandbox: a scene
// that trusts its file ([body.cloud] trusted = true) skips it, and the docs ask users to
// trust only files they wrote or read (docs/guide/scenes.md).
#include "rkpm/particles/cloud.hpp"
#include "rkpm/particles/generators.hpp"

#include <algorithm>
#include <iterator>
#include <cctype>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

namespace rkpm::particles {
namespace {

// Commands that act outside the geometry: processes (System, SystemCall, OnelabRun),
// the process's end (Exit, Abort, Error once options change), time (Sleep), files and
// the environment (CreateDir, Include, Merge, Save, Print, Printf's redirection, Plugin,
// ShapeFromFile, ListFromFile, GetEnv, and the prompts GetString, GetValue, GetNumber),
// options (Options, SetNumber, SetString, which Delete Options and ONELAB use), names
// made from strings (S2N, StringToName: a command spelt inside a string), control flow
// that can run without bound (For, While, Macro, Call, Function), copies that can double
// the model line by line (Duplicata), meshing inside the script (Mesh, RefineMesh,
// OptimizeMesh, SetOrder), and element sizes or counts of the script's own (Field,
// Characteristic, MeshSize, Transfinite, Layers).
constexpr std::string_view kRefusedWords[] = {
    "System",      "SystemCall",   "NonBlockingSystemCall", "OnelabRun",     "OnelabAction", "Exit",
    "Abort",       "Error",        "Sleep",                 "CreateDir",     "Include",      "Merge",
    "MergeWithBoundingBox", "Save", "Print",                "Printf",        "Plugin",       "ShapeFromFile",
    "ListFromFile", "GetEnv",      "GetString",             "GetValue",      "GetNumber",    "Options",
    "SetNumber",   "SetString",    "SetChanged",            "S2N",           "StringToName", "For",
    "While",       "Macro",        "Call",                  "Function",      "Duplicata",    "Mesh",
    "RefineMesh",  "OptimizeMesh", "SetOrder",              "Field",         "Characteristic", "MeshSize",
    "Transfinite", "Layers"};

bool starts_word(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool in_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

[[noreturn]] void refuse(const std::string& path, int line, const std::string& what) {
  throw CloudError("Gmsh file '" + path + "' line " + std::to_string(line) + ": " + what +
                   " is not allowed in an untrusted .geo script (it acts outside the geometry or changes "
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
  const auto skip_to = [&](std::size_t from, std::size_t to) {
    line += static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(from),
                                        text.begin() + static_cast<std::ptrdiff_t>(to), '\n'));
    return to;
  };
  // Bytes Gmsh's lexer reads otherwise than a text file, wherever they are: a NUL ends a
  // comment early, a carriage return alone would hide the line count.
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\0') refuse(path, line, "a NUL byte");
    if (text[i] == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n')) refuse(path, line, "a bare carriage return");
    if (text[i] == '\n') ++line;
  }
  line = 1;
  char previous = ' ';  // the last character that was not blank, outside comments
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (text.compare(i, 2, "//") == 0) {
      i = skip_to(i, std::min(text.find('\n', i), text.size()));
    } else if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      i = skip_to(i, end == std::string::npos ? text.size() : end + 2);
    } else if (c == '"' || c == '\'') {
      // Gmsh's strings have no escapes: the string ends at the next quote of its kind.
      const std::size_t end = text.find(c, i + 1);
      if (end == std::string::npos) refuse(path, line, "an unterminated string");
      i = skip_to(i, end + 1);
      previous = c;
    } else if (starts_word(c) && !(std::isdigit(static_cast<unsigned char>(previous)) || previous == '.')) {
      const std::size_t begin = i;
      while (i < text.size() && in_word(text[i])) ++i;
      const std::string word = text.substr(begin, i - begin);
      if (std::find(std::begin(kRefusedWords), std::end(kRefusedWords), word) != std::end(kRefusedWords))
        refuse(path, line, "'" + word + "'");
      previous = 'a';
    } else if (c == '.' && (std::isalpha(static_cast<unsigned char>(previous)) || previous == '_' ||
                            previous == ']')) {
      // Name.Option or Name[i].Option: an option of Gmsh's, which can change the mesh
      // size, the error handling or the process (a number's point follows a digit).
      refuse(path, line, "an option (a name followed by '.')");
    } else {
      if (!std::isspace(static_cast<unsigned char>(c))) previous = c;
      ++i;
    }
  }
}

}  // namespace rkpm::particles
