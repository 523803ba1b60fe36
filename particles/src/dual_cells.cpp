#include "rkpm/particles/dual_cells.hpp"

#include "element_topology.hpp"
#include "small_sort.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>

namespace rkpm::particles {
namespace {

// Centroid of a face from its global node ids in increasing order, so both
// elements sharing the face (and every particle asking) get the same bits.
Vec3 face_centroid(const std::vector<Vec3>& X, const std::int32_t* ids, int n) {
  std::array<std::int32_t, 4> sorted{};
  std::copy(ids, ids + n, sorted.begin());
  detail::sort_small(sorted.data(), n);
  Vec3 c = X[sorted[0]];
  for (int k = 1; k < n; ++k) c += X[sorted[k]];
  return c / static_cast<double>(n);
}

// Triangle (p0, p1, p2) with its centroid and area vector; `sign` = -1 flips it for
// the cell on the other side without changing a single bit of its geometry.
// `face` is the boundary face a boundary piece lies on, -1 for interior facets.
void add_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2, double sign, std::int32_t face,
                  std::vector<DualFacet>& out) {
  const Vec3 point = (p0 + p1 + p2) / 3.0;
  const Vec3 area = 0.5 * (p1 - p0).cross(p2 - p0);
  out.push_back({point, sign * area, {p0, p1, p2}, face >= 0, face});
}

// CSR from (key, value) pairs in value order; keys in [0, n_keys).
template <class ForEachPair>
void build_csr(int n_keys, ForEachPair for_each_pair, std::vector<std::int32_t>& offset,
               std::vector<std::int32_t>& values) {
  offset.assign(n_keys + 1, 0);
  for_each_pair([&](std::int32_t key, std::int32_t) { ++offset[key + 1]; });
  for (int k = 0; k < n_keys; ++k) offset[k + 1] += offset[k];
  values.resize(offset[n_keys]);
  std::vector<std::int32_t> fill(offset.begin(), offset.end() - 1);
  for_each_pair([&](std::int32_t key, std::int32_t value) { values[fill[key]++] = value; });
}

}  // namespace

DualCells::DualCells(const Cloud& cloud) : cloud_(cloud) {
  const int n = static_cast<int>(cloud.size());
  const Mesh& mesh = cloud.mesh;
  build_csr(
      n,
      [&](auto&& emit) {
        for (int e = 0; e < mesh.n_elements(); ++e) {
          for (int k = 0; k < mesh.element_size(e); ++k) emit(mesh.element_nodes(e)[k], e);
        }
      },
      element_offset_, elements_);
  build_csr(
      n,
      [&](auto&& emit) {
        for (int f = 0; f < static_cast<int>(cloud.boundary_faces.size()); ++f) {
          const BoundaryFace& face = cloud.boundary_faces[f];
          for (int k = 0; k < face.n_nodes; ++k) emit(face.nodes[k], f);
        }
      },
      bface_offset_, bfaces_);
}

void DualCells::facets(std::int32_t particle, std::vector<DualFacet>& out) const {
  out.clear();
  const std::vector<Vec3>& X = cloud_.X;
  for (int k = element_offset_[particle]; k < element_offset_[particle + 1]; ++k) {
    const int e = elements_[k];
    const std::int32_t* nodes = cloud_.mesh.element_nodes(e);
    const auto& topo = detail::topology(cloud_.mesh.type[e]);
    const int local = static_cast<int>(std::find(nodes, nodes + topo.n_nodes, particle) - nodes);

    // Element centroid summed in element order: identical for every node of e.
    Vec3 centre = X[nodes[0]];
    for (int a = 1; a < topo.n_nodes; ++a) centre += X[nodes[a]];
    centre /= static_cast<double>(topo.n_nodes);

    // Each face around the particle serves two of its edges: compute it once.
    std::array<Vec3, 6> face_centre;
    std::array<bool, 6> have_face_centre{};
    auto centroid_of = [&](int face) -> const Vec3& {
      if (!have_face_centre[face]) {
        const detail::LocalFace& f = topo.faces[face];
        std::array<std::int32_t, 4> ids{};
        for (int a = 0; a < f.n_nodes; ++a) ids[a] = nodes[f.nodes[a]];
        face_centre[face] = face_centroid(X, ids.data(), f.n_nodes);
        have_face_centre[face] = true;
      }
      return face_centre[face];
    };
    for (const int edge_index : topo.edges_of_node[local]) {
      const detail::LocalEdge& edge = topo.edges[edge_index];
      const Vec3 mid = 0.5 * (X[nodes[edge.first]] + X[nodes[edge.second]]);
      const Vec3& ca = centroid_of(edge.face_a);
      const Vec3& cb = centroid_of(edge.face_b);
      // The topology orients the facet from edge.first to edge.second.
      const double sign = local == edge.first ? 1.0 : -1.0;
      add_triangle(mid, ca, centre, sign, -1, out);
      add_triangle(mid, centre, cb, sign, -1, out);
    }
  }

  for (int k = bface_offset_[particle]; k < bface_offset_[particle + 1]; ++k) {
    const std::int32_t face_index = bfaces_[k];
    const BoundaryFace& face = cloud_.boundary_faces[face_index];
    const int m = face.n_nodes;
    const int at = static_cast<int>(std::find(face.nodes, face.nodes + m, particle) - face.nodes);
    const Vec3& a = X[particle];
    const Vec3 mid_next = 0.5 * (a + X[face.nodes[(at + 1) % m]]);
    const Vec3 mid_prev = 0.5 * (X[face.nodes[(at + m - 1) % m]] + a);
    const Vec3 centre = face_centroid(X, face.nodes, m);
    add_triangle(a, mid_next, centre, 1.0, face_index, out);
    add_triangle(a, centre, mid_prev, 1.0, face_index, out);
  }
}

double DualCells::volume(std::int32_t particle, std::vector<DualFacet>& scratch) const {
  facets(particle, scratch);
  // Divergence theorem about the particle itself: the surface is closed, so the
  // origin is arbitrary, and a local one avoids cancellation far from zero.
  const Vec3& origin = cloud_.X[particle];
  double sum = 0.0;
  for (const DualFacet& f : scratch) sum += (f.point - origin).dot(f.area);
  return sum / 3.0;
}

}  // namespace rkpm::particles
