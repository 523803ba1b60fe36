// The scene side of the cloud-generator catalog (compiled into rkpm_scene): the tables,
// the loader's reading, the nested levels' rescaling and the wall thickness.
#include "clouds/catalog.hpp"

#include "rkpm/scene/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace rkpm::clouds {

namespace {
// Calls `call` on the catalog entry named `generator`; a validated scene never names
// another (the registry's choices are the catalog's).
template <class Call>
auto dispatch(const std::string& generator, Call&& call) {
#define RKPM_CLOUD(entry) \
  if (generator == #entry) return call(entry::table, entry::load, entry::rescale, entry::wall_thickness);
#include "clouds/catalog.def"
#undef RKPM_CLOUD
  throw std::logic_error("generator \"" + generator + "\" is not in the cloud catalog");
}
}  // namespace

scene::ParamTable cloud_table(std::string generator, std::string help) {
  scene::ParamTable t;
  t.section = "body.cloud";
  t.selector_key = "generator";
  t.selector_value = std::move(generator);
  t.help = std::move(help);
  return t;
}

std::vector<scene::ParamTable> cloud_tables() {
  return {
#define RKPM_CLOUD(generator) generator::table(),
#include "clouds/catalog.def"
#undef RKPM_CLOUD
  };
}

void load_cloud(scene::BodySpec& spec) {
  dispatch(spec.generator(), [&](auto, auto load, auto, auto) { load(spec); });
}

bool rescale_cloud(scene::ParamSet& cloud, double factor) {
  return dispatch(cloud.choice("generator"), [&](auto, auto, auto rescale, auto) { return rescale(cloud, factor); });
}

bool can_rescale(const scene::BodySpec& spec) {
  scene::ParamSet copy = spec.cloud;
  return rescale_cloud(copy, 1.0);
}

double wall_thickness(const scene::BodySpec& spec) {
  return dispatch(spec.generator(), [&](auto, auto, auto, auto thickness) { return thickness(spec.cloud); });
}

std::int64_t scaled_cells(std::int64_t cells, double factor, std::int64_t smallest) {
  return std::max(smallest, static_cast<std::int64_t>(std::lround(static_cast<double>(cells) * factor)));
}

std::string key_at(const scene::ParamSet& p, const std::string& key) {
  return fmt::format("{}:{}: [{}] {}", p.file(), p.line(key), p.section(), key);
}

std::string existing_file(const scene::ParamSet& p, const std::string& key) {
  namespace fs = std::filesystem;
  const fs::path given = p.text(key);
  const fs::path resolved = given.is_absolute() ? given : (fs::path(p.file()).parent_path() / given).lexically_normal();
  std::error_code ec;
  if (!fs::is_regular_file(resolved, ec))
    throw p.error(key, fmt::format("an existing file (resolved to {})", resolved.string()));
  return resolved.string();
}

}  // namespace rkpm::clouds
