#include "sim/run/run_output.hpp"

#include "sim/run/collective_output.hpp"

#include <fmt/format.h>

namespace rkpm::sim {

RunOutput::RunOutput(const par::Comm& comm, const std::filesystem::path& out_dir, const World& world,
                     const Body* shape_body, CellOutput cells, bool resume)
    : comm_(comm), cells_(cells) {
  try {
    if (resume)
      collective_output(comm, [&] { series_ = io::PvdSeries::resume(out_dir, "frames", world.time, comm.root()); });
    else
      collective_output(comm, [&] { series_.emplace(out_dir, "frames", comm.root()); });
  } catch (const std::exception& e) {
    if (resume) throw ResumeRefused(e.what());
    throw OutputFailed(fmt::format("cannot write the output folder '{}': {}", out_dir.string(), e.what()));
  }
  collective_output(comm, [&] { history_.emplace(out_dir / "history.csv", world, shape_body, resume); });
}

void RunOutput::write_frame(const World& world, Integrator& integrator) {
  if (!comm_.parallel()) {
    collective_output(comm_, [&] {
      series_->write(world.time, make_frame(world, cells_, positions_));
      history_->record(world, integrator);
    });
    return;
  }
  // Each rank's piece, then the .pvtu and the .pvd once all pieces are on disk.
  io::Frame piece;
  collective_output(comm_, [&] { piece = make_frame(world, cells_, positions_); });
  collective_output(comm_, [&] { series_->write_piece(world.time, piece, comm_.rank()); });
  collective_output(comm_, [&] { series_->add_parallel_frame(world.time, piece, comm_.size()); });
  collective_output(comm_, [&] { history_->record(world, integrator); });
}

bool RunOutput::has_frame_at(double time) const {
  return !series_->entries().empty() && series_->entries().back().time >= time;
}

}  // namespace rkpm::sim
