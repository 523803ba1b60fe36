#include "rkpm/sim/shape_command.hpp"

#include "rkpm/io/json.hpp"
#include "rkpm/io/frame_points.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/history.hpp"
#include "rkpm/sim/run.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace rkpm::sim {

int run_shape_command(const ShapeCommandOptions& options, std::ostream& out, std::ostream& log) {
  try {
    const scene::Scene scene = scene::load_scene(options.scene.string());
    const std::string name = options.body.empty() ? scene.output.text("shape_report") : options.body;
    if (name.empty())
      throw std::runtime_error(fmt::format("{}: [output] shape_report is not set: name the shell body with --body",
                                           options.scene.string()));
    const auto frame = io::frame_file(options.frame);
    const auto positions = io::read_frame_points(frame).position;

    // The particles of all bodies in scene order, each in its one-rank numbering.
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
