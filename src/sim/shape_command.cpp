#include "rkpm/sim/shape_command.hpp"

#include "rkpm/io/json.hpp"
#include "rkpm/io/pvd_series.hpp"
#include "rkpm/io/vtu_points.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/history.hpp"
#include "rkpm/sim/run.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace rkpm::sim {

namespace {

// A run directory stands for the last frame its frames.pvd lists.
std::filesystem::path frame_file(const std::filesystem::path& given) {
  if (!std::filesystem::is_directory(given)) return given;
  const auto pvd = given / "frames.pvd";
  const auto entries = io::read_pvd(pvd);
  if (entries.empty()) throw std::runtime_error(pvd.string() + ": lists no frame");
  return given / entries.back().file;
}

}  // namespace

int run_shape_command(const ShapeCommandOptions& options, std::ostream& out, std::ostream& log) {
  try {
    const scene::Scene scene = scene::load_scene(options.scene.string());
    const std::string name = options.body.empty() ? scene.output.text("shape_report") : options.body;
    if (name.empty())
      throw std::runtime_error(fmt::format("{}: [output] shape_report is not set: name the shell body with --body",
                                           options.scene.string()));
    const auto frame = frame_file(options.frame);
    const auto positions = io::read_vtu_points(frame);

    // The frame lists the particles of all bodies in scene order.
    std::size_t offset = 0, total = 0;
    std::optional<particles::Cloud> cloud;
    for (const auto& body : scene.bodies) {
      particles::Cloud c = build_cloud(body);
      if (body.name() == name && !cloud) {
        offset = total;
        cloud = std::move(c);
        total += cloud->size();
      } else {
        total += c.size();
      }
    }
    if (!cloud) throw std::runtime_error(fmt::format("{}: no body named '{}'", options.scene.string(), name));
    if (cloud->surface_bit("outer") == 0u)
      throw std::runtime_error(fmt::format("{}: body '{}' has no outer surface: expected a shell body",
                                           options.scene.string(), name));
    if (positions.size() != total)
      throw std::runtime_error(fmt::format("{}: {} points, but the bodies of {} have {} particles: "
                                           "expected a frame of a run of this scene",
                                           frame.string(), positions.size(), options.scene.string(), total));
    const std::vector<Vec3> x(positions.begin() + static_cast<std::ptrdiff_t>(offset),
                              positions.begin() + static_cast<std::ptrdiff_t>(offset + cloud->size()));
    const ShapeReport shape = measure_shape(*cloud, x, "outer");
    const auto csv = options.csv.empty() ? frame.parent_path() / "shape_profile.csv" : options.csv;
    io::Json json = io::Json::object();
    json.set("frame", frame.string());
    json.set("body", name);
    write_shape(shape, csv, json);
    json.set("profile_csv", csv.string());
    out << json.dump() << "\n";
    return kSuccess;
  } catch (const scene::SceneError& e) {
    log << "error: " << e.what() << "\n";
  } catch (const std::exception& e) {
    log << "error: " << e.what() << "\n";
  }
  return kBadInput;
}

}  // namespace rkpm::sim
