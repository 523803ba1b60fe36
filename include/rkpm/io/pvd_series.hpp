// A time series of .vtu frames listed by a ParaView .pvd collection file.
//
// Crash safety: each frame is written to a temporary and renamed, and only
// then is the .pvd rewritten (again temporary + rename) to list it. At any
// instant the .pvd on disk lists only complete, readable frames, so a run
// killed mid-write leaves a valid series ending at its last good frame.
#pragma once

#include "rkpm/io/frame.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rkpm::io {

struct PvdEntry {
  double time = 0.0;
  std::string file;  // relative to the .pvd's directory
};

// The .pvd text for `entries` (times printed so they read back bit-for-bit).
std::string pvd_text(const std::vector<PvdEntry>& entries);

// Parses the DataSet entries of a .pvd file. Throws std::runtime_error naming
// the file and the offending entry when it is missing or malformed.
std::vector<PvdEntry> read_pvd(const std::filesystem::path& pvd);

class PvdSeries {
 public:
  // Starts a new series: creates `dir` if needed and writes an empty
  // `<basename>.pvd` at once, so an older series of the same name is no longer
  // listed. `basename` may use letters, digits, '_', '-' and '.'.
  // `owner`: this process writes the .pvd (false on the other ranks of a distributed
  // run, which keep the same entries without touching the file).
  PvdSeries(std::filesystem::path dir, std::string basename, bool owner = true);

  // Continues a series after a restart from a checkpoint at `up_to_time`:
  // keeps the existing entries with time <= up_to_time, deletes the frame
  // files of the later (abandoned) entries, rewrites the .pvd, and numbers the
  // next frame after the last kept one. Throws if the .pvd is missing, or a
  // kept frame file is missing.
  static PvdSeries resume(const std::filesystem::path& dir, const std::string& basename, double up_to_time,
                          bool owner = true);

  // Validates and writes `frame` as `<basename>_<nnnnnn>.vtu` at simulated
  // `time` (which must be finite and later than the previous frame's), then
  // lists it in the .pvd. Invalid frames (NonFiniteValue, FrameError) throw
  // before any file is touched; on an I/O error the .pvd still lists exactly
  // the earlier frames and no temporary is left. Returns the frame path.
  std::filesystem::path write(double time, const Frame& frame);

  // Distributed runs write a frame in two phases, each called on every rank:
  //   write_piece: validates this rank's piece and writes `<basename>_<nnnnnn>_<rank>.vtu`;
  //   add_parallel_frame, once the caller has agreed that every rank's piece is on disk:
  //     the owner (rank 0) writes `<basename>_<nnnnnn>.pvtu` naming the `ranks` pieces (ParaView and
  //     VTK's readers open it as one grid) and lists it in the .pvd; every rank keeps
  //     the same entries. Returns the .pvtu path.
  std::filesystem::path write_piece(double time, const Frame& piece, int rank) const;
  std::filesystem::path add_parallel_frame(double time, const Frame& piece, int ranks);
  std::filesystem::path pvd_path() const;
  std::filesystem::path frame_path(int index) const;
  // Frames listed in the .pvd, including those kept by resume().
  int frames_written() const { return static_cast<int>(entries_.size()); }
  const std::vector<PvdEntry>& entries() const { return entries_; }

 private:
  PvdSeries(std::filesystem::path dir, std::string basename, std::vector<PvdEntry> entries, int next_index,
            bool owner);
  void rewrite_pvd() const;
  // Throws unless `time` is finite and later than the last frame's.
  void check_next_time(double time) const;

  std::filesystem::path dir_;
  std::string basename_;
  std::vector<PvdEntry> entries_;
  int next_index_ = 0;
  bool owner_ = true;
};

}  // namespace rkpm::io
