// What a run writes as it goes: the frames (frames.pvd and its .vtu, or each rank's
// piece and the .pvtu) and, with each frame, its row of history.csv. The run loop asks
// for a frame; this class decides how a frame is written on one rank or many.
#pragma once

#include "rkpm/io/pvd_series.hpp"
#include "rkpm/par/comm.hpp"
#include "rkpm/sim/history.hpp"
#include "rkpm/sim/output.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

namespace rkpm::sim {

// A resumed run whose output folder does not match its checkpoint (the .pvd or
// history.csv): the restart's input is wrong, not the disk.
struct ResumeRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class RunOutput {
 public:
  // Opens frames.pvd and history.csv in `out_dir` on every rank, agreed on: fresh, or
  // (`resume`) kept up to world.time and appended to. Throws ResumeRefused when a
  // resumed series cannot be kept, OutputFailed when a file cannot be written.
  RunOutput(const par::Comm& comm, const std::filesystem::path& out_dir, const World& world, const Body* shape_body,
            CellOutput cells, bool resume);

  // The world's present state as the next frame, and its row of history.csv.
  // Collective; throws OutputFailed or io::NonFiniteValue (collective_output).
  void write_frame(const World& world, Integrator& integrator);

  // Whether the series already holds a frame at `time` or later.
  bool has_frame_at(double time) const;
  std::int64_t frames_written() const { return series_->frames_written(); }
  std::filesystem::path pvd_path() const { return series_->pvd_path(); }

 private:
  const par::Comm& comm_;
  CellOutput cells_;
  std::optional<io::PvdSeries> series_;
  std::optional<History> history_;
  std::vector<Vec3> positions_;  // make_frame's scratch
};

}  // namespace rkpm::sim
