// Clouds from Gmsh: a .msh file as it is, or a .geo file meshed with a declared element
// size. Gmsh itself runs in a child process (gmsh_model.hpp, isolated_call.hpp): its
// readers crash on some malformed files, a script can make its mesher allocate without
// bound, and a file it stopped reading can leave its state broken. The corner nodes of
// the volume elements become the particles (a second-order mesh's mid-edge and face
// nodes are dropped: the RK approximation, not the mesh, interpolates), and every
// physical group of dimension 2 becomes a named surface.
#include "gmsh_model.hpp"
#include "isolated_call.hpp"
#include "rkpm/particles/element_geometry.hpp"
#include "rkpm/particles/generators.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <unordered_map>

namespace rkpm::particles {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw CloudError("Gmsh file '" + path + "': " + what);
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

// What the child may use for an untrusted file: a minute of CPU and a gigabyte, plus, for
// a mesh file, a second and 200 bytes per byte of it (Gmsh holds a node in about 100
// bytes of text), and, for a script, a millisecond and 16 KiB per node of the bound the
// pre-flight counted with. A trusted file has no limits: its author vouches for its size.
ChildLimits limits_for(const GmshReadSpec& spec, double node_bound) {
  if (spec.trusted) return {};
  constexpr std::size_t kGiB = std::size_t{1} << 30;
  if (is_geo(spec.path))
    return {60.0 + 1e-3 * node_bound, kGiB + static_cast<std::size_t>(16384.0 * std::min(node_bound, 1e12))};
  std::error_code ec;
  const auto bytes = static_cast<double>(std::filesystem::file_size(spec.path, ec));
  return {60.0 + bytes / 1e6, kGiB + static_cast<std::size_t>(200.0 * bytes)};
}

// The model as Gmsh reads it, from a child process. An untrusted file is screened
// first: opening a script runs it.
GmshModel read_model(const GmshReadSpec& spec, double node_bound = 0.0) {
  if (!spec.trusted) {
    if (is_geo(spec.path)) screen_geo_script(spec.path);
    else require_mesh_header(spec.path);
  }
  if (!std::ifstream(spec.path)) fail(spec.path, "cannot be read");
  try {
    const std::string bytes =
        run_isolated([&](ByteWriter& out) { write_gmsh_model(out, read_gmsh_model(spec)); }, limits_for(spec, node_bound));
    ByteReader in(bytes);
    return read_gmsh_model_bytes(in);
  } catch (const IsolatedError& e) {
    // The child's own refusals already name the file.
    if (e.message.rfind("Gmsh file '", 0) == 0) throw CloudError(e.message);
    fail(spec.path, "Gmsh " + e.message + " reading it; expected a valid Gmsh file");
  } catch (const std::runtime_error& e) {
    fail(spec.path, std::string("reading Gmsh's answer failed: ") + e.what());
  }
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

}  // namespace

std::vector<std::string> gmsh_surface_names(const std::string& path, bool trusted) {
  const GmshModel model = read_model({path, 0.0, trusted, GmshRead::Surfaces});
  std::vector<std::string> names{"surface"};
  for (const auto& [name, tag] : model.surfaces) names.push_back(name);
  return names;
}

double gmsh_particle_estimate(const GmshImportSpec& spec) {
  const GmshModel model = read_model({spec.path, spec.mesh_size, spec.trusted, GmshRead::Estimate});
  return is_geo(spec.path) ? model.node_bound : static_cast<double>(model.node_count);
}

Cloud import_gmsh(const GmshImportSpec& spec) {
  const std::string& path = spec.path;
  // A script's limits grow with its node bound, which a first child measures.
  double bound = 0.0;
  if (is_geo(path) && !spec.trusted) bound = gmsh_particle_estimate(spec);
  const GmshModel model = read_model({path, spec.mesh_size, spec.trusted, GmshRead::Full}, bound);
  if (model.volume_elements.empty()) fail(path, "has no volume elements (tetrahedra or hexahedra)");

  // Particles: the corner nodes in order of first use; their ids index cloud.X.
  std::unordered_map<std::size_t, std::size_t> coord_of;
  for (std::size_t k = 0; k < model.node_tags.size(); ++k) coord_of[model.node_tags[k]] = k;
  if (model.coords.size() != 3 * model.node_tags.size()) fail(path, "Gmsh returned inconsistent node coordinates");
  std::unordered_map<std::size_t, std::int32_t> particle_of;
  Cloud cloud;
  cloud.name = path;
  std::vector<std::size_t> gmsh_tag_of_element;
  for (const GmshElementBlock& block : model.volume_elements) {
    const int corners = corner_nodes(block.type);
    if (corners == 0)
      fail(path, "element " + std::to_string(block.tags.front()) + " is a " + block.type_name +
                     ": only tetrahedra and hexahedra (first or second order) can be imported");
    for (std::size_t e = 0; e < block.tags.size(); ++e) {
      std::int32_t ids[8];
      for (int c = 0; c < corners; ++c) {
        const std::size_t tag = block.nodes[e * static_cast<std::size_t>(block.nodes_per_element) + c];
        auto [it, inserted] = particle_of.try_emplace(tag, static_cast<std::int32_t>(cloud.X.size()));
        if (inserted) {
          const auto found = coord_of.find(tag);
          if (found == coord_of.end())
            fail(path, "element " + std::to_string(block.tags[e]) + " refers to node " + std::to_string(tag) +
                           ", which the file does not define");
          const std::size_t k = found->second;
          const double* x = &model.coords[3 * k];
          if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
            fail(path, "node " + std::to_string(tag) + " has a coordinate that is not a finite number");
          cloud.X.emplace_back(spec.scale * x[0], spec.scale * x[1], spec.scale * x[2]);
        }
        ids[c] = it->second;
      }
      cloud.mesh.add_element(corners == 4 ? ElementType::Tet4 : ElementType::Hex8, ids);
      gmsh_tag_of_element.push_back(block.tags[e]);
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
  if (model.surfaces.size() + 1 > 32) fail(path, "has more than 31 physical surfaces");
  cloud.surface_names = {"surface"};
  for (const auto& [name, tag] : model.surfaces) cloud.surface_names.push_back(name);
  finalize_cloud(cloud);
  for (const std::int32_t p : cloud.boundary_particles) cloud.surface_mask[p] |= 1u;
  for (std::size_t k = 0; k < model.surface_nodes.size(); ++k)
    for (std::size_t tag : model.surface_nodes[k])
      if (auto it = particle_of.find(tag); it != particle_of.end()) cloud.surface_mask[it->second] |= 1u << (k + 1);
  return cloud;
}

}  // namespace rkpm::particles
