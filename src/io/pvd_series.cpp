#include "rkpm/io/pvd_series.hpp"

#include "rkpm/io/atomic_file.hpp"
#include "rkpm/io/vtu_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rkpm::io {

namespace fs = std::filesystem;

namespace {

constexpr int kIndexDigits = 6;

void check_basename(const std::string& basename) {
  if (basename.empty()) throw std::invalid_argument("output basename is empty");
  for (char c : basename) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '-' || c == '.';
    // Restricting the name keeps the .pvd free of XML escaping and paths.
    if (!ok) {
      throw std::invalid_argument(
          fmt::format("output basename '{}' contains '{}'; expected letters, digits, '_', '-' or '.'", basename, c));
    }
  }
}

std::string frame_file_name(const std::string& basename, int index) {
  return fmt::format("{}_{:0{}d}.vtu", basename, index, kIndexDigits);
}

std::string piece_file_name(const std::string& basename, int index, int rank) {
  return fmt::format("{}_{:0{}d}_{}.vtu", basename, index, kIndexDigits, rank);
}

std::string parallel_file_name(const std::string& basename, int index) {
  return fmt::format("{}_{:0{}d}.pvtu", basename, index, kIndexDigits);
}

// The .pvtu of one frame: the pieces' array layout (taken from this rank's piece; every
// piece has the same arrays) and their file names.
std::string pvtu_text(const Frame& piece, const std::string& basename, int index, int ranks) {
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPointData>\n";
  for (const PointField& f : piece.point_fields)
    text += fmt::format("      <PDataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\"/>\n", f.name,
                        f.components);
  if (!piece.duplicate_points.empty())
    text += "      <PDataArray type=\"UInt8\" Name=\"vtkGhostType\" NumberOfComponents=\"1\"/>\n";
  text += "    </PPointData>\n    <PPoints>\n      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n"
          "    </PPoints>\n";
  for (int r = 0; r < ranks; ++r) text += fmt::format("    <Piece Source=\"{}\"/>\n", piece_file_name(basename, index, r));
  text += "  </PUnstructuredGrid>\n</VTKFile>\n";
  return text;
}

// The frame number encoded in `<basename>_<digits>.vtu` (or `.pvtu`, a distributed
// run's frame), or -1 if `file` is not one of this series' frame names.
int frame_index_of(const std::string& basename, const std::string& file) {
  const std::string prefix = basename + "_";
  const bool parallel = file.size() > 5 && file.compare(file.size() - 5, 5, ".pvtu") == 0;
  const std::string suffix = parallel ? ".pvtu" : ".vtu";
  if (file.size() <= prefix.size() + suffix.size() || file.compare(0, prefix.size(), prefix) != 0 ||
      file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0) {
    return -1;
  }
  const char* first = file.data() + prefix.size();
  const char* last = file.data() + file.size() - suffix.size();
  int index = -1;
  const auto [end, ec] = std::from_chars(first, last, index);
  return (ec == std::errc() && end == last && index >= 0) ? index : -1;
}

// Value of attribute `name` inside one XML start tag, or false if absent.
bool tag_attribute(const std::string& tag, const std::string& name, std::string& value) {
  for (std::size_t pos = tag.find(name); pos != std::string::npos; pos = tag.find(name, pos + 1)) {
    const bool starts_word = pos > 0 && std::isspace(static_cast<unsigned char>(tag[pos - 1]));
    std::size_t q = pos + name.size();
    while (q < tag.size() && std::isspace(static_cast<unsigned char>(tag[q]))) ++q;
    if (!starts_word || q >= tag.size() || tag[q] != '=') continue;
    ++q;
    while (q < tag.size() && std::isspace(static_cast<unsigned char>(tag[q]))) ++q;
    if (q >= tag.size() || (tag[q] != '"' && tag[q] != '\'')) return false;
    const std::size_t close = tag.find(tag[q], q + 1);
    if (close == std::string::npos) return false;
    value = tag.substr(q + 1, close - q - 1);
    return true;
  }
  return false;
}

}  // namespace

std::string pvd_text(const std::vector<PvdEntry>& entries) {
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const PvdEntry& e : entries) {
    // fmt's "{}" prints the shortest text that reads back to the same double.
    text += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", e.time, e.file);
  }
  text += "  </Collection>\n</VTKFile>\n";
  return text;
}

std::vector<PvdEntry> read_pvd(const fs::path& pvd) {
  std::ifstream in(pvd, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot open time-series file '{}'", pvd.string()));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (text.find("type=\"Collection\"") == std::string::npos) {
    throw std::runtime_error(fmt::format("'{}' is not a VTK Collection (.pvd) file", pvd.string()));
  }

  std::vector<PvdEntry> entries;
  for (std::size_t pos = text.find("<DataSet"); pos != std::string::npos; pos = text.find("<DataSet", pos + 1)) {
    const std::size_t end = text.find('>', pos);
    if (end == std::string::npos) throw std::runtime_error(fmt::format("'{}': unterminated DataSet tag", pvd.string()));
    const std::string tag = text.substr(pos, end - pos);
    PvdEntry entry;
    std::string time_text;
    if (!tag_attribute(tag, "timestep", time_text) || !tag_attribute(tag, "file", entry.file)) {
      throw std::runtime_error(
          fmt::format("'{}': DataSet entry '{}' lacks a timestep or file attribute", pvd.string(), tag));
    }
    const char* last = time_text.data() + time_text.size();
    const auto [parsed_end, ec] = std::from_chars(time_text.data(), last, entry.time);  // locale-independent
    if (ec != std::errc() || parsed_end != last || !std::isfinite(entry.time)) {
      throw std::runtime_error(
          fmt::format("'{}': timestep '{}' is not a finite number", pvd.string(), time_text));
    }
    entries.push_back(std::move(entry));
  }
  return entries;
}

PvdSeries::PvdSeries(fs::path dir, std::string basename, bool owner)
    : PvdSeries(std::move(dir), std::move(basename), {}, 0, owner) {
  rewrite_pvd();
}

PvdSeries::PvdSeries(fs::path dir, std::string basename, std::vector<PvdEntry> entries, int next_index, bool owner)
    : dir_(std::move(dir)),
      basename_(std::move(basename)),
      entries_(std::move(entries)),
      next_index_(next_index),
      owner_(owner) {
  check_basename(basename_);
  fs::create_directories(dir_);
}

PvdSeries PvdSeries::resume(const fs::path& dir, const std::string& basename, double up_to_time, bool owner) {
  check_basename(basename);
  const fs::path pvd = dir / (basename + ".pvd");
  if (!fs::exists(pvd)) {
    throw std::runtime_error(fmt::format("cannot resume output: time-series file '{}' does not exist", pvd.string()));
  }
  std::vector<PvdEntry> kept;
  std::vector<fs::path> abandoned;
  int next_index = 0;
  for (PvdEntry& e : read_pvd(pvd)) {
    const int index = frame_index_of(basename, e.file);
    if (index < 0) {
      throw std::runtime_error(fmt::format("cannot resume output: '{}' lists '{}', expected a name like '{}'",
                                           pvd.string(), e.file, frame_file_name(basename, 0)));
    }
    if (e.time <= up_to_time) {
      if (!fs::exists(dir / e.file)) {
        throw std::runtime_error(
            fmt::format("cannot resume output: frame '{}' listed in '{}' is missing", e.file, pvd.string()));
      }
      next_index = std::max(next_index, index + 1);
      kept.push_back(std::move(e));
    } else {
      abandoned.push_back(dir / e.file);
    }
  }
  PvdSeries series(dir, basename, std::move(kept), next_index, owner);
  // List only the kept frames first, then delete the abandoned ones: the .pvd
  // never names a file that is gone.
  series.rewrite_pvd();
  if (owner)
    for (const fs::path& file : abandoned) fs::remove(file);
  return series;
}

fs::path PvdSeries::pvd_path() const { return dir_ / (basename_ + ".pvd"); }

fs::path PvdSeries::frame_path(int index) const { return dir_ / frame_file_name(basename_, index); }

fs::path PvdSeries::write(double time, const Frame& frame) {
  check_next_time(time);
  validate_frame(frame);  // before any file is touched

  const fs::path path = frame_path(next_index_);
  replace_atomically(path, [&](const fs::path& tmp) { write_vtu(tmp, frame); });
  entries_.push_back({time, path.filename().string()});
  try {
    rewrite_pvd();
  } catch (...) {
    // The .pvd still lists the previous frames only; the unlisted new file is
    // overwritten by the next attempt, which reuses its number.
    entries_.pop_back();
    throw;
  }
  ++next_index_;
  return path;
}

fs::path PvdSeries::write_piece(double time, const Frame& piece, int rank) const {
  check_next_time(time);
  validate_frame(piece);  // before any file is touched
  const fs::path path = dir_ / piece_file_name(basename_, next_index_, rank);
  replace_atomically(path, [&](const fs::path& tmp) { write_vtu(tmp, piece); });
  return path;
}

fs::path PvdSeries::add_parallel_frame(double time, const Frame& piece, int ranks) {
  const fs::path path = dir_ / parallel_file_name(basename_, next_index_);
  entries_.push_back({time, path.filename().string()});
  if (owner_) {
    try {
      write_text_atomically(path, pvtu_text(piece, basename_, next_index_, ranks));
      rewrite_pvd();
    } catch (...) {
      entries_.pop_back();
      throw;
    }
  }
  ++next_index_;
  return path;
}

void PvdSeries::check_next_time(double time) const {
  if (!std::isfinite(time)) throw NonFiniteValue(fmt::format("output frame time is {}", time));
  if (!entries_.empty() && !(time > entries_.back().time)) {
    throw FrameError(fmt::format("output frame time {} is not after the previous frame's time {}", time,
                                 entries_.back().time));
  }
}

void PvdSeries::rewrite_pvd() const {
  if (owner_) write_text_atomically(pvd_path(), pvd_text(entries_));
}

}  // namespace rkpm::io
