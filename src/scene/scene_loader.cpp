// Reading a scene file: TOML parsing, the layout of sections, and validation of
// every table against the registry. Checks across sections are in scene_checks.cpp.
#include "clouds/catalog.hpp"
#include "rkpm/scene/param_registry.hpp"
#include "rkpm/scene/scene.hpp"
#include "scene_checks.hpp"
#include "spelling.hpp"
#include "validate.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace rkpm::scene {
namespace {

namespace fs = std::filesystem;

// What may appear at the top level and inside a [[body]] besides its own keys.
const std::vector<std::string> kSections = {"scene", "integrator", "output", "body", "term"};
const std::vector<std::string> kArraySections = {"body", "term"};
bool contains(const std::vector<std::string>& list, std::string_view word) {
  return std::find(list.begin(), list.end(), word) != list.end();
}

// The name of a [[body]] sub-table from its section ("body.rk" -> "rk").
std::string sub_table_name(const std::string& section) { return section.substr(section.find('.') + 1); }

// The sub-tables a [[body]] may have: its own, and every material model's companions.
const std::vector<std::string>& body_subsections() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = {"cloud", "material", "rk", "initial", "boundary"};
    for (const auto& model : ParamRegistry::instance().variant_names("body.material"))
      for (const auto& section : ParamRegistry::instance().variant("body.material", model)->companion_sections)
        if (!contains(all, sub_table_name(section))) all.push_back(sub_table_name(section));
    return all;
  }();
  return names;
}

// Whether the [body.material] model `model` takes the section `section` alongside
// (ParamTable::companion_sections), and the models that do, for messages.
bool takes_section(const std::string& model, const std::string& section) {
  const ParamTable* table = ParamRegistry::instance().variant("body.material", model);
  return table && contains(table->companion_sections, section);
}

std::string models_taking(const std::string& section) {
  std::string names;
  for (const auto& model : ParamRegistry::instance().variant_names("body.material")) {
    if (!takes_section(model, section)) continue;
    names += fmt::format("{}model = \"{}\"", names.empty() ? "" : " or ", model);
  }
  return names.empty() ? "no model" : names;
}

class Loader {
 public:
  Loader(const toml::table& root, std::string file) : root_(root), file_(std::move(file)) {}

  Scene load() {
    check_top_level_keys();
    Scene scene;
    scene.file = file_;
    scene.scene = section("scene", true);
    scene.integrator = section("integrator", true);
    scene.output = section("output", false);
    for (const toml::table* body : array_section("body", true)) scene.bodies.push_back(load_body(*body));
    for (const toml::table* term : array_section("term", false)) {
      scene.terms.push_back(TermSpec{validate_variant_table(*term, site("term", line_of(*term)))});
    }
    check_scene(scene);
    return scene;
  }

 private:
  TableSite site(const std::string& section, int line) const { return TableSite{file_, section, line}; }

  SceneError section_error(int line, const std::string& section, const std::string& expected) const {
    return SceneError(file_, line, section, "", "", expected);
  }

  void check_top_level_keys() const {
    for (const auto& [key, node] : root_) {
      const std::string name(key.str());
      if (contains(kSections, name)) continue;
      if (node.is_table() || node.is_array_of_tables()) {
        throw section_error(line_of(node), name, "a known section: " + list_with_suggestion(name, kSections, false));
      }
      throw SceneError(file_, line_of(node), fmt::format("{} = {}: expected a key inside a section; sections: {}",
                                                         name, toml_text(node),
                                                         list_with_suggestion(name, kSections, false)));
    }
  }

  // A single-table section; an absent optional one validates as empty (all defaults).
  ParamSet section(const std::string& name, bool required) const {
    const ParamTable* table = ParamRegistry::instance().section(name);
    const toml::node* node = root_.get(name);
    if (!node) {
      if (required) {
        throw SceneError(file_, 0, fmt::format("[{}]: expected this section (required), with keys: {}", name,
                                               list_with_suggestion("", table->names(), false)));
      }
      return validate_table(toml::table{}, {table}, site(name, 0));
    }
    const toml::table* t = node->as_table();
    if (!t) throw section_error(line_of(*node), name, fmt::format("a single [{}] table", name));
    return validate_table(*t, {table}, site(name, line_of(*t)));
  }

  std::vector<const toml::table*> array_section(const std::string& name, bool required) const {
    std::vector<const toml::table*> out;
    const toml::node* node = root_.get(name);
    if (!node) {
      if (required) throw SceneError(file_, 0, fmt::format("[[{}]]: expected at least one (required)", name));
      return out;
    }
    if (!node->is_array_of_tables()) {
      throw section_error(line_of(*node), name, fmt::format("[[{}]] (an array of tables, one per {})", name, name));
    }
    for (const auto& item : *node->as_array()) out.push_back(item.as_table());
    return out;
  }

  BodySpec load_body(const toml::table& body_table) const {
    const int body_line = line_of(body_table);
    const ParamTable* own = ParamRegistry::instance().section("body");

    // The body's own keys sit beside its sub-tables; an unknown key lists both.
    for (const auto& [key, node] : body_table) {
      const std::string name(key.str());
      if (contains(body_subsections(), name) || own->find(name)) continue;
      std::vector<std::string> known = own->names();
      known.insert(known.end(), body_subsections().begin(), body_subsections().end());
      throw SceneError(file_, line_of(node), "body", name, toml_text(node),
                       "a known key or sub-table: " + list_with_suggestion(name, known, false));
    }

    BodySpec spec;
    spec.body = validate_table(body_table, {own}, site("body", body_line), body_subsections());
    spec.cloud = validate_variant_table(sub_table(body_table, "cloud", body_line, true), site_of(body_table, "cloud"));
    spec.material = validate_variant_table(sub_table(body_table, "material", body_line, true), site_of(body_table, "material"));
    spec.rk = plain_sub_table(body_table, "rk");
    spec.initial = plain_sub_table(body_table, "initial");

    // A model's own sub-tables (the LCE's own table) exist exactly for the models
    // whose table declares them; other models reject them.
    for (const auto& name : body_subsections()) {
      const std::string section = "body." + name;
      if (!contains({"cloud", "material", "rk", "initial", "boundary"}, name) && body_table.get(name) &&
          !takes_section(spec.model(), section))
        throw section_error(line_of(*body_table.get(name)), section,
                            fmt::format("no {} table for model = \"{}\" (only {} has a {})", name, spec.model(),
                                        models_taking(section), name));
    }
    if (const ParamTable* model = ParamRegistry::instance().variant("body.material", spec.model()))
      for (const auto& section : model->companion_sections)
        spec.material_sections.emplace(sub_table_name(section), plain_sub_table(body_table, sub_table_name(section)));

    if (const toml::node* node = body_table.get("boundary")) {
      if (!node->is_array_of_tables()) {
        throw section_error(line_of(*node), "body.boundary", "[[body.boundary]] (an array of tables, one per condition)");
      }
      const ParamTable* table = ParamRegistry::instance().section("body.boundary");
      for (const auto& item : *node->as_array()) {
        spec.boundaries.push_back(validate_table(*item.as_table(), {table}, site("body.boundary", line_of(item))));
      }
    }

    clouds::load_cloud(spec);
    return spec;
  }

  TableSite site_of(const toml::table& body_table, const std::string& sub) const {
    const toml::node* node = body_table.get(sub);
    return site("body." + sub, node ? line_of(*node) : line_of(body_table));
  }

  const toml::table& sub_table(const toml::table& body_table, const std::string& sub, int body_line,
                               bool required) const {
    static const toml::table empty;
    const toml::node* node = body_table.get(sub);
    if (!node) {
      if (required) {
        throw section_error(body_line, "body." + sub, "this table for every body (required)");
      }
      return empty;
    }
    if (!node->is_table()) throw section_error(line_of(*node), "body." + sub, fmt::format("a single [body.{}] table", sub));
    return *node->as_table();
  }

  ParamSet plain_sub_table(const toml::table& body_table, const std::string& sub) const {
    const TableSite where = site_of(body_table, sub);
    return validate_table(sub_table(body_table, sub, where.line, false),
                          {ParamRegistry::instance().section(where.section)}, where);
  }

  // Paths in a scene are relative to the scene file's directory, so a scene and
  // its meshes can be moved together.
  // A Gmsh cloud: the file must be one Gmsh reads (.msh or .geo), a .geo needs a mesh
  // size, and its physical surfaces become the names the body's tables may use.
  const toml::table& root_;
  std::string file_;
};

}  // namespace

Scene parse_scene(std::string_view toml_text, const std::string& display_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, display_name);
  } catch (const toml::parse_error& e) {
    throw SceneError(display_name, static_cast<int>(e.source().begin.line),
                     fmt::format("TOML syntax error: {}", e.description()));
  }
  return Loader(root, display_name).load();
}

Scene load_scene(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!fs::is_regular_file(path) || !in) {
    throw SceneError(path, 0, fmt::format("cannot read the scene file: {}", fs::exists(path) ? "not a readable file" : "no such file"));
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path);
}

}  // namespace rkpm::scene
