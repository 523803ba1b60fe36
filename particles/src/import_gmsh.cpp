// Clouds from Gmsh, through Gmsh's own C++ API (Debian's libgmsh-dev): a .msh file as
// it is, or a .geo file meshed here with a declared element size. The corner nodes of
// the volume elements become the particles (a second-order mesh's mid-edge and face
// nodes are dropped: the RK approximation, not the mesh, interpolates), and every
// physical group of dimension 2 becomes a named surface.
#include "rkpm/particles/element_geometry.hpp"
#include "rkpm/particles/generators.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <string>
#include <unordered_map>

namespace rkpm::particles {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw CloudError("Gmsh file '" + path + "': " + what);
}

// Gmsh keeps one process-wide state: one import at a time, under this lock.
std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

bool& gmsh_initialised() {
  static bool initialised = false;
  return initialised;
}

void ensure_initialised() {
  if (gmsh_initialised()) return;
  gmsh::initialize(0, nullptr, false);
  gmsh_initialised() = true;
}

// Gmsh's options outlive a file: a script may set them, and a trusted one may. Before
// each open they are set back to what every import starts from: quiet, errors thrown
// (AbortOnError = 2, caught by with_gmsh), and the meshing options rkpm's estimate
// assumes.
void reset_options() {
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.AbortOnError", 2);
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

bool is_geo(const std::string& path) { return std::filesystem::path(path).extension() == ".geo"; }

// Gmsh runs any file whose first line is not a mesh header as a .geo script, whatever
// its name: an untrusted file named otherwise must be a mesh.
void require_mesh_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string first;
  std::getline(in, first);
  if (!first.empty() && first.back() == '\r') first.pop_back();
  if (first != "$MeshFormat" && first != "$NOD")
    fail(path, "expected a Gmsh mesh, whose first line is $MeshFormat (Gmsh would run any other file as a "
               "script); a .geo geometry is named *.geo");
}

// Opens `path` as the only model; Gmsh reports a file it cannot read by throwing. An
// untrusted file is checked first: opening a script runs it.
void open_model(const std::string& path, bool trusted) {
  if (!trusted) {
    if (is_geo(path)) screen_geo_script(path);
    else require_mesh_header(path);
  }
  ensure_initialised();
  reset_options();
  gmsh::clear();
  try {
    gmsh::open(path);
  } catch (const std::string& e) {
    fail(path, "not a mesh or geometry Gmsh can read: " + e);
  } catch (const std::exception& e) {
    fail(path, std::string("not a mesh or geometry Gmsh can read: ") + e.what());
  }
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

// Corner-node count of Gmsh's 3D element types that a cloud can hold: tetrahedra and
// hexahedra of first and second order (Gmsh numbers corner nodes first, in the same
// order as VTK for both). 0 for any other type.
int corner_nodes(int gmsh_type) {
  switch (gmsh_type) {
    case 4: case 11: case 29: return 4;   // tet4, tet10, tet20
    case 5: case 12: case 17: return 8;   // hex8, hex27, hex20
    default: return 0;
  }
}

// Runs one use of Gmsh's API on `path` under the process-wide lock. Gmsh reports its
// errors by throwing std::string (and, from its C parts, C strings): every kind is
// turned into a CloudError naming the file, so nothing Gmsh throws reaches the caller
// as anything else. Gmsh's model is cleared afterwards whatever happened.
template <class Use>
auto with_gmsh(const std::string& path, Use use) -> decltype(use()) {
  std::lock_guard<std::mutex> lock(gmsh_mutex());
  struct ClearModel {
    ~ClearModel() {
      if (!gmsh_initialised()) return;  // a file refused before Gmsh ever started
      try {
        gmsh::clear();
      } catch (...) {  // a failed clear leaves a model the next open replaces
      }
    }
  } clear_model;
  try {
    return use();
  } catch (const CloudError&) {
    throw;
  } catch (const std::string& e) {
    fail(path, "Gmsh: " + e);
  } catch (const char* e) {
    fail(path, std::string("Gmsh: ") + (e ? e : "unknown error"));
  } catch (const std::exception& e) {
    fail(path, std::string("Gmsh: ") + e.what());
  } catch (...) {
    fail(path, "Gmsh failed with an error of unknown type");
  }
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

}  // namespace

std::vector<std::string> gmsh_surface_names(const std::string& path, bool trusted) {
  return with_gmsh(path, [&] {
    open_model(path, trusted);
    std::vector<std::string> names{"surface"};
    for (const auto& [name, tag] : named_surfaces()) names.push_back(name);
    return names;
  });
}

double gmsh_particle_estimate(const GmshImportSpec& spec) {
  return with_gmsh(spec.path, [&] {
    open_model(spec.path, spec.trusted);
    double estimate = 0.0;
    if (is_geo(spec.path)) {
      estimate = geo_node_bound(spec.mesh_size);
    } else {
      std::vector<std::size_t> tags;
      std::vector<double> xyz, uvw;
      gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
      estimate = static_cast<double>(tags.size());
    }
    return estimate;
  });
}

Cloud import_gmsh(const GmshImportSpec& spec) {
  const std::string& path = spec.path;
  return with_gmsh(path, [&] {
    open_model(path, spec.trusted);
    if (is_geo(path)) {
      if (!(spec.mesh_size > 0.0)) fail(path, "a .geo file needs a mesh size to be meshed with");
      gmsh::option::setNumber("Mesh.MeshSizeMax", spec.mesh_size);
      // Sizes given at the points of an untrusted script are ignored: the scene's
      // mesh_size, which the pre-flight counts with, is the size. A trusted script keeps
      // its own setting.
      if (!spec.trusted) gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
      const double bound = geo_node_bound(spec.mesh_size);
      try {
        gmsh::model::mesh::generate(3);
      } catch (const std::string& e) {
        fail(path, "meshing failed: " + e);
      }
      // What the pre-flight allowed for is what an untrusted script may make.
      std::vector<std::size_t> tags;
      std::vector<double> xyz, uvw;
      gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
      if (!spec.trusted && static_cast<double>(tags.size()) > bound)
        fail(path, "meshed into " + std::to_string(tags.size()) + " nodes, more than the " +
                       std::to_string(static_cast<long long>(bound)) +
                       " the pre-flight estimate allows at mesh_size " + std::to_string(spec.mesh_size) +
                       "; expected a geometry whose mesh the size declares (or trusted = true)");
    }

    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, element_nodes;
    gmsh::model::mesh::getElements(types, element_tags, element_nodes, 3);
    if (types.empty()) fail(path, "has no volume elements (tetrahedra or hexahedra)");

    // Particles: the corner nodes in order of first use; their ids index cloud.X.
    std::vector<std::size_t> node_tags;
    std::vector<double> coords, params;
    gmsh::model::mesh::getNodes(node_tags, coords, params, -1, -1, false, false);
    std::unordered_map<std::size_t, std::size_t> coord_of;
    for (std::size_t k = 0; k < node_tags.size(); ++k) coord_of[node_tags[k]] = k;
    std::unordered_map<std::size_t, std::int32_t> particle_of;
    Cloud cloud;
    cloud.name = path;
    std::vector<std::size_t> gmsh_tag_of_element;
    for (std::size_t t = 0; t < types.size(); ++t) {
      const int corners = corner_nodes(types[t]);
      std::string type_name;
      int dim = 0, order = 0, n_nodes = 0, n_primary = 0;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(types[t], type_name, dim, order, n_nodes, local, n_primary);
      if (corners == 0)
        fail(path, "element " + std::to_string(element_tags[t].front()) + " is a " + type_name +
                       ": only tetrahedra and hexahedra (first or second order) can be imported");
      for (std::size_t e = 0; e < element_tags[t].size(); ++e) {
        std::int32_t ids[8];
        for (int c = 0; c < corners; ++c) {
          const std::size_t tag = element_nodes[t][e * static_cast<std::size_t>(n_nodes) + c];
          auto [it, inserted] = particle_of.try_emplace(tag, static_cast<std::int32_t>(cloud.X.size()));
          if (inserted) {
            const std::size_t k = coord_of.at(tag);
            cloud.X.emplace_back(spec.scale * coords[3 * k], spec.scale * coords[3 * k + 1],
                                 spec.scale * coords[3 * k + 2]);
          }
          ids[c] = it->second;
        }
        cloud.mesh.add_element(corners == 4 ? ElementType::Tet4 : ElementType::Hex8, ids);
        gmsh_tag_of_element.push_back(element_tags[t][e]);
      }
    }

    // Inverted or degenerate elements, named by their Gmsh tag, before finalize_cloud.
    int inverted = 0, first = -1;
    for (int e = 0; e < cloud.mesh.n_elements(); ++e)
      if (!(element_min_scaled_jacobian(cloud, e) > 0.0) && inverted++ == 0) first = e;
    if (inverted > 0)
      fail(path, std::to_string(inverted) + " of " + std::to_string(cloud.mesh.n_elements()) +
                     " volume elements are inverted or degenerate (first: element " +
                     std::to_string(gmsh_tag_of_element[first]) + "); expected Gmsh node order with positive volume");

    // Surfaces: bit 0 is the whole boundary, bit k the k-th named physical surface.
    const auto named = named_surfaces();
    if (named.size() + 1 > 32) fail(path, "has more than 31 physical surfaces");
    cloud.surface_names = {"surface"};
    for (const auto& [name, tag] : named) cloud.surface_names.push_back(name);
    finalize_cloud(cloud);
    for (const std::int32_t p : cloud.boundary_particles) cloud.surface_mask[p] |= 1u;
    for (std::size_t k = 0; k < named.size(); ++k) {
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(2, named[k].second, entities);
      for (int entity : entities) {
        std::vector<std::size_t> tags;
        std::vector<double> xyz, uvw;
        gmsh::model::mesh::getNodes(tags, xyz, uvw, 2, entity, true, false);
        for (std::size_t tag : tags)
          if (auto it = particle_of.find(tag); it != particle_of.end()) cloud.surface_mask[it->second] |= 1u << (k + 1);
      }
    }
    return cloud;
  });
}

}  // namespace rkpm::particles
