// A particle cloud: the discretisation of one body in its reference configuration.
//
// Every cloud carries a conforming mesh of linear elements (tetrahedra or hexahedra)
// whose nodes are the particles. The mesh is never used for interpolation: the
// reproducing-kernel shape functions do that. It exists to define the median-dual
// cells around the particles, which give
//   * nodal volumes (the quadrature weights and lumped masses),
//   * boundary normals and area weights (surface terms, boundary conditions), and
//   * the closed cell boundaries over which stabilized conforming nodal integration
//     (SCNI) smooths the gradients (see dual_cells.hpp).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rkpm::particles {

using Vec3 = Eigen::Vector3d;

// Numbers equal VTK's cell-type codes so the mesh can be written without translation.
enum class ElementType : std::uint8_t { Tet4 = 10, Hex8 = 12 };

int nodes_per_element(ElementType type);

// Linear elements in VTK node ordering, stored flat.
struct Mesh {
  std::vector<ElementType> type;      // one per element
  std::vector<std::int32_t> offset;   // n_elements + 1 entries into `nodes`
  std::vector<std::int32_t> nodes;    // particle ids

  int n_elements() const { return static_cast<int>(type.size()); }
  const std::int32_t* element_nodes(int e) const { return nodes.data() + offset[e]; }
  int element_size(int e) const { return offset[e + 1] - offset[e]; }
  void add_element(ElementType t, const std::int32_t* ids);
};

// A face of an element that lies on the body's surface, node order such that the
// right-hand rule gives the outward normal. Triangles use three of the four slots.
struct BoundaryFace {
  std::int32_t element = -1;
  std::int32_t n_nodes = 0;
  std::int32_t nodes[4] = {-1, -1, -1, -1};
};

struct Cloud {
  std::string name;                    // generator or file it came from, for messages

  std::vector<Vec3> X;                 // reference positions [m]
  std::vector<double> volume;          // median-dual cell volume [m^3]
  Mesh mesh;

  std::vector<BoundaryFace> boundary_faces;

  // Boundary particles, sorted by id. The three arrays below are parallel.
  std::vector<std::int32_t> boundary_particles;
  std::vector<Vec3> boundary_normal;   // outward unit normal (area-weighted mean of the dual pieces)
  std::vector<double> boundary_area;   // area of the particle's share of the surface [m^2]
  std::vector<std::int32_t> boundary_index;  // per particle: index into the arrays above, or -1

  // Named surfaces (block faces "xmin".."zmax", shell "outer"/"inner", sphere "surface").
  // Bit k of surface_mask[i] is set when particle i lies on surface_names[k].
  std::vector<std::string> surface_names;
  std::vector<std::uint32_t> surface_mask;

  std::size_t size() const { return X.size(); }
  bool on_surface(std::int32_t particle, const std::string& surface) const;
  std::uint32_t surface_bit(const std::string& surface) const;  // 0 if unknown
};

// Fills boundary_faces, volume, boundary_* and checks the mesh (every element has
// positive volume, every node is used). Generators call it as their last step.
// Throws CloudError naming the cloud and the offending element on failure.
void finalize_cloud(Cloud& cloud);

struct CloudError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace rkpm::particles
