// Cloud generators. All lengths in metres. Each returns a finalized cloud
// (see finalize_cloud) and the analytic quantities the tests compare against.
#pragma once

#include "rkpm/particles/cloud.hpp"

#include <array>
#include <cstdint>
#include <string>

namespace rkpm::particles {

// Rectangular block [origin, origin + size] of hexahedra, cells[i] per axis.
// jitter > 0 moves every particle by a uniform random offset of at most
// jitter * (local spacing) per axis, keeping boundary particles on their faces.
// Surfaces: xmin xmax ymin ymax zmin zmax.
struct BlockSpec {
  Vec3 origin = Vec3::Zero();
  Vec3 size = Vec3::Ones();
  std::array<int, 3> cells = {8, 8, 8};
  double jitter = 0.0;          // fraction of the spacing, [0, 0.3]
  std::uint64_t seed = 1;
};
Cloud make_block(const BlockSpec& spec);

// Solid ball of hexahedra: a cube mapped onto the ball, n cells along a diameter.
// The cloud is mirror-symmetric about the centre's three coordinate planes. An even
// n puts a particle at the centre, where every surface point is equally near: a
// field taken from the nearest surface particle (an LCE director with initial =
// "surface_normal") gets an arbitrary direction there and breaks that symmetry;
// an odd n has no particle there. Surface: surface.
struct SphereSpec {
  Vec3 center = Vec3::Zero();
  double radius = 1.0;
  int cells = 16;               // cells across the diameter (volume within 0.5 %)
};
Cloud make_sphere(const SphereSpec& spec);

// Closed thick shell whose outer surface is the ellipsoid with the given semi-axes
// and whose inner surface is the ellipsoid with every semi-axis reduced by
// `thickness` (a true offset surface of an oblate spheroid self-intersects when the
// thickness exceeds the rim's radius of curvature c^2/a; the seed's cell is such a
// case). Cubed-sphere parametrisation: 6 faces of face_cells x face_cells, `layers`
// particle layers through the wall. Along each meridian the particles follow a blend
// of arc length and turning of the normal, which refines the tight rim of a flat
// spheroid (normals within 0.5 deg of the analytic ones at the default resolution,
// see test_shell.cpp). The default gives 6*32^2+2 = 6146 particles per
// layer and 5 layers: 30,730 particles, the seed's 30,728 within 0.01 %.
// Surfaces: outer inner.
struct ShellSpec {
  Vec3 center = Vec3::Zero();
  Vec3 semi_axes = Vec3(5e-6, 5e-6, 1.5e-6);
  double thickness = 0.5e-6;
  int face_cells = 32;
  int layers = 5;
};
Cloud make_shell(const ShellSpec& spec);

// Nodes and cells (VTK_TETRA, VTK_HEXAHEDRON) of an unstructured-grid file (.vtu).
// Surface: surface (every particle on the body's surface).
// Throws CloudError naming the file and what was wrong with it; VTK's own
// diagnostics are folded into that message, nothing is printed. Not for concurrent
// use: while it reads, VTK's process-wide message window is redirected.
Cloud import_vtu(const std::string& path);

// A Gmsh file (Gmsh's C++ API): a .msh mesh, or a .geo geometry meshed with elements
// of at most `mesh_size` (required for .geo, ignored for .msh). Tetrahedra and
// hexahedra of first and second order; their corner nodes are the particles.
// Coordinates are multiplied by `scale`.
// Surfaces: "surface" (the whole boundary) and one per physical group of dimension 2,
// by its name. Throws CloudError naming the file and, for a bad element, its Gmsh tag.
// Not for concurrent use with another Gmsh import (Gmsh's state is process-wide; the
// importer serialises its own calls).
struct GmshImportSpec {
  std::string path;
  double scale = 1.0;
  double mesh_size = 0.0;
  // A .geo file is a program Gmsh runs. Unless trusted, one that could act outside its
  // own geometry (run a command, end the process, read other files, loop) is refused
  // before Gmsh sees it (screen_geo_script).
  bool trusted = false;
};
Cloud import_gmsh(const GmshImportSpec& spec);
// The surface names a Gmsh file provides ("surface" first, then its named physical
// surfaces in tag order), without meshing it. Throws CloudError for a file Gmsh cannot
// read, or an untrusted .geo that screen_geo_script refuses.
std::vector<std::string> gmsh_surface_names(const std::string& path, bool trusted = false);
// Throws CloudError naming the file, the line and the command when the .geo script at
// `path` uses a command that acts outside its own geometry: SystemCall and its
// variants, Exit, Sleep, OnelabRun, CreateDir, Include, Merge, loops (For, While) and
// macros (Call), or sets a meshing option (Mesh.*) that would change the element size
// the scene declares. Comments and strings are skipped.
void screen_geo_script(const std::string& path);
// The particles a Gmsh import will hold, before importing: a .msh file's node count
// (an upper bound: a second-order mesh's mid-nodes are not particles), for a .geo file
// 1.4 V / mesh_size^3 with V its bounding box's volume (a tetrahedral mesh of edge h
// holds about 1.4 nodes per h^3).
double gmsh_particle_estimate(const GmshImportSpec& spec);

// Analytic references.
double ellipsoid_volume(const Vec3& semi_axes);
double ellipsoid_area(const Vec3& semi_axes);       // exact for spheroids, numeric otherwise
Vec3 ellipsoid_normal(const Vec3& semi_axes, const Vec3& x);  // outward unit normal at x (centred)

}  // namespace rkpm::particles
