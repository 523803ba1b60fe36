#include "rkpm/io/frame.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

namespace rkpm::io {

CellBlock vertex_cells(std::size_t n_points) {
  CellBlock block;
  block.types.assign(n_points, static_cast<std::uint8_t>(CellType::vertex));
  block.offsets.resize(n_points + 1);
  block.connectivity.resize(n_points);
  for (std::size_t i = 0; i < n_points; ++i) {
    block.offsets[i] = static_cast<std::int64_t>(i);
    block.connectivity[i] = static_cast<std::int64_t>(i);
  }
  block.offsets[n_points] = static_cast<std::int64_t>(n_points);
  return block;
}

namespace {

void validate_points(const std::vector<Vec3>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int d = 0; d < 3; ++d) {
      if (!std::isfinite(points[i][d])) {
        throw NonFiniteValue(fmt::format("output frame: point position of particle {} has non-finite component {} = {}",
                                         i, d, points[i][d]));
      }
    }
  }
}

void validate_cells(const CellBlock& cells, std::size_t n_points) {
  const std::size_t n_cells = cells.types.size();
  if (cells.offsets.size() != n_cells + 1 || cells.offsets.front() != 0) {
    throw FrameError(fmt::format("output frame: cell offsets must have n_cells + 1 = {} entries starting at 0, got {} entries",
                                 n_cells + 1, cells.offsets.size()));
  }
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (cells.offsets[c + 1] < cells.offsets[c]) {
      throw FrameError(fmt::format("output frame: cell offsets decrease at cell {} ({} -> {})", c, cells.offsets[c],
                                   cells.offsets[c + 1]));
    }
  }
  if (static_cast<std::size_t>(cells.offsets.back()) != cells.connectivity.size()) {
    throw FrameError(fmt::format("output frame: last cell offset {} does not match connectivity size {}",
                                 cells.offsets.back(), cells.connectivity.size()));
  }
  for (std::size_t k = 0; k < cells.connectivity.size(); ++k) {
    const std::int64_t p = cells.connectivity[k];
    if (p < 0 || static_cast<std::size_t>(p) >= n_points) {
      throw FrameError(fmt::format("output frame: cell connectivity entry {} = {} is outside [0, {})", k, p, n_points));
    }
  }
}

// `tuple_word` names what one tuple is ("particle" for point fields) so the
// message points straight at the offending particle.
void validate_field(const PointField& field, const char* kind, const char* tuple_word, std::size_t expected_tuples) {
  if (field.name.empty()) throw FrameError(fmt::format("output frame: a {} has an empty name", kind));
  if (field.components <= 0) {
    throw FrameError(fmt::format("output frame: {} '{}' has {} components, expected a positive count", kind, field.name,
                                 field.components));
  }
  const auto nc = static_cast<std::size_t>(field.components);
  if (field.values.size() % nc != 0) {
    throw FrameError(fmt::format("output frame: {} '{}' has {} values, not a multiple of its {} components", kind,
                                 field.name, field.values.size(), nc));
  }
  if (expected_tuples != 0 && field.values.size() != expected_tuples * nc) {
    throw FrameError(fmt::format("output frame: {} '{}' has {} values, expected {} points x {} components = {}", kind,
                                 field.name, field.values.size(), expected_tuples, nc, expected_tuples * nc));
  }
  for (std::size_t k = 0; k < field.values.size(); ++k) {
    if (!std::isfinite(field.values[k])) {
      throw NonFiniteValue(fmt::format("output frame: {} '{}' of {} {} (component {}) is {}", kind, field.name,
                                       tuple_word, k / nc, k % nc, field.values[k]));
    }
  }
}

void validate_unique_names(const std::vector<PointField>& fields, const char* kind) {
  std::set<std::string> seen;
  for (const PointField& f : fields) {
    if (!seen.insert(f.name).second) throw FrameError(fmt::format("output frame: {} name '{}' appears twice", kind, f.name));
  }
}

}  // namespace

void validate_frame(const Frame& frame) {
  if (frame.points == nullptr) throw FrameError("output frame: no point positions given");
  const std::vector<Vec3>& points = *frame.points;
  validate_points(points);
  validate_cells(frame.cells, points.size());
  for (const PointField& f : frame.point_fields) {
    // A point field must have exactly one tuple per point, even for an empty cloud.
    if (points.empty() && !f.values.empty()) {
      throw FrameError(fmt::format("output frame: point field '{}' has {} values but the frame has no points", f.name,
                                   f.values.size()));
    }
    validate_field(f, "point field", "particle", points.size());
  }
  for (const PointField& f : frame.field_data) validate_field(f, "field-data array", "tuple", 0);
  if (!frame.duplicate_points.empty() && frame.duplicate_points.size() != points.size())
    throw FrameError(fmt::format("output frame: {} duplicate-point flags for {} points", frame.duplicate_points.size(),
                                 points.size()));
  validate_unique_names(frame.point_fields, "point field");
  validate_unique_names(frame.field_data, "field-data array");
}

}  // namespace rkpm::io
