// The run's writes, made on every rank and agreed on (the run loop and its summary).
#pragma once

#include "rkpm/io/vtu_writer.hpp"
#include "rkpm/par/comm.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace rkpm::sim {

// A write of the run's output failed (the folder, a frame, history.csv, a checkpoint).
struct OutputFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs `write` (on every rank) and agrees on the outcome: a failure on any rank ends the
// output on every rank with the lowest failing rank's message (one voice), as the
// failure it was: a non-finite value found in a frame's data is the simulation's
// failure and passes as NonFiniteValue; anything else is the disk's, OutputFailed.
template <class Write>
void collective_output(const par::Comm& comm, Write&& write) {
  std::int64_t kind = 0;  // 1: a non-finite value, 2: an output failure
  std::string message;
  try {
    write();
  } catch (const io::NonFiniteValue& e) {
    kind = 1;
    message = e.what();
  } catch (const std::exception& e) {
    kind = 2;
    message = e.what();
  }
  if (!comm.parallel()) {
    if (kind == 1) throw io::NonFiniteValue(message);
    if (kind == 2) throw OutputFailed(message);
    return;
  }
  const auto kinds = comm.gather(kind);
  for (std::size_t r = 0; r < kinds.size(); ++r) {
    if (kinds[r] == 0) continue;
    const std::string text = fmt::format("rank {}: {}", r, comm.broadcast(message, static_cast<int>(r)));
    if (kinds[r] == 1) throw io::NonFiniteValue(text);
    throw OutputFailed(text);
  }
}

// A checkpoint file of this rank: the name itself on one rank, `<name>.<rank>` on more.
inline std::filesystem::path rank_file(const std::filesystem::path& path, const par::Comm& comm) {
  if (!comm.parallel()) return path;
  return path.string() + "." + std::to_string(comm.rank());
}

}  // namespace rkpm::sim
