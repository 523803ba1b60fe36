// Gmsh's C++ API (Debian's libgmsh-dev), called in the child process that
// import_gmsh.cpp starts for each use of a Gmsh file (gmsh_model.hpp).
#include "gmsh_model.hpp"

#include "isolated_call.hpp"
#include "rkpm/particles/cloud.hpp"
#include "rkpm/particles/generators.hpp"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace rkpm::particles {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw CloudError("Gmsh file '" + path + "': " + what);
}

bool is_geo(const std::string& path) { return std::filesystem::path(path).extension() == ".geo"; }

// Quiet, errors thrown (AbortOnError = 2), one thread (the child has only the forking
// thread), and the meshing options rkpm's estimate assumes.
void set_options() {
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.AbortOnError", 2);
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads1D", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads3D", 1);
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::option::setNumber("Mesh.MeshSizeFactor", 1.0);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 1);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
  gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 0);
  gmsh::option::setNumber("Mesh.RecombineAll", 0);
}

// The named surfaces: physical groups of dimension 2, by name (a group without a name
// is called by its tag, "physical_surface_<tag>").
std::vector<std::pair<std::string, int>> named_surfaces() {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  std::vector<std::pair<std::string, int>> named;
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    named.emplace_back(name.empty() ? "physical_surface_" + std::to_string(tag) : name, tag);
  }
  return named;
}

// A bound on the nodes of the open geometry meshed at size h: the nodes of a grid of
// that size over its bounding box, times 3 for a tetrahedral mesh's denser nodes (about
// 1.4 in the bulk) and a small body's surface nodes (a unit cube at h = 0.5 has 45
// nodes against the grid's 27). Each extent has at least two sheets of nodes, so a slab
// thinner than h still counts its layer of elements, which a plain volume over h^3
// would count as almost none.
double geo_node_bound(double h) {
  if (!(h > 0.0)) return 0.0;
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  const auto sheets = [h](double extent) { return std::max(extent / h, 1.0) + 1.0; };
  return 3.0 * sheets(x1 - x0) * sheets(y1 - y0) * sheets(z1 - z0);
}

std::size_t count_nodes() {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, uvw;
  gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
  return tags.size();
}

// An untrusted script meshes at the scene's size and no finer: sizes at its points are
// ignored (MeshSizeFromPoints = 0), the size is capped at mesh_size, and a mesh with more
// nodes than the pre-flight's bound is refused. A trusted script keeps its own sizes.
void mesh_geo(const GmshReadSpec& spec, double bound) {
  if (!(spec.mesh_size > 0.0)) fail(spec.path, "a .geo file needs a mesh size to be meshed with");
  gmsh::option::setNumber("Mesh.MeshSizeMax", spec.mesh_size);
  if (!spec.trusted) gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  try {
    gmsh::model::mesh::generate(3);
  } catch (const std::string& e) {
    fail(spec.path, "meshing failed: " + e);
  }
  const std::size_t nodes = count_nodes();
  if (!spec.trusted && static_cast<double>(nodes) > bound)
    fail(spec.path, "meshed into " + std::to_string(nodes) + " nodes, more than the " +
                        std::to_string(static_cast<long long>(bound)) + " the pre-flight estimate allows at mesh_size " +
                        std::to_string(spec.mesh_size) + "; expected a geometry whose mesh the size declares (or trusted = true)");
}

void read_full(const GmshReadSpec& spec, GmshModel& model) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, 3);
  for (std::size_t t = 0; t < types.size(); ++t) {
    GmshElementBlock block;
    block.type = types[t];
    int dim = 0, order = 0, n_primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(types[t], block.type_name, dim, order, block.nodes_per_element, local,
                                            n_primary);
    block.tags = std::move(element_tags[t]);
    block.nodes = std::move(element_nodes[t]);
    if (block.nodes.size() != block.tags.size() * static_cast<std::size_t>(block.nodes_per_element))
      fail(spec.path, "Gmsh returned an inconsistent element block");
    model.volume_elements.push_back(std::move(block));
  }
  std::vector<double> params;
  gmsh::model::mesh::getNodes(model.node_tags, model.coords, params, -1, -1, false, false);
  for (const auto& [name, tag] : model.surfaces) {
    std::vector<std::size_t> nodes;
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(2, tag, entities);
    for (int entity : entities) {
      std::vector<std::size_t> tags;
      std::vector<double> xyz, uvw;
      gmsh::model::mesh::getNodes(tags, xyz, uvw, 2, entity, true, false);
      nodes.insert(nodes.end(), tags.begin(), tags.end());
    }
    model.surface_nodes.push_back(std::move(nodes));
  }
}

}  // namespace

GmshModel read_gmsh_model(const GmshReadSpec& spec) {
  const std::string& path = spec.path;
  GmshModel model;
  try {
    gmsh::initialize(0, nullptr, false);
    set_options();
    try {
      gmsh::open(path);
    } catch (const std::string& e) {
      fail(path, "not a mesh or geometry Gmsh can read: " + e);
    }
    model.surfaces = named_surfaces();
    if (spec.what == GmshRead::Surfaces) return model;
    if (is_geo(path)) {
      model.node_bound = geo_node_bound(spec.mesh_size);
      if (spec.what == GmshRead::Full) mesh_geo(spec, model.node_bound);
    }
    model.node_count = count_nodes();
    if (spec.what == GmshRead::Full) read_full(spec, model);
  } catch (const CloudError&) {
    throw;
  } catch (const std::string& e) {  // Gmsh reports its errors by throwing std::string
    fail(path, "Gmsh: " + e);
  } catch (const char* e) {
    fail(path, std::string("Gmsh: ") + (e ? e : "unknown error"));
  }
  return model;
}

void write_gmsh_model(ByteWriter& out, const GmshModel& m) {
  out.put<std::uint64_t>(m.surfaces.size());
  for (const auto& [name, tag] : m.surfaces) {
    out.put_string(name);
    out.put(tag);
  }
  out.put(m.node_bound);
  out.put<std::uint64_t>(m.node_count);
  out.put_vector(m.node_tags);
  out.put_vector(m.coords);
  out.put<std::uint64_t>(m.volume_elements.size());
  for (const auto& b : m.volume_elements) {
    out.put(b.type);
    out.put_string(b.type_name);
    out.put(b.nodes_per_element);
    out.put_vector(b.tags);
    out.put_vector(b.nodes);
  }
  out.put<std::uint64_t>(m.surface_nodes.size());
  for (const auto& nodes : m.surface_nodes) out.put_vector(nodes);
}

GmshModel read_gmsh_model_bytes(ByteReader& in) {
  GmshModel m;
  m.surfaces.resize(in.checked_count(12));
  for (auto& [name, tag] : m.surfaces) {
    name = in.get_string();
    tag = in.get<int>();
  }
  m.node_bound = in.get<double>();
  m.node_count = in.get<std::uint64_t>();
  m.node_tags = in.get_vector<std::size_t>();
  m.coords = in.get_vector<double>();
  m.volume_elements.resize(in.checked_count(40));
  for (auto& b : m.volume_elements) {
    b.type = in.get<int>();
    b.type_name = in.get_string();
    b.nodes_per_element = in.get<int>();
    b.tags = in.get_vector<std::size_t>();
    b.nodes = in.get_vector<std::size_t>();
  }
  m.surface_nodes.resize(in.checked_count(8));
  for (auto& nodes : m.surface_nodes) nodes = in.get_vector<std::size_t>();
  return m;
}

}  // namespace rkpm::particles
