// finalize_cloud: checks a cloud's mesh and derives everything the simulator needs
// from it (boundary faces, median-dual volumes, boundary normals and areas).
#include "rkpm/particles/cloud.hpp"
#include "rkpm/particles/dual_cells.hpp"
#include "rkpm/particles/element_geometry.hpp"

#include "element_topology.hpp"
#include "small_sort.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>

namespace rkpm::particles {
namespace {

[[noreturn]] void fail(const Cloud& cloud, const std::string& what) {
  throw CloudError("particle cloud '" + cloud.name + "': " + what);
}

std::string element_label(const Cloud& cloud, int e) {
  return "element " + std::to_string(e) +
         (cloud.mesh.type[e] == ElementType::Tet4 ? " (Tet4)" : " (Hex8)");
}

void check_connectivity(const Cloud& cloud) {
  const Mesh& mesh = cloud.mesh;
  const auto n = static_cast<std::int64_t>(cloud.size());
  if (n == 0) fail(cloud, "has no particles");
  if (mesh.n_elements() == 0) fail(cloud, "has no elements");
  if (static_cast<int>(mesh.offset.size()) != mesh.n_elements() + 1 || mesh.offset.front() != 0 ||
      mesh.offset.back() != static_cast<std::int32_t>(mesh.nodes.size())) {
    fail(cloud, "mesh offsets do not match its element and node arrays");
  }
  std::vector<char> used(n, 0);
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (mesh.element_size(e) != nodes_per_element(mesh.type[e])) {
      fail(cloud, element_label(cloud, e) + " has " + std::to_string(mesh.element_size(e)) + " nodes");
    }
    for (int k = 0; k < mesh.element_size(e); ++k) {
      const std::int32_t id = mesh.element_nodes(e)[k];
      if (id < 0 || id >= n) {
        fail(cloud, element_label(cloud, e) + " refers to particle " + std::to_string(id) +
                        ", expected an id in [0, " + std::to_string(n) + ")");
      }
      used[id] = 1;
    }
  }
  const auto unused = std::find(used.begin(), used.end(), 0);
  if (unused != used.end()) {
    fail(cloud, "particle " + std::to_string(unused - used.begin()) + " belongs to no element");
  }
}

void check_elements(const Cloud& cloud) {
  for (int e = 0; e < cloud.mesh.n_elements(); ++e) {
    const double q = element_min_scaled_jacobian(cloud, e);
    if (!(q > 0.0)) {
      std::ostringstream msg;
      msg << element_label(cloud, e) << " is inverted or degenerate (min scaled corner Jacobian " << q
          << ", volume " << element_volume(cloud, e) << ")";
      fail(cloud, msg.str());
    }
  }
}

// Two particles closer than 1e-9 of the bounding-box diagonal are duplicates:
// they would split one physical point between two dual cells.
//
// Such a pair lies in one cluster of every coordinate, a cluster being a run of the
// particles sorted by that coordinate with no gap wider than the tolerance. So the
// check splits by x, splits each x-cluster by y and each of those by z, and compares
// pairs only within the last clusters: O(n log n) on a lattice, where a sweep over x
// alone would compare every pair of a lattice plane (whole planes share one x).
void check_duplicates(const Cloud& cloud) {
  const std::vector<Vec3>& X = cloud.X;
  Vec3 lo = X[0], hi = X[0];
  for (const Vec3& x : X) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double tol = 1e-9 * (hi - lo).norm();
  std::vector<std::int32_t> order(X.size());
  std::iota(order.begin(), order.end(), 0);
  const auto split = [&](auto& self, std::size_t begin, std::size_t end, int axis) -> void {
    std::sort(order.begin() + begin, order.begin() + end, [&](std::int32_t a, std::int32_t b) {
      return X[a](axis) < X[b](axis) || (X[a](axis) == X[b](axis) && a < b);
    });
    for (std::size_t first = begin; first < end;) {
      std::size_t last = first + 1;
      while (last < end && X[order[last]](axis) - X[order[last - 1]](axis) <= tol) ++last;
      if (last - first > 1) {
        if (axis < 2) {
          self(self, first, last, axis + 1);
        } else {
          for (std::size_t i = first; i < last; ++i)
            for (std::size_t j = i + 1; j < last; ++j)
              if ((X[order[j]] - X[order[i]]).norm() <= tol) {
                const auto [a, b] = std::minmax(order[i], order[j]);
                fail(cloud, "particles " + std::to_string(a) + " and " + std::to_string(b) + " coincide");
              }
        }
      }
      first = last;
    }
  };
  split(split, 0, order.size(), 0);
}

struct FaceRecord {
  std::array<std::int32_t, 4> key;  // sorted node ids, padded with -1
  std::int32_t element;
  std::int32_t local_face;
};

// Sorts the face records by key, then element: bucketed by the smallest node id (a
// counting sort, linear), then each bucket's few records (the faces at one node) by the
// whole order. The same result as one comparison sort of all of them (six records per
// hexahedron, O(n log n) on the largest array of the cloud's set-up), in linear time;
// docs/verification/performance.md measures the set-up.
void sort_faces(std::vector<FaceRecord>& faces, std::size_t n_particles) {
  const auto before = [](const FaceRecord& a, const FaceRecord& b) {
    return a.key != b.key ? a.key < b.key : a.element < b.element;
  };
  std::vector<std::size_t> start(n_particles + 1, 0);
  for (const FaceRecord& r : faces) ++start[static_cast<std::size_t>(r.key[0]) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<FaceRecord> sorted(faces.size());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const FaceRecord& r : faces) sorted[fill[static_cast<std::size_t>(r.key[0])]++] = r;
  for (std::size_t i = 0; i < n_particles; ++i)
    std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(start[i]),
              sorted.begin() + static_cast<std::ptrdiff_t>(start[i + 1]), before);
  faces = std::move(sorted);
}

// Faces of exactly one element are the body's surface (a conforming mesh shares
// every interior face between two elements).
void find_boundary_faces(Cloud& cloud) {
  const Mesh& mesh = cloud.mesh;
  std::vector<FaceRecord> faces;
  faces.reserve(6 * static_cast<std::size_t>(mesh.n_elements()));
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const auto& topo = detail::topology(mesh.type[e]);
    const std::int32_t* nodes = mesh.element_nodes(e);
    for (int f = 0; f < static_cast<int>(topo.faces.size()); ++f) {
      FaceRecord r{{-1, -1, -1, -1}, e, f};
      for (int k = 0; k < topo.faces[f].n_nodes; ++k) r.key[k] = nodes[topo.faces[f].nodes[k]];
      detail::sort_small(r.key.data(), topo.faces[f].n_nodes);
      faces.push_back(r);
    }
  }
  sort_faces(faces, cloud.size());

  std::vector<FaceRecord> boundary;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j - i > 2) {
      fail(cloud, "a face of " + element_label(cloud, faces[i].element) + " is shared by " +
                      std::to_string(j - i) + " elements (non-manifold mesh)");
    }
    if (j - i == 1) boundary.push_back(faces[i]);
    i = j;
  }
  std::sort(boundary.begin(), boundary.end(), [](const FaceRecord& a, const FaceRecord& b) {
    return a.element != b.element ? a.element < b.element : a.local_face < b.local_face;
  });

  const std::vector<Vec3>& X = cloud.X;
  cloud.boundary_faces.clear();
  for (const FaceRecord& r : boundary) {
    const auto& topo = detail::topology(mesh.type[r.element]);
    const detail::LocalFace& lf = topo.faces[r.local_face];
    const std::int32_t* nodes = mesh.element_nodes(r.element);
    BoundaryFace face;
    face.element = r.element;
    face.n_nodes = lf.n_nodes;
    Vec3 face_centre = Vec3::Zero(), element_centre = Vec3::Zero();
    for (int k = 0; k < lf.n_nodes; ++k) {
      face.nodes[k] = nodes[lf.nodes[k]];
      face_centre += X[face.nodes[k]] / lf.n_nodes;
    }
    for (int k = 0; k < topo.n_nodes; ++k) element_centre += X[nodes[k]] / topo.n_nodes;
    // The local face tables are outward for valid elements; the check against the
    // element centroid keeps that promise even for badly shaped ones.
    Vec3 area = Vec3::Zero();
    for (int k = 0; k < lf.n_nodes; ++k) {
      area += (X[face.nodes[k]] - face_centre).cross(X[face.nodes[(k + 1) % lf.n_nodes]] - face_centre);
    }
    if (area.dot(face_centre - element_centre) < 0.0) std::reverse(face.nodes, face.nodes + lf.n_nodes);
    cloud.boundary_faces.push_back(face);
  }
}

// Volumes and boundary data from the dual cells, so the SCNI cell identities
// (sum of area vectors = 0, integral of x n = V I) hold with exactly these V.
void measure_dual_cells(Cloud& cloud) {
  const int n = static_cast<int>(cloud.size());
  const DualCells cells(cloud);
  cloud.volume.assign(n, 0.0);
  std::vector<Vec3> area_vector(n, Vec3::Zero());
  std::vector<double> area(n, 0.0);
  // Each particle's cell on its own (in parallel); the lists below in particle order.
#pragma omp parallel
  {
    std::vector<DualFacet> facets;
#pragma omp for schedule(static)
    for (std::int32_t i = 0; i < n; ++i) {
      cloud.volume[i] = cells.volume(i, facets);
      for (const DualFacet& f : facets) {
        if (!f.on_boundary) continue;
        area_vector[i] += f.area;
        area[i] += f.area.norm();
      }
    }
  }
  cloud.boundary_particles.clear();
  cloud.boundary_normal.clear();
  cloud.boundary_area.clear();
  cloud.boundary_index.assign(n, -1);
  for (std::int32_t i = 0; i < n; ++i) {
    if (!(cloud.volume[i] > 0.0)) {
      fail(cloud, "the dual cell of particle " + std::to_string(i) + " has non-positive volume " +
                      std::to_string(cloud.volume[i]));
    }
    if (area[i] == 0.0) continue;
    cloud.boundary_index[i] = static_cast<std::int32_t>(cloud.boundary_particles.size());
    cloud.boundary_particles.push_back(i);
    cloud.boundary_normal.push_back(area_vector[i].normalized());
    cloud.boundary_area.push_back(area[i]);
  }
}

}  // namespace

void finalize_cloud(Cloud& cloud) {
  check_connectivity(cloud);
  check_elements(cloud);
  check_duplicates(cloud);
  if (cloud.surface_mask.empty()) cloud.surface_mask.assign(cloud.size(), 0);
  if (cloud.surface_mask.size() != cloud.size()) {
    fail(cloud, "surface_mask has " + std::to_string(cloud.surface_mask.size()) + " entries for " +
                    std::to_string(cloud.size()) + " particles");
  }
  if (cloud.surface_names.size() > 32) fail(cloud, "more than 32 named surfaces");
  find_boundary_faces(cloud);
  measure_dual_cells(cloud);
}

}  // namespace rkpm::particles
