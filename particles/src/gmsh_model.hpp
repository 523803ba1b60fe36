// What rkpm takes from a Gmsh file, as plain data: read by Gmsh's API in a child
// process (isolated_call.hpp), so that a file that crashes Gmsh's readers, makes its
// mesher allocate without bound or loop, or leaves Gmsh's state broken costs the child,
// not the run. Only gmsh_model.cpp includes gmsh.h.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace rkpm::particles {

struct GmshElementBlock {
  int type = 0;                      // Gmsh's element type code
  std::string type_name;             // "Tetrahedron 4", "Prism 6", ...
  int nodes_per_element = 0;
  std::vector<std::size_t> tags;     // the elements' Gmsh tags
  std::vector<std::size_t> nodes;    // nodes_per_element node tags per element
};

struct GmshModel {
  std::vector<std::pair<std::string, int>> surfaces;  // named physical surfaces, by tag order
  double node_bound = 0.0;                            // .geo: geo_node_bound at the mesh size
  std::size_t node_count = 0;                         // nodes in the model (a .msh as read)
  // Filled by a full read only:
  std::vector<std::size_t> node_tags;
  std::vector<double> coords;                         // x, y, z per node tag
  std::vector<GmshElementBlock> volume_elements;
  std::vector<std::vector<std::size_t>> surface_nodes;  // per named surface
};

// How much of the model a caller needs.
enum class GmshRead { Surfaces, Estimate, Full };

struct GmshReadSpec {
  std::string path;
  double mesh_size = 0.0;  // .geo: the element size it is meshed at
  bool trusted = false;
  GmshRead what = GmshRead::Full;
};

// Runs in the child: opens the file with Gmsh, meshes a .geo at spec.mesh_size (Full),
// and returns the model. Throws CloudError naming the file for what rkpm refuses.
GmshModel read_gmsh_model(const GmshReadSpec& spec);

// The model through a byte stream, for the pipe between child and parent.
class ByteWriter;
class ByteReader;
void write_gmsh_model(ByteWriter& out, const GmshModel& model);
GmshModel read_gmsh_model_bytes(ByteReader& in);

}  // namespace rkpm::particles
