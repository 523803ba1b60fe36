// A loaded and fully validated scene: plain data for the program to build a
// simulation from. Everything the file got wrong was reported while loading, so
// code that reads a Scene never has to check user input again.
#pragma once

#include "rkpm/scene/param_set.hpp"
#include "rkpm/scene/scene_error.hpp"

#include <optional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace rkpm::scene {

struct BodySpec {
  ParamSet body;                       // [[body]]: name, density
  ParamSet cloud;                      // [body.cloud]: generator and that generator's keys
  ParamSet material;                   // [body.material]: model and that model's keys
  // The material model's own sub-tables of [[body]] (ParamTable::companion_sections), by
  // their name after "body.": present exactly for the models that declare them.
  std::map<std::string, ParamSet> material_sections;
  ParamSet rk;                         // [body.rk]
  ParamSet initial;                    // [body.initial]
  std::vector<ParamSet> boundaries;    // [[body.boundary]]
  std::string cloud_file;              // vtu and gmsh clouds: the file, resolved against the scene's directory
  std::vector<std::string> file_surfaces;  // gmsh clouds: "surface" and the file's physical surfaces

  const std::string& name() const { return body.text("name"); }
  const std::string& generator() const { return cloud.choice("generator"); }
  const std::string& model() const { return material.choice("model"); }
  // [body.<name>] of the model's own sub-tables; throws std::logic_error for a name the
  // model does not declare (a model reads only its own).
  const ParamSet& material_section(const std::string& name) const;
  // The named surfaces the body's cloud generator provides.
  const std::vector<std::string>& surfaces() const;
};

struct TermSpec {
  ParamSet params;                     // [[term]]: type and that term's keys
  const std::string& type() const { return params.choice("type"); }
};

struct Scene {
  std::string file;                    // as given to load_scene
  ParamSet scene;                      // [scene]
  ParamSet integrator;                 // [integrator]
  ParamSet output;                     // [output]
  std::vector<BodySpec> bodies;        // in file order
  std::vector<TermSpec> terms;         // only the terms the file declares, in file order

  const BodySpec* find_body(std::string_view name) const;  // nullptr if absent
  std::vector<const TermSpec*> terms_of(std::string_view type) const;
};

// Reads, parses and validates a scene file. Throws SceneError (FILE:LINE: ...) for
// a file that cannot be read, a TOML syntax error, an unknown key or section, a
// wrong type, an out-of-range value, a missing file it refers to, or an
// inconsistent combination of keys.
Scene load_scene(const std::string& path);

// The same from text; `display_name` names the file in messages, and relative
// paths inside the scene are resolved against its directory.
Scene parse_scene(std::string_view toml_text, const std::string& display_name);

}  // namespace rkpm::scene
