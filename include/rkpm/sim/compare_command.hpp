// `rkpm compare`: how far apart two runs of one scene end, particle by particle. The
// same scene on another rank or thread count, a restarted run against an uninterrupted
// one, a build against another: each frame is read in the one-rank numbering
// (io/frame_points.hpp), so runs on any rank counts compare directly.
#pragma once

#include <filesystem>
#include <ostream>

namespace rkpm::sim {

struct CompareCommandOptions {
  std::filesystem::path reference;  // a frame, or a run directory (its last listed frame)
  std::filesystem::path other;
};

// Prints JSON on `out`: the particle count, the largest distance between a particle's
// two positions, the reference's largest displacement and their ratio. Returns an exit
// code (RunExit): kBadInput with a message on `log` when a frame cannot be read or the
// two frames do not hold the same bodies and particles.
int run_compare_command(const CompareCommandOptions& options, std::ostream& out, std::ostream& log);

}  // namespace rkpm::sim
