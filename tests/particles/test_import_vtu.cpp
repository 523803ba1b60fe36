#include "cloud_checks.hpp"
#include "tet_mesh.hpp"

#include "rkpm/particles/generators.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

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

// One tetrahedron, its cells replaced by `cells`.
std::string write_tet_file(const std::string& name, const std::vector<VtuCell>& cells) {
  return write_vtu(name, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, cells);
}

std::string write_text(const std::string& name, const std::string& text) {
  const fs::path path = fs::path(::testing::TempDir()) / "rkpm_particles_vtu" / name;
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

// `text` with the first occurrence of `from` replaced by `to` (which must occur).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test fixture: '" + from + "' not in the text");
  return text.replace(at, from.size(), to);
}

std::string text_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Cells naming points the file does not have were read out of bounds (by the
// element-quality check) before they were rejected.
TEST(ImportVtu, PointIdBeyondThePointsIsNamed) {
  expect_import_error(write_tet_file("bad_id.vtu", {{10, {0, 1, 2, 3}}, {10, {0, 1, 2, 40}}}),
                      {"cell 1 (vtkTetra (VTK type 10)) refers to point 40", "the file has 4 points (ids 0 to 3)"});
}

TEST(ImportVtu, NegativePointIdIsNamed) {
  expect_import_error(write_tet_file("negative_id.vtu", {{10, {0, -1, 2, 3}}}), {"cell 0", "refers to point -1"});
}

TEST(ImportVtu, CellSizeMustMatchItsType) {
  expect_import_error(write_tet_file("short_hex.vtu", {{10, {0, 1, 2, 3}}, {12, {0, 1, 2, 3, 0, 1, 2}}}),
                      {"cell 1 (vtkHexahedron (VTK type 12)) has 7 points, expected 8"});
  expect_import_error(write_tet_file("long_tet.vtu", {{10, {0, 1, 2, 3, 0, 1, 2, 3, 0}}, {10, {0, 1, 2}}}),
                      {"cell 0 (vtkTetra (VTK type 10)) has 9 points, expected 4"});
}

TEST(ImportVtu, NonFiniteCoordinateIsNamed) {
  const std::string good = write_tet_file("finite.vtu", {{10, {0, 1, 2, 3}}});
  const std::string text = replaced(text_of(good), "\n0 1 0\n", "\n0 nan 0\n");
  ASSERT_NE(text, text_of(good));
  expect_import_error(write_text("nan.vtu", text), {"point 2 has a non-finite coordinate"});
}

// VTK's reader loops and allocates by the sizes the XML declares: absurd ones are
// refused before it acts on them.
TEST(ImportVtu, AbsurdDeclaredSizesAreRefusedBeforeReading) {
  const std::string good = text_of(write_tet_file("sizes.vtu", {{10, {0, 1, 2, 3}}}));
  expect_import_error(
      write_text("components.vtu",
                 replaced(good, "NumberOfComponents=\"3\"", "NumberOfComponents=\"34294967295\"")),
      {"DataArray declares NumberOfComponents=\"34294967295\", expected an integer from 1 to 1024"});
  expect_import_error(
      write_text("points.vtu", replaced(good, "NumberOfPoints=\"4\"", "NumberOfPoints=\"1000000000000000\"")),
      {"Piece declares NumberOfPoints=\"1000000000000000\""});
  expect_import_error(write_text("cells.vtu", replaced(good, "NumberOfCells=\"1\"", "NumberOfCells=\"-1\"")),
                      {"Piece declares NumberOfCells=\"-1\", expected an integer from 0 to"});
  // VTK adds the offset to a file position (signed overflow); any offset makes it
  // read appended data, whatever the format says.
  expect_import_error(write_text("offset.vtu", replaced(good, "NumberOfComponents=\"3\" format=\"ascii\"",
                                                        "NumberOfComponents=\"3\" format=\"ascii\" "
                                                        "offset=\"99999999999999999999\"")),
                      {"DataArray declares offset=\"99999999999999999999\", expected an integer from 0 to"});
}

// VTK 9.1 sizes the connectivity by the last cell offset before checking it: at
// 2^61 the size wraps around and the reader writes past a tiny buffer (ASan:
// heap-buffer-overflow in vtkXMLDataParser::ReadAsciiData), at 2^32 it throws
// std::bad_alloc. The offsets are read and bounded first.
TEST(ImportVtu, HugeCellOffsetsAreRefusedBeforeReading) {
  const std::string good = text_of(write_tet_file("offsets.vtu", {{10, {0, 1, 2, 3}}}));
  const std::string offsets = "Name=\"offsets\" format=\"ascii\">\n";
  ASSERT_NE(good.find(offsets + "4 \n"), std::string::npos);
  for (const std::string big : {"4294967296", "2305843009213693952", "9223372036854775807"}) {
    const std::string path = write_text("offset_" + big + ".vtu", replaced(good, offsets + "4 ", offsets + big + " "));
    expect_import_error(path,
                        {"the cell offsets of piece 0 reach " + big + " for 1 cells, more than 8 points per cell"});
  }
}

// A one-tetrahedron file whose points are zlib-compressed binary data with the
// given compression header (base64 of UInt32 words) and no valid data after it.
std::string compressed_points_file(const std::string& name, const std::string& header) {
  return write_text(
      name,
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n"
      "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n"
      "<DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"binary\">\n" +
          header + "eJxjYMAPAAAcAAE=\n</DataArray>\n</Points>\n<Cells>\n"
          "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>\n"
          "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n"
          "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>\n</Cells>\n</Piece>\n"
          "</UnstructuredGrid>\n</VTKFile>\n");
}

// A compressed array's header (block count, block size, last block size, then
// each block's compressed size) is trusted by VTK 9.1: 2^32 - 1 blocks made it
// allocate and zero 16 GB for a file of a few hundred bytes, a block size
// of 0 divided by zero (SIGFPE), no blocks but a last block read a list it never
// allocated (SIGSEGV), a last block larger than a block or a compressed size
// beyond the file allocated gigabytes. Each header is checked against the file.
TEST(ImportVtu, CompressionHeadersAreCheckedAgainstTheFile) {
  const std::string points = "DataArray \"Points\": its compression header declares ";
  // {2^32 - 1, 32768, 96}, {0, 32768, 96}, {1, 0, 96}, {1, 96, 4e9}, {1, 96, 96, 2^31}
  expect_import_error(compressed_points_file("blocks.vtu", "/////wCAAABgAAAA"),
                      {points + "4294967295 blocks, more than the file can hold"});
  expect_import_error(compressed_points_file("no_blocks.vtu", "AAAAAACAAABgAAAA"),
                      {points + "no block but a last block of 96 bytes"});
  expect_import_error(compressed_points_file("zero_block_size.vtu", "AQAAAAAAAABgAAAA"),
                      {points + "blocks of 0 bytes and a last block of 96 bytes"});
  expect_import_error(compressed_points_file("big_last_block.vtu", "AQAAAGAAAAAAKGvu"),
                      {points + "blocks of 96 bytes and a last block of 4000000000 bytes"});
  expect_import_error(compressed_points_file("big_compressed_block.vtu", "AQAAAGAAAABgAAAAAAAAgA=="),
                      {points + "a compressed block of 2147483648 bytes, more than the file holds"});
}

// VTK's own diagnostics (a coloured dump of the pipeline on the terminal) are
// folded into the one error: nothing reaches stderr, the message names the file
// and says what the reader found, without VTK's headers or escape codes.
TEST(ImportVtu, ReaderDiagnosticsBecomeOneMessage) {
  const std::string good = text_of(write_tet_file("whole.vtu", {{10, {0, 1, 2, 3}}}));
  const std::string path = write_text("truncated.vtu", good.substr(0, good.find("<Cells>") + 20));
  ::testing::internal::CaptureStderr();
  std::string what;
  try {
    import_vtu(path);
  } catch (const CloudError& e) {
    what = e.what();
  }
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(err, "");
  EXPECT_NE(what.find("import_vtu '" + path + "': the reader failed: "), std::string::npos) << what;
  EXPECT_EQ(what.find('\x1b'), std::string::npos) << what;
  EXPECT_EQ(what.find("ERROR: In"), std::string::npos) << what;
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;

  // The capture ends with the import: a valid file still imports afterwards.
  EXPECT_EQ(import_vtu(write_tet_file("after.vtu", {{10, {0, 1, 2, 3}}})).size(), 4u);
}

TEST(ImportVtu, ErrorsInsideTheDataAreOneMessageToo) {
  const std::string good = text_of(write_tet_file("data.vtu", {{10, {0, 1, 2, 3}}}));
  const std::string path = write_text("short_points.vtu", replaced(good, "\n0 0 1\n", "\n"));
  ::testing::internal::CaptureStderr();
  expect_import_error(path, {"the reader failed: "});
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace rkpm::particles
