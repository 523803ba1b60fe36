#include "rkpm/rk/nodal_integration.hpp"

#include "rkpm/particles/cloud.hpp"
#include "rkpm/particles/dual_cells.hpp"
#include "rkpm/rk/row_scatter.hpp"

#include <fmt/format.h>

#if defined(__GLIBC__)
#include <malloc.h>  // malloc_trim
#endif

#include <array>
#include <cstring>
#include <functional>
#include <tuple>
#include <omp.h>

#include <algorithm>
#include <limits>
#include <string>
#include <unordered_map>

namespace rkpm::rk {

namespace {

// Collects the first failure (lowest particle id) of a parallel loop, so the
// message does not depend on thread scheduling; exceptions must not cross the
// OpenMP region.
class FirstError {
 public:
  void record(Index particle, std::string message) {
#pragma omp critical(rkpm_first_error)
    if (particle < particle_) {
      particle_ = particle;
      message_ = std::move(message);
    }
  }
  void rethrow() const {
    if (failed()) throw ApproximationError(message_);
  }
  bool failed() const { return particle_ != std::numeric_limits<Index>::max(); }
  Index particle() const { return particle_; }

 private:
  Index particle_ = std::numeric_limits<Index>::max();
  std::string message_;
};

// Mixes the bits of a point's three coordinates into a hash.
template <class Bits>
std::size_t hash_bits(const Bits& b) {
  const std::uint64_t h = (b[0] * 0x9E3779B97F4A7C15ull) ^ (b[1] * 0xBF58476D1CE4E5B9ull) ^ (b[2] * 0x94D049BB133111EBull);
  return static_cast<std::size_t>(h ^ (h >> 29));
}

// Per-thread dense accumulator over particles with the list of touched ids.
struct RowAccumulator {
  std::vector<Vec3> value;
  std::vector<char> used;
  std::vector<Index> touched;
  explicit RowAccumulator(std::size_t n) : value(n, Vec3::Zero()), used(n, 0) {}
  void add(Index i, const Vec3& v) {
    if (!used[i]) {
      used[i] = 1;
      touched.push_back(i);
    }
    value[i] += v;
  }
  // Appends the row (sorted by particle id) to col/grad in the storage's precision,
  // resets the touched slots and returns the row's length.
  template <class Stored>
  Index flush(double scale, std::vector<Index>& col, std::vector<Stored>& grad) {
    std::sort(touched.begin(), touched.end());
    for (Index i : touched) {
      col.push_back(i);
      grad.push_back((value[i] * scale).template cast<typename Stored::Scalar>());
      value[i].setZero();
      used[i] = 0;
    }
    const auto length = static_cast<Index>(touched.size());
    touched.clear();
    return length;
  }
  void discard() {
    for (Index i : touched) {
      value[i].setZero();
      used[i] = 0;
    }
    touched.clear();
  }
};

// Shape-function values at the quadrature points of a block of smoothing cells. Cells
// share points (a centroid rule's facet with the cell across it, a corner rule's edge
// midpoints, face and element centroids with up to eight cells): the first cell of the
// block to need a point evaluates it, the others read it. A point is named by its
// coordinates' bits: DualCells forms each facet point and corner in one order whichever
// cell asks, so a shared point has the same bits everywhere (and two points with the
// same coordinates have the same values anyway). Both cells of a shared facet then use
// the very same values, so its contributions cancel exactly in the integration
// constraint. Cleared per block: what is shared depends on the fixed block split alone,
// not on the thread count.
class BlockPointValues {
 public:
  void clear() {
    where_.clear();
    ids_.clear();
    psi_.clear();
  }
  // The range [begin, begin + length) of the stored values at x, evaluated from
  // candidates() (a callable returning the CandidateSet) if not stored yet; false if the
  // approximation cannot be evaluated there.
  template <class Candidates>
  bool find_or_evaluate(const RKApproximation& rk, const Vec3& x, const Candidates& candidates, ShapeValues& sv,
                        std::size_t& begin, std::size_t& length) {
    const Key key = key_of(x);
    const auto it = where_.find(key);
    if (it != where_.end()) {
      std::tie(begin, length) = it->second;
      return true;
    }
    if (!rk.evaluate_among(x, candidates(), sv, false)) return false;
    begin = ids_.size();
    length = sv.ids.size();
    ids_.insert(ids_.end(), sv.ids.begin(), sv.ids.end());
    psi_.insert(psi_.end(), sv.psi.begin(), sv.psi.end());
    where_.emplace(key, std::make_pair(begin, length));
    return true;
  }
  Index id(std::size_t k) const { return ids_[k]; }
  double psi(std::size_t k) const { return psi_[k]; }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const { return hash_bits(k); }
  };
  static Key key_of(const Vec3& x) {
    Key k;
    std::memcpy(k.data(), x.data(), sizeof k);
    return k;
  }
  std::unordered_map<Key, std::pair<std::size_t, std::size_t>, KeyHash> where_;
  std::vector<Index> ids_;
  std::vector<double> psi_;
};

// A smoothing cell's boundary integral of Psi_I n dA (or of a part of its boundary) as a
// weighted sum over distinct points, sum_k Psi_I(p_k) w_k, by one of two rules on each
// planar triangle of the cell surface (both exact for linear functions, so the patch
// test holds either way):
//   centroids: Psi at the centroid times the area vector (one point per triangle, about
//     48 per interior cell of a hexahedral mesh, each shared with one other cell);
//   corners: Psi at each corner times a third of the area vector. The corners are the
//     particle, edge midpoints, face and element centroids, shared by up to eight cells:
//     about 7 evaluations per particle instead of 24. An open-addressing table on the
//     corners' bits merges a cell's repeated corners (some 150 for a few dozen points).
// Each point carries a tag (the named surfaces of a boundary piece); points are merged
// only with points of the same tag.
class CellQuadrature {
 public:
  std::vector<Vec3> point, weight;
  std::vector<std::uint32_t> tag;

  // The facets for which tag_of(f) >= 0, tagged with that value.
  template <class TagOf>
  void collect(const std::vector<particles::DualFacet>& facets, FacetRule rule, TagOf tag_of) {
    point.clear();
    weight.clear();
    tag.clear();
    if (rule == FacetRule::Centroids) {
      for (const auto& f : facets) {
        const std::int64_t t = tag_of(f);
        if (t < 0) continue;
        point.push_back(f.point);
        weight.push_back(f.area);
        tag.push_back(static_cast<std::uint32_t>(t));
      }
      return;
    }
    const std::size_t needed = 2 * 3 * facets.size();
    if (slot_.size() < needed) {
      std::size_t size = 64;
      while (size < needed) size *= 2;  // a power of two: the probe wraps with a mask
      slot_.assign(size, kEmpty);
    }
    const std::size_t mask = slot_.size() - 1;
    for (const auto& f : facets) {
      const std::int64_t t = tag_of(f);
      if (t < 0) continue;
      const auto f_tag = static_cast<std::uint32_t>(t);
      const Vec3 third = f.area / 3.0;
      for (const Vec3& c : f.corner) {
        std::uint64_t bits[3];
        std::memcpy(bits, c.data(), sizeof bits);
        bits[0] ^= f_tag;
        std::size_t s = hash_bits(bits) & mask;
        while (slot_[s] != kEmpty && (point[slot_[s]] != c || tag[slot_[s]] != f_tag)) s = (s + 1) & mask;
        if (slot_[s] == kEmpty) {
          slot_[s] = static_cast<std::uint32_t>(point.size());
          used_.push_back(s);
          point.push_back(c);
          weight.push_back(Vec3::Zero());
          tag.push_back(f_tag);
        }
        weight[slot_[s]] += third;
      }
    }
    for (const std::size_t s : used_) slot_[s] = kEmpty;
    used_.clear();
  }

 private:
  static constexpr std::uint32_t kEmpty = ~0u;
  std::vector<std::uint32_t> slot_;
  std::vector<std::size_t> used_;
};

// Every facet of a smoothing cell, untagged: the whole closed surface.
std::int64_t whole_cell(const particles::DualFacet&) { return 0; }

// The named surfaces a boundary face lies on: those all its nodes share (a particle on a
// block edge is on two faces, a face on one).
std::uint32_t face_surfaces(const particles::Cloud& cloud, std::int32_t face) {
  if (cloud.surface_mask.empty() || face < 0) return 0u;
  const auto& bf = cloud.boundary_faces[face];
  std::uint32_t mask = ~0u;
  for (int k = 0; k < bf.n_nodes; ++k) mask &= cloud.surface_mask[bf.nodes[k]];
  return mask;
}

std::string particle_label(const particles::Cloud& cloud, Index i) {
  return fmt::format("cloud '{}', particle {}", cloud.name, i);
}

// CSR rows of a block of consecutive points, built by one thread.
template <class Value>
struct CsrPiece {
  std::vector<Index> length, col;
  std::vector<Value> value;
};

// Returns the pages of freed blocks to the operating system. glibc keeps a freed
// block that is not at the top of its heap resident, so without this the pieces joined
// so far would stay in the process's memory beside the matrix they were copied into.
void release_freed_pages() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

// Appends a piece's values as they are: one per entry.
template <class Value>
void append_values(const CsrPiece<Value>& piece, std::vector<Value>& out) {
  out.insert(out.end(), piece.value.begin(), piece.value.end());
}

// Appends a piece of single-precision gradients in GradientOperator::grad_float's
// planar order: each row's x components, then its y, then its z.
void append_values(const CsrPiece<Vec3f>& piece, std::vector<float>& out) {
  static_assert(sizeof(Vec3f) == 3 * sizeof(float), "three floats per entry, no padding");
  std::size_t k0 = 0;
  for (const Index len : piece.length) {
    const auto n = static_cast<std::size_t>(len);
    for (int c = 0; c < 3; ++c)
      for (std::size_t m = 0; m < n; ++m) out.push_back(piece.value[k0 + m](c));
    k0 += n;
  }
}

// Joins the pieces in block order into one CSR matrix, freeing each as it goes and
// returning the freed pages every few pieces, so a build's peak is about one copy of
// the matrix (the pieces, then the matrix as it fills) rather than two: the allocator
// keeps freed blocks in the middle of its heap resident unless told to return them
// (docs/verification/performance.md measures the peak). `value` takes
// each entry as it is, or (single-precision gradients) as three planar floats.
template <class Value, class Out>
void join(std::vector<CsrPiece<Value>>& pieces, std::vector<Index>& row_offset, std::vector<Index>& col,
          std::vector<Out>& value) {
  constexpr std::size_t kPiecesPerRelease = 64;
  constexpr std::size_t kStoredPerEntry = sizeof(Value) / sizeof(Out);
  std::size_t rows = 0, entries = 0;
  for (const auto& piece : pieces) {
    rows += piece.length.size();
    entries += piece.col.size();
  }
  row_offset.assign(rows + 1, 0);
  col.reserve(entries);
  value.reserve(entries * kStoredPerEntry);
  std::size_t r = 0, joined = 0;
  for (auto& piece : pieces) {
    for (const Index len : piece.length) {
      row_offset[r + 1] = row_offset[r] + len;
      ++r;
    }
    col.insert(col.end(), piece.col.begin(), piece.col.end());
    append_values(piece, value);
    piece = CsrPiece<Value>{};
    if (++joined % kPiecesPerRelease == 0) release_freed_pages();
  }
  release_freed_pages();
}

// Psi_I at each of `points` (in parallel), stored row by row in CSR form: the shape of
// the boundary quadrature and of the nodal interpolation. A point the approximation
// cannot handle is diagnosed serially afterwards, named by label(p).
// The points are taken in fixed blocks, each filling a CSR piece of its own with a
// per-thread scratch; the pieces are joined in block order (the result does not
// depend on the threads) and freed as they are joined, so the build holds little
// beyond the result. (Keeping a ShapeValues per point, with its neighbour-query
// buffer, held several times the result's memory.)
// `owner` (optional): the points lie in the cells of these particles, a cell's points
// consecutive (the boundary quadrature). Then one neighbour query around the owner
// serves all its points, and a point repeated in a block (a corner two cells share) is
// evaluated once.
// Value: double, or float for storage in single precision (the rows are evaluated in
// double and rounded as they are stored).
template <class Value>
void shape_function_rows(const RKApproximation& rk, const std::vector<Vec3>& points, std::vector<Index>& row_offset,
                         std::vector<Index>& col, std::vector<Value>& psi,
                         const std::function<std::string(std::size_t)>& label, const std::vector<char>& rows = {},
                         const std::vector<Index>& owner = {}) {
  const auto selected = [&](std::size_t p) { return rows.empty() || rows[p] != 0; };
  constexpr std::size_t block = 512;
  const std::size_t m = points.size();
  const std::size_t n_blocks = (m + block - 1) / block;
  const std::vector<Vec3>& X = rk.points();
  std::vector<CsrPiece<Value>> pieces(n_blocks);
  FirstError error;
#pragma omp parallel
  {
    ShapeValues values;
    BlockPointValues stored;
    CandidateSet near_owner;
#pragma omp for schedule(dynamic, 1)
    for (std::size_t b = 0; b < n_blocks; ++b) {
      auto& piece = pieces[b];
      const std::size_t end = std::min(m, (b + 1) * block);
      stored.clear();
      std::size_t group_end = b * block;  // the current owner's points end here
      for (std::size_t p = b * block; p < end; ++p) {
        if (!selected(p)) {
          piece.length.push_back(0);
          continue;
        }
        if (owner.empty()) {
          if (!rk.evaluate(points[p], values, false)) {
            error.record(static_cast<Index>(p), "");
            break;
          }
          piece.length.push_back(static_cast<Index>(values.ids.size()));
          piece.col.insert(piece.col.end(), values.ids.begin(), values.ids.end());
          piece.value.insert(piece.value.end(), values.psi.begin(), values.psi.end());
          continue;
        }
        bool have_candidates = p < group_end;
        const Vec3& centre = X[static_cast<std::size_t>(owner[p])];
        const auto owner_candidates = [&]() -> const CandidateSet& {
          if (!have_candidates) {
            for (group_end = p; group_end < end && owner[group_end] == owner[p];) ++group_end;
            rk.candidates(centre, points.data() + p, group_end - p, near_owner);
            have_candidates = true;
          }
          return near_owner;
        };
        std::size_t begin = 0, length = 0;
        if (!stored.find_or_evaluate(rk, points[p], owner_candidates, values, begin, length)) {
          error.record(static_cast<Index>(p), "");
          break;
        }
        piece.length.push_back(static_cast<Index>(length));
        for (std::size_t k = begin; k < begin + length; ++k) {
          piece.col.push_back(stored.id(k));
          piece.value.push_back(static_cast<Value>(stored.psi(k)));
        }
      }
    }
  }
  try {
    error.rethrow();
  } catch (const ApproximationError&) {
    ShapeValues values;
    for (std::size_t p = 0; p < m; ++p)
      if (selected(p)) rk.evaluate_or_throw(points[p], values, false, label(p));
  }
  join(pieces, row_offset, col, psi);
}

}  // namespace

void CsrTranspose::build(const std::vector<Index>& row_offset, const std::vector<Index>& col, Index n_columns) {
  offset.assign(n_columns + 1, 0);
  for (Index i : col) ++offset[i + 1];
  for (Index i = 0; i < n_columns; ++i) offset[i + 1] += offset[i];
  entry.resize(col.size());
  row.resize(col.size());
  std::vector<Index> fill(offset.begin(), offset.end() - 1);
  const auto n_rows = static_cast<Index>(row_offset.size()) - 1;
  for (Index r = 0; r < n_rows; ++r)
    for (Index k = row_offset[r]; k < row_offset[r + 1]; ++k) {
      const Index slot = fill[col[k]]++;
      entry[slot] = k;
      row[slot] = r;
    }
}

namespace {

// The smoothed gradients of every row, built as `Stored` (Vec3 or Vec3f) and joined
// into `grad` (op.grad, or op.grad_float in its planar order); each block's piece is
// converted as it is filled, so the build never holds a double copy of a
// single-precision operator.
template <class Stored, class Out>
void build_gradient_rows(const particles::Cloud& cloud, const RKApproximation& rk, Integration scheme, FacetRule rule,
                         const std::vector<char>& rows, GradientOperator& op, std::vector<Out>& grad) {
  const auto n = static_cast<Index>(cloud.size());
  constexpr Index block = 1024;
  const Index n_blocks = (n + block - 1) / block;
  std::vector<CsrPiece<Stored>> pieces(static_cast<std::size_t>(n_blocks));
  std::vector<double> weight(n, 0.0);
  FirstError error;
  const particles::DualCells cells(cloud);

#pragma omp parallel
  {
    ShapeValues sv;
    std::vector<particles::DualFacet> facets;
    CellQuadrature quadrature;
    CandidateSet near_cell;
    BlockPointValues values;
    RowAccumulator acc(n);
#pragma omp for schedule(dynamic, 1)
    for (Index b = 0; b < n_blocks; ++b) {
      auto& piece = pieces[static_cast<std::size_t>(b)];
      values.clear();
      for (Index L = b * block; L < std::min(n, (b + 1) * block); ++L) {
        if (!rows.empty() && rows[static_cast<std::size_t>(L)] == 0) {
          piece.length.push_back(0);  // another rank's point
          continue;
        }
        const Vec3& XL = cloud.X[L];
        if (scheme == Integration::Direct) {
          if (!rk.evaluate(XL, sv, true)) {
            error.record(L, "");  // message filled below, outside the hot path
            break;
          }
          piece.length.push_back(static_cast<Index>(sv.ids.size()));
          piece.col.insert(piece.col.end(), sv.ids.begin(), sv.ids.end());
          for (const Vec3& g : sv.grad) piece.value.push_back(g.template cast<typename Stored::Scalar>());
          weight[L] = cloud.volume[L];
          continue;
        }
        cells.facets(L, facets);
        quadrature.collect(facets, rule, whole_cell);
        double volume = 0.0;
        for (const auto& f : facets) volume += f.point.dot(f.area) / 3.0;  // divergence theorem: exact, closed cell
        // One candidate query for the whole cell (around its points), and only
        // if one of its points is not stored yet.
        bool have_candidates = false;
        const auto cell_candidates = [&]() -> const CandidateSet& {
          if (!have_candidates) {
            rk.candidates(XL, quadrature.point.data(), quadrature.point.size(), near_cell);
            have_candidates = true;
          }
          return near_cell;
        };
        bool ok = volume > 0.0;
        for (std::size_t q = 0; ok && q < quadrature.point.size(); ++q) {
          std::size_t begin = 0, length = 0;
          ok = values.find_or_evaluate(rk, quadrature.point[q], cell_candidates, sv, begin, length);
          for (std::size_t k = begin; ok && k < begin + length; ++k)
            acc.add(values.id(k), values.psi(k) * quadrature.weight[q]);
        }
        if (!ok) {
          acc.discard();
          error.record(L, "");
          break;
        }
        piece.length.push_back(acc.flush(1.0 / volume, piece.col, piece.value));
        weight[L] = volume;
      }
    }
  }
  if (error.failed()) {
    // Re-run the first failing particle serially to produce the full diagnosis.
    const Index L = error.particle();
    ShapeValues sv;
    const std::string what = particle_label(cloud, L);
    if (scheme == Integration::Direct) rk.evaluate_or_throw(cloud.X[L], sv, true, what);
    std::vector<particles::DualFacet> facets;
    cells.facets(L, facets);
    CellQuadrature quadrature;
    quadrature.collect(facets, rule, whole_cell);
    for (const Vec3& p : quadrature.point)
      rk.evaluate_or_throw(p, sv, false, what + " (a quadrature point on its smoothing-cell boundary)");
    throw ApproximationError(fmt::format("{}: its smoothing cell has no positive volume", what));
  }
  join(pieces, op.row_offset, op.col, grad);
  op.weight = std::move(weight);
  op.n_columns = n;
}

}  // namespace

GradientOperator build_gradient_operator(const particles::Cloud& cloud, const RKApproximation& rk,
                                         Integration scheme, GradientPrecision precision,
                                         const std::vector<char>& rows, FacetRule rule) {
  GradientOperator op;
  if (precision == GradientPrecision::Float)
    build_gradient_rows<Vec3f>(cloud, rk, scheme, rule, rows, op, op.grad_float);
  else
    build_gradient_rows<Vec3>(cloud, rk, scheme, rule, rows, op, op.grad);
  return op;
}

BoundaryQuadrature build_boundary_quadrature(const particles::Cloud& cloud, const RKApproximation& rk,
                                             std::uint32_t surface_bits, FacetRule rule) {
  const particles::DualCells cells(cloud);
  return build_boundary_quadrature(cloud, cells, rk, surface_bits, 0, cloud.boundary_particles.size(), rule);
}

BoundaryQuadrature build_boundary_quadrature(const particles::Cloud& cloud, const particles::DualCells& cells,
                                             const RKApproximation& rk, std::uint32_t surface_bits,
                                             std::size_t first, std::size_t last, FacetRule rule) {
  BoundaryQuadrature q;
  std::vector<particles::DualFacet> facets;
  CellQuadrature quadrature;
  // The boundary pieces on the chosen surfaces, tagged with the surfaces they lie on.
  const auto chosen = [&](const particles::DualFacet& f) -> std::int64_t {
    if (!f.on_boundary) return -1;
    const std::uint32_t surfaces = face_surfaces(cloud, f.face);
    return surface_bits == 0u || (surfaces & surface_bits) ? std::int64_t{surfaces} : -1;
  };
  last = std::min(last, cloud.boundary_particles.size());
  for (std::size_t b = first; b < last; ++b) {
    const Index L = cloud.boundary_particles[b];
    cells.facets(L, facets);
    quadrature.collect(facets, rule, chosen);
    q.point.insert(q.point.end(), quadrature.point.begin(), quadrature.point.end());
    q.area.insert(q.area.end(), quadrature.weight.begin(), quadrature.weight.end());
    q.owner.insert(q.owner.end(), quadrature.point.size(), L);
    q.surface_mask.insert(q.surface_mask.end(), quadrature.tag.begin(), quadrature.tag.end());
  }
  shape_function_rows(
      rk, q.point, q.row_offset, q.col, q.psi,
      [&](std::size_t p) { return particle_label(cloud, q.owner[p]) + " (a boundary quadrature point)"; }, {},
      q.owner);
  return q;
}

NodalInterpolation build_nodal_interpolation(const particles::Cloud& cloud, const RKApproximation& rk,
                                             const std::vector<char>& rows) {
  NodalInterpolation interp;
  shape_function_rows(
      rk, cloud.X, interp.row_offset, interp.col, interp.psi,
      [&](std::size_t j) { return particle_label(cloud, static_cast<Index>(j)); }, rows);
  return interp;
}

void deformation_gradients(const GradientOperator& op, const std::vector<Vec3>& x, std::vector<Mat3>& F) {
  const Index n = op.n_rows();
  F.resize(n);
#pragma omp parallel for schedule(static)
  for (Index L = 0; L < n; ++L) F[L] = row_gradient(op, x, L);
}

void internal_forces(const GradientOperator& op, const std::vector<Mat3>& P, std::vector<Vec3>& f) {
  const int threads = RowScatter::team_threads();
  RowScatter scatter;
  scatter.plan(op.n_rows(), op.n_columns, {{&op.row_offset, &op.col}}, threads, 1);
  f.resize(static_cast<std::size_t>(op.n_columns));
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    scatter.clear(t);
    Vec3* sum = scatter.buffer(t, 0);
    for (Index L = scatter.row_begin(t); L < scatter.row_end(t); ++L) scatter_row(op, L, op.weight[L], P[L], sum);
#pragma omp barrier
    scatter.reduce(t, 0, 1.0, f);
  }
}

}  // namespace rkpm::rk
