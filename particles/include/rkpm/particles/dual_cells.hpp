// Median-dual cells of a particle cloud's mesh, as closed triangulated surfaces.
//
// The cell of particle a is the union, over the elements around a, of the part of
// each element nearer to a in the median-dual sense. Its boundary consists of
//   * interior facets, one quadrilateral per element edge (a,b):
//       [midpoint(a,b), centroid(face 1 of the edge), centroid(element), centroid(face 2)],
//     shared with the cell of b, where it appears with the opposite orientation;
//   * boundary pieces, one quadrilateral per boundary face around a:
//       [a, midpoint(a,next), centroid(face), midpoint(prev,a)],
//     tagged with the boundary face they lie on.
// Each quadrilateral is split into two triangles with fixed diagonals, so every facet
// is planar: a one-point (centroid) rule, or a third of the area at each corner,
// integrates linear functions over it exactly, and the cells sharing a facet or a
// corner evaluate the same points bit for bit. The cell
// surface is closed, which is what makes the smoothed gradients of SCNI satisfy
// the divergence theorem, and so the linear patch test, exactly.
#pragma once

#include "rkpm/particles/cloud.hpp"

#include <array>
#include <vector>

namespace rkpm::particles {

struct DualFacet {
  Vec3 point;        // triangle centroid: the quadrature point [m]
  Vec3 area;         // outward area vector (unit normal times area) [m^2]
  // The triangle's corners: particles, edge midpoints, face and element centroids, each
  // computed in one order whichever cell asks, so a corner shared by several cells has
  // the same bits in all of them (a builder may evaluate it once).
  std::array<Vec3, 3> corner;
  bool on_boundary;  // true for pieces of the body's surface
  // Boundary pieces: index into Cloud::boundary_faces of the face the piece lies on,
  // which tells the named surface of a particle on an edge between two surfaces
  // (e.g. a block's corner belongs to three). -1 for interior facets.
  std::int32_t face = -1;
};

class DualCells {
 public:
  explicit DualCells(const Cloud& cloud);

  // Replaces `out` with the oriented triangles bounding the cell of `particle`.
  // Thread-safe: const and allocation only in `out`.
  void facets(std::int32_t particle, std::vector<DualFacet>& out) const;

  // Cell volume by the divergence theorem: (1/3) sum point . area.
  double volume(std::int32_t particle, std::vector<DualFacet>& scratch) const;

 private:
  const Cloud& cloud_;
  std::vector<std::int32_t> element_offset_;  // particle -> incident elements (CSR)
  std::vector<std::int32_t> elements_;
  std::vector<std::int32_t> bface_offset_;    // particle -> incident boundary faces (CSR)
  std::vector<std::int32_t> bfaces_;
};

}  // namespace rkpm::particles
