// `rkpm shape`: the red-blood-cell shape report (shape_report.hpp) of any frame of a
// run, so that a partial, interrupted or older run can be measured without rerunning it.
// The scene gives the cloud (its outer surface), the frame gives the positions.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>

namespace rkpm::sim {

struct ShapeCommandOptions {
  std::filesystem::path scene;    // the scene file of the run
  std::filesystem::path frame;    // a .vtu frame, or a run directory (its last listed frame)
  std::string body;               // empty: the scene's [output] shape_report body
  std::filesystem::path csv;      // profile output; empty: shape_profile.csv beside the frame
};

// Prints the report as JSON on `out` and writes the profile CSV. Returns an exit code
// (RunExit): kBadInput with a message on `log` for a bad scene, frame or body name.
int run_shape_command(const ShapeCommandOptions& options, std::ostream& out, std::ostream& log);

}  // namespace rkpm::sim
