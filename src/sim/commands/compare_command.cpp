#include "rkpm/sim/compare_command.hpp"

#include "rkpm/io/frame_points.hpp"
#include "rkpm/io/json.hpp"
#include "rkpm/sim/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace rkpm::sim {

int run_compare_command(const CompareCommandOptions& options, std::ostream& out, std::ostream& log) {
  try {
    const auto reference_frame = io::frame_file(options.reference);
    const auto other_frame = io::frame_file(options.other);
    const io::FramePoints a = io::read_frame_points(reference_frame);
    const io::FramePoints b = io::read_frame_points(other_frame);
    if (a.body_size != b.body_size)
      throw std::runtime_error(fmt::format("{} and {} hold different bodies or particle counts ({} and {} particles): "
                                           "expected two runs of the same scene",
                                           reference_frame.string(), other_frame.string(), a.position.size(),
                                           b.position.size()));
    double difference = 0.0, displacement = 0.0;
    for (std::size_t k = 0; k < a.position.size(); ++k) {
      difference = std::max(difference, (a.position[k] - b.position[k]).norm());
      if (!a.displacement.empty()) displacement = std::max(displacement, a.displacement[k].norm());
    }
    io::Json json = io::Json::object();
    json.set("reference", reference_frame.string());
    json.set("other", other_frame.string());
    json.set("particles", static_cast<std::int64_t>(a.position.size()));
    json.set("largest_difference", difference);  // [m]
    if (!a.displacement.empty()) {
      json.set("largest_displacement", displacement);
      json.set("relative_difference", displacement > 0.0 ? difference / displacement : 0.0);
    }
    out << json.dump() << "\n";
    return kSuccess;
  } catch (const std::exception& e) {
    log << "error: " << e.what() << "\n";
  }
  return kBadInput;
}

}  // namespace rkpm::sim
