#include "cloud_checks.hpp"
#include "tet_mesh.hpp"

#include "rkpm/particles/generators.hpp"

#include <filesystem>
#include <fstream>
#include <iomanip>

namespace rkpm::particles {
namespace {

namespace fs = std::filesystem;

// A hand-written ASCII .vtu, so the test does not depend on VTK's writer.
struct VtuCell {
  int vtk_type;
  std::vector<std::int64_t> nodes;
};

std::string write_vtu(const std::string& name, const std::vector<Vec3>& points, const std::vector<VtuCell>& cells) {
  const fs::path dir = fs::path(::testing::TempDir()) / "rkpm_particles_vtu";
  fs::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream out(path);
  out << std::setprecision(17);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\""
      << points.size() << "\" NumberOfCells=\"" << cells.size() << "\">\n";
  out << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& x : points) out << x.x() << " " << x.y() << " " << x.z() << "\n";
  out << "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const VtuCell& c : cells) {
    for (const auto n : c.nodes) out << n << " ";
  }
  out << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::int64_t offset = 0;
  for (const VtuCell& c : cells) out << (offset += static_cast<std::int64_t>(c.nodes.size())) << " ";
  out << "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (const VtuCell& c : cells) out << c.vtk_type << " ";
  out << "\n</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return path;
}

std::string write_cloud(const std::string& name, const Cloud& cloud) {
  std::vector<VtuCell> cells;
  for (int e = 0; e < cloud.mesh.n_elements(); ++e) {
    const std::int32_t* n = cloud.mesh.element_nodes(e);
    cells.push_back({static_cast<int>(cloud.mesh.type[e]), {n, n + cloud.mesh.element_size(e)}});
  }
  return write_vtu(name, cloud.X, cells);
}

BlockSpec jittered_block() {
  BlockSpec spec;
  spec.cells = {4, 3, 5};
  spec.size = Vec3(1.0, 2.0, 3.0);
  spec.jitter = 0.25;
  return spec;
}

void expect_same_cloud(const Cloud& original, const Cloud& imported) {
  ASSERT_EQ(imported.size(), original.size());
  EXPECT_EQ(imported.mesh.nodes, original.mesh.nodes);
  double worst = 0.0;
  for (std::size_t i = 0; i < original.size(); ++i) {
    worst = std::max(worst, std::abs(imported.volume[i] - original.volume[i]) / original.volume[i]);
  }
  testing::report("vtu round trip max nodal volume relative difference", worst);
  EXPECT_LT(worst, 1e-14);
  EXPECT_EQ(imported.boundary_particles, original.boundary_particles);
  // The whole surface is one named surface, "surface", and nothing else is on it.
  EXPECT_EQ(imported.surface_names, std::vector<std::string>{"surface"});
  std::size_t on_surface = 0;
  for (std::int32_t p = 0; p < static_cast<std::int32_t>(imported.size()); ++p) {
    on_surface += imported.on_surface(p, "surface") ? 1 : 0;
  }
  EXPECT_EQ(on_surface, imported.boundary_particles.size());
  for (const std::int32_t p : imported.boundary_particles) EXPECT_TRUE(imported.on_surface(p, "surface"));
  EXPECT_FALSE(imported.on_surface(imported.boundary_particles.front(), "boundary"));
}

TEST(ImportVtu, HexRoundTripKeepsNodalVolumes) {
  const Cloud block = make_block(jittered_block());
  const std::string path = write_cloud("block.vtu", block);
  const Cloud imported = import_vtu(path);
  EXPECT_EQ(imported.name, path);
  expect_same_cloud(block, imported);
}

TEST(ImportVtu, TetRoundTripKeepsNodalVolumes) {
  const Cloud tets = testing::tet_block(jittered_block());
  expect_same_cloud(tets, import_vtu(write_cloud("tets.vtu", tets)));
}

void expect_import_error(const std::string& path, const std::vector<std::string>& fragments) {
  try {
    import_vtu(path);
    ADD_FAILURE() << "expected CloudError for " << path;
  } catch (const CloudError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    for (const auto& f : fragments) EXPECT_NE(what.find(f), std::string::npos) << "'" << f << "' not in: " << what;
  }
}

TEST(ImportVtu, MissingFile) {
  expect_import_error((fs::path(::testing::TempDir()) / "no_such_file.vtu").string(), {"cannot open"});
}

TEST(ImportVtu, NotAVtuFile) {
  const fs::path path = fs::path(::testing::TempDir()) / "rkpm_particles_vtu" / "garbage.vtu";
  fs::create_directories(path.parent_path());
  std::ofstream(path) << "this is not XML\n";
  expect_import_error(path.string(), {"not a VTK XML UnstructuredGrid"});
}

TEST(ImportVtu, NoPoints) { expect_import_error(write_vtu("empty.vtu", {}, {}), {"no points"}); }

TEST(ImportVtu, UnsupportedCellTypeIsNamedAndCounted) {
  const std::vector<Vec3> points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                    Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)};
  const std::vector<VtuCell> cells = {{13, {0, 1, 2, 3, 4, 5}}, {13, {0, 1, 2, 3, 4, 5}}, {5, {0, 1, 2}}};
  expect_import_error(write_vtu("wedge.vtu", points, cells), {"2 x vtkWedge", "1 x vtkTriangle"});
}

TEST(ImportVtu, InvertedCellsAreCounted) {
  Cloud block = make_block(jittered_block());
  // Mirror the node order of two hexahedra (bottom and top faces swapped).
  for (const int e : {3, 7}) {
    std::int32_t* n = block.mesh.nodes.data() + block.mesh.offset[e];
    std::swap_ranges(n, n + 4, n + 4);
  }
  expect_import_error(write_cloud("inverted.vtu", block), {"2 of 60 cells are inverted", "first: cell 3"});
}

}  // namespace
}  // namespace rkpm::particles
