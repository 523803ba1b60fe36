#include "element_topology.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <stdexcept>

namespace rkpm::particles::detail {
namespace {

std::vector<Vec3> reference_nodes(ElementType type) {
  if (type == ElementType::Tet4) return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
          Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
}

// VTK's faces, written so the right-hand rule points out of the element.
std::vector<LocalFace> reference_faces(ElementType type) {
  if (type == ElementType::Tet4) {
    return {{3, {0, 2, 1, -1}}, {3, {0, 1, 3, -1}}, {3, {1, 2, 3, -1}}, {3, {0, 3, 2, -1}}};
  }
  return {{4, {0, 3, 2, 1}}, {4, {4, 5, 6, 7}}, {4, {0, 1, 5, 4}},
          {4, {1, 2, 6, 5}}, {4, {2, 3, 7, 6}}, {4, {3, 0, 4, 7}}};
}

Vec3 face_centroid(const std::vector<Vec3>& x, const LocalFace& f) {
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < f.n_nodes; ++k) c += x[f.nodes[k]];
  return c / f.n_nodes;
}

Vec3 face_area_vector(const std::vector<Vec3>& x, const LocalFace& f) {
  const Vec3 c = face_centroid(x, f);
  Vec3 a = Vec3::Zero();
  for (int k = 0; k < f.n_nodes; ++k) {
    a += 0.5 * (x[f.nodes[k]] - c).cross(x[f.nodes[(k + 1) % f.n_nodes]] - c);
  }
  return a;
}

bool face_has_edge(const LocalFace& f, int a, int b) {
  const auto* end = f.nodes.begin() + f.n_nodes;
  return std::find(f.nodes.begin(), end, a) != end && std::find(f.nodes.begin(), end, b) != end;
}

ElementTopology build(ElementType type) {
  ElementTopology t;
  t.type = type;
  t.n_nodes = nodes_per_element(type);
  t.faces = reference_faces(type);
  const std::vector<Vec3> x = reference_nodes(type);
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : x) centre += p;
  centre /= t.n_nodes;

  for (const LocalFace& f : t.faces) {
    if (face_area_vector(x, f).dot(face_centroid(x, f) - centre) <= 0.0) {
      throw std::logic_error("element topology: a reference face is not oriented outward");
    }
  }

  // Edges: consecutive nodes of a face; every edge lies on exactly two faces.
  for (const LocalFace& f : t.faces) {
    for (int k = 0; k < f.n_nodes; ++k) {
      const int a = std::min(f.nodes[k], f.nodes[(k + 1) % f.n_nodes]);
      const int b = std::max(f.nodes[k], f.nodes[(k + 1) % f.n_nodes]);
      const bool seen = std::any_of(t.edges.begin(), t.edges.end(),
                                    [&](const LocalEdge& e) { return e.first == a && e.second == b; });
      if (seen) continue;
      LocalEdge edge{a, b, -1, -1};
      for (int g = 0; g < static_cast<int>(t.faces.size()); ++g) {
        if (!face_has_edge(t.faces[g], a, b)) continue;
        (edge.face_a < 0 ? edge.face_a : edge.face_b) = g;
      }
      // Order the two faces so the facet normal points from `first` to `second`.
      const Vec3 mid = 0.5 * (x[a] + x[b]);
      const Vec3 ca = face_centroid(x, t.faces[edge.face_a]);
      const Vec3 cb = face_centroid(x, t.faces[edge.face_b]);
      const Vec3 normal = (ca - mid).cross(centre - mid) + (centre - mid).cross(cb - mid);
      if (normal.dot(x[b] - x[a]) < 0.0) std::swap(edge.face_a, edge.face_b);
      t.edges.push_back(edge);
    }
  }

  t.edges_of_node.resize(t.n_nodes);
  t.corner_neighbors.resize(t.n_nodes);
  for (int e = 0; e < static_cast<int>(t.edges.size()); ++e) {
    t.edges_of_node[t.edges[e].first].push_back(e);
    t.edges_of_node[t.edges[e].second].push_back(e);
  }
  for (int n = 0; n < t.n_nodes; ++n) {
    std::array<int, 3>& nb = t.corner_neighbors[n];
    for (int k = 0; k < 3; ++k) {
      const LocalEdge& e = t.edges[t.edges_of_node[n][k]];
      nb[k] = e.first == n ? e.second : e.first;
    }
    const double det = (x[nb[0]] - x[n]).cross(x[nb[1]] - x[n]).dot(x[nb[2]] - x[n]);
    if (det < 0.0) std::swap(nb[1], nb[2]);
  }
  return t;
}

}  // namespace

const ElementTopology& topology(ElementType type) {
  static const ElementTopology tet = build(ElementType::Tet4);
  static const ElementTopology hex = build(ElementType::Hex8);
  return type == ElementType::Tet4 ? tet : hex;
}

}  // namespace rkpm::particles::detail
