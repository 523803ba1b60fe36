// One output frame, described without reference to the simulator's internals:
// current positions, optional cells, and named per-point fields. The writer
// only ever sees this, so the physics side can change its storage freely.
#pragma once

#include "rkpm/common/types.hpp"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rkpm::io {

// VTK cell type codes used by the project (vtkCellType.h).
enum class CellType : std::uint8_t { vertex = 1, tetra = 10, hexahedron = 12 };

// A named field with `components` values per tuple, stored tuple after tuple.
// 1 = scalar, 3 = vector, 9 = tensor (row-major 3x3; VTK and ParaView treat
// 9-component arrays as tensors and offer eigen-decomposition filters on them).
struct PointField {
  std::string name;
  int components = 1;
  std::vector<double> values;

  std::size_t tuples() const { return components > 0 ? values.size() / static_cast<std::size_t>(components) : 0; }
};

// Cells in compressed-row form, as vtkCellArray stores them: cell c uses
// connectivity[offsets[c] .. offsets[c+1]), so offsets has n_cells + 1 entries
// and starts at 0 (a default-constructed block already holds that 0). An
// empty block (no cells) is allowed.
struct CellBlock {
  std::vector<std::uint8_t> types;
  std::vector<std::int64_t> offsets{0};
  std::vector<std::int64_t> connectivity;

  std::size_t size() const { return types.size(); }
};

struct Frame {
  const std::vector<Vec3>* points = nullptr;  // current positions, not owned
  CellBlock cells;
  std::vector<PointField> point_fields;       // one tuple per point
  std::vector<PointField> field_data;         // global values (any tuple count), e.g. TimeValue
  // A piece of a distributed frame: 1 for each point that is a copy of another piece's
  // (the halo), 0 for the piece's own; empty for a whole frame. Written as VTK's
  // vtkGhostType array (DUPLICATEPOINT), so that ParaView's filters count every
  // particle once over the pieces.
  std::vector<std::uint8_t> duplicate_points;
};

// Any structural problem with a frame: sizes, names, cell indices.
class FrameError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A NaN or infinity about to be written. The caller catches this, keeps its
// last good frame on disk and stops (a blown-up state is never written).
class NonFiniteValue : public FrameError {
 public:
  using FrameError::FrameError;
};

// One VTK_VERTEX cell per point ("points" output mode), so ParaView renders
// particle clouds without a glyph filter.
CellBlock vertex_cells(std::size_t n_points);

// Throws FrameError / NonFiniteValue naming the field, the point index, the
// component and the offending value. Called by every writer before any file
// is touched.
void validate_frame(const Frame& frame);

}  // namespace rkpm::io
