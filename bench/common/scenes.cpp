#include "scenes.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace rkpm::bench {

namespace {

// Cube of the adhesion substrate's material, clamped at its base and loaded by a
// body force so that the step does real work (finite strain, non-zero stress).
std::string block_text(int cells) {
  return fmt::format(R"(
[scene]
name = "perf_block"

[integrator]
mode = "dynamic"
t_end = 1e-3

[output]
every = 1e-3

[[body]]
name = "block"
density = 1000.0

[body.cloud]
generator = "block"
size = [10e-6, 10e-6, 10e-6]
cells = [{0}, {0}, {0}]

[body.material]
model = "mooney_rivlin"
c1 = 2.126e3
c2 = 1.7e2
lambda = 1.7e5

[[body.boundary]]
surface = "zmin"
type = "fixed"

[[term]]
type = "body_force"
body = "block"
acceleration = [0.0, 0.0, -2e5]
)",
                     cells);
}

// The adhesion scene's cell on its own: LCE with the Frank term (kappa > 0), director
// anchored to the surface normal, surface tension against the medium.
std::string sphere_text(int cells) {
  return fmt::format(R"(
[scene]
name = "perf_sphere"

[integrator]
mode = "dynamic"
t_end = 1e-3
damping = 5e5

[output]
every = 1e-3

[[body]]
name = "cell"
density = 1000.0

[body.cloud]
generator = "sphere"
radius = 5e-6
cells = {}

[body.material]
model = "lce"
mu = 1e4
bulk = 1e5
s = 2.0
kappa = 1e-11

[body.director]
initial = "surface_normal"
boundary = "normal"

[[term]]
type = "surface_tension"
body = "cell"
gamma = 1e-3
)",
                     cells);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Replaces the value of `key = ...` at the start of a line (the first such line).
std::string set_key(const std::string& text, const std::string& key, const std::string& value) {
  const std::regex line("^" + key + "\\s*=[^\\n#]*", std::regex::multiline);
  if (!std::regex_search(text, line)) throw std::runtime_error("the RBC scene has no '" + key + " =' line");
  return std::regex_replace(text, line, key + " = " + value, std::regex_constants::format_first_only);
}

// Declares the body's support shape and particle order: a [body.rk] section before its
// material (every scene here has one body and no [body.rk] of its own).
std::string with_rk(const std::string& text, const RkChoices& rk) {
  if (text.find("[body.rk]") != std::string::npos)
    throw std::runtime_error("the scene declares [body.rk] itself; the study sets its [body.rk] keys");
  const auto at = text.find("[body.material]");
  if (at == std::string::npos) throw std::runtime_error("the scene has no [body.material]");
  return text.substr(0, at) +
         fmt::format("[body.rk]\nsupport_shape = \"{}\"\nparticle_order = \"{}\"\ngradient_precision = \"{}\"\n\n",
                     rk.support_shape, rk.particle_order, rk.gradient_precision) +
         text.substr(at);
}

}  // namespace

const char* geometry_name(Geometry g) {
  switch (g) {
    case Geometry::Block: return "block";
    case Geometry::Sphere: return "sphere";
    case Geometry::Shell: return "shell";
  }
  return "?";
}

Geometry parse_geometry(const std::string& name) {
  for (Geometry g : {Geometry::Block, Geometry::Sphere, Geometry::Shell})
    if (name == geometry_name(g)) return g;
  throw std::invalid_argument("unknown geometry '" + name + "' (block, sphere, shell)");
}

long long particles_at(Geometry g, int r) {
  const long long n = r;
  // Block and ball: (cells + 1)^3 nodes. Shell: 6 fc^2 + 2 nodes per layer.
  return g == Geometry::Shell ? shell_layers * (6 * n * n + 2) : (n + 1) * (n + 1) * (n + 1);
}

int resolution_for(Geometry g, double target) {
  const int minimum = g == Geometry::Shell ? 4 : 2;
  int best = minimum;
  for (int r = minimum; particles_at(g, r) < 4.0 * target; ++r)
    if (std::abs(std::log(particles_at(g, r) / target)) < std::abs(std::log(particles_at(g, best) / target))) best = r;
  return best;
}

scene::Scene make_scene(Geometry g, int resolution, const std::string& rbc_scene, const RkChoices& rk) {
  switch (g) {
    case Geometry::Block:
      return scene::parse_scene(with_rk(block_text(resolution), rk), "perf_block.toml");
    case Geometry::Sphere:
      return scene::parse_scene(with_rk(sphere_text(resolution), rk), "perf_sphere.toml");
    case Geometry::Shell: {
      std::string text = read_text(rbc_scene);
      text = set_key(text, "face_cells", std::to_string(resolution));
      text = set_key(text, "layers", std::to_string(shell_layers));
      return scene::parse_scene(with_rk(text, rk), rbc_scene);
    }
  }
  throw std::logic_error("geometry");
}

std::string source_file(const std::string& relative) {
  if (const char* dir = std::getenv("RKPM_SOURCE_DIR"); dir && *dir) return std::string(dir) + "/" + relative;
  return std::string(RKPM_SOURCE_DIR) + "/" + relative;
}

}  // namespace rkpm::bench
