// A .vtu written by write_vtu and read back through VTK's reader must hold
// exactly (bit for bit) the points, cells and fields that were written, in
// appended raw-binary zlib-compressed form.
#include "io_test_support.hpp"
#include "vtu_read_back.hpp"

#include "rkpm/io/vtu_writer.hpp"

#include <cstring>
#include <iostream>
#include <limits>

namespace rkpm::io::test {
namespace {

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

void expect_same_field(const PointField& written, const PointField& read) {
  ASSERT_EQ(read.components, written.components) << written.name;
  ASSERT_EQ(read.values.size(), written.values.size()) << written.name;
  for (std::size_t k = 0; k < written.values.size(); ++k) {
    ASSERT_EQ(bits(read.values[k]), bits(written.values[k])) << written.name << " value " << k;
  }
}

void expect_same_frame(const Frame& written, const ReadBack& read) {
  EXPECT_TRUE(read.points_are_float64);
  ASSERT_EQ(read.points.size(), written.points->size());
  for (std::size_t i = 0; i < read.points.size(); ++i) {
    for (int d = 0; d < 3; ++d) ASSERT_EQ(bits(read.points[i][d]), bits((*written.points)[i][d])) << i << "," << d;
  }
  EXPECT_EQ(read.cells.types, written.cells.types);
  EXPECT_EQ(read.cells.offsets, written.cells.offsets);
  EXPECT_EQ(read.cells.connectivity, written.cells.connectivity);
  ASSERT_EQ(read.point_fields.size(), written.point_fields.size());
  for (const PointField& f : written.point_fields) {
    ASSERT_EQ(read.point_fields.count(f.name), 1u) << f.name;
    expect_same_field(f, read.point_fields.at(f.name));
  }
  ASSERT_EQ(read.field_data.size(), written.field_data.size());
  for (const PointField& f : written.field_data) {
    ASSERT_EQ(read.field_data.count(f.name), 1u) << f.name;
    expect_same_field(f, read.field_data.at(f.name));
  }
}

using VtuWriter = ScratchDir;

TEST_F(VtuWriter, HexFrameReadsBackBitForBit) {
  const std::vector<Vec3> points = hex_block_points(11);
  Frame frame;
  frame.points = &points;
  frame.cells = hex_block_cells();
  frame.point_fields = sample_fields(points.size(), 12);
  frame.field_data.push_back({"TimeValue", 1, {0.123456789012345678}});
  frame.field_data.push_back({"energies", 2, {1.0 / 3.0, -2.0e-17}});

  const auto path = dir / "hex.vtu";
  write_vtu(path, frame);
  expect_same_frame(frame, read_vtu_back(path));
}

TEST_F(VtuWriter, PointsModeUsesOneVertexCellPerPoint) {
  const std::vector<Vec3> points = hex_block_points(21);
  Frame frame;
  frame.points = &points;
  frame.cells = vertex_cells(points.size());
  frame.point_fields = sample_fields(points.size(), 22);

  const auto path = dir / "cloud.vtu";
  write_vtu(path, frame);
  const ReadBack read = read_vtu_back(path);
  expect_same_frame(frame, read);
  ASSERT_EQ(read.cells.types.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(read.cells.types[i], 1);  // VTK_VERTEX
    EXPECT_EQ(read.cells.connectivity[i], static_cast<std::int64_t>(i));
  }
}

TEST_F(VtuWriter, FileIsAppendedRawBinaryAndZlibCompressed) {
  const std::vector<Vec3> points = hex_block_points(31);
  Frame frame;
  frame.points = &points;
  frame.cells = hex_block_cells();
  frame.point_fields = sample_fields(points.size(), 32);
  const auto path = dir / "format.vtu";
  write_vtu(path, frame);

  const std::string text = read_text(path);
  const std::string header = text.substr(0, text.find("<AppendedData"));
  EXPECT_NE(header.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos) << header;
  EXPECT_NE(header.find("header_type=\"UInt64\""), std::string::npos) << header;
  EXPECT_NE(header.find("format=\"appended\""), std::string::npos) << header;
  EXPECT_EQ(header.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(header.find("format=\"binary\""), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
  // Tensor fields are declared with 9 components so ParaView treats them as tensors.
  EXPECT_NE(header.find("Name=\"cauchy_stress\" NumberOfComponents=\"9\""), std::string::npos) << header;
}

TEST_F(VtuWriter, CompressionShrinksRedundantData) {
  // A resting cloud: zero stress everywhere. Raw, the arrays alone take
  // n * (3 + 9) doubles + n cells * (offset + connectivity + type); zlib must
  // collapse the constant tensor field to almost nothing.
  const std::size_t n = 5000;
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < n; ++i) points.emplace_back(0.5 * static_cast<double>(i), 0.0, 0.0);
  Frame frame;
  frame.points = &points;
  frame.cells = vertex_cells(n);
  frame.point_fields.push_back({"cauchy_stress", 9, std::vector<double>(9 * n, 0.0)});
  const auto path = dir / "resting.vtu";
  write_vtu(path, frame);
  const std::size_t raw_bytes = n * (3 + 9) * 8 + n * (8 + 8 + 1);
  const std::size_t file_bytes = std::filesystem::file_size(path);
  std::cout << "resting cloud: raw " << raw_bytes << " bytes, file " << file_bytes << " bytes\n";
  EXPECT_LT(file_bytes, raw_bytes / 4);
  expect_same_frame(frame, read_vtu_back(path));
}

TEST_F(VtuWriter, NonFiniteValueThrowsBeforeTouchingTheFile) {
  const std::vector<Vec3> points = hex_block_points(41);
  Frame frame;
  frame.points = &points;
  frame.cells = hex_block_cells();
  frame.point_fields = sample_fields(points.size(), 42);
  frame.point_fields[4].values[7 * 9 + 4] = std::numeric_limits<double>::quiet_NaN();  // cauchy_stress, particle 7
  const auto path = dir / "bad.vtu";
  EXPECT_THROW(write_vtu(path, frame), NonFiniteValue);
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST_F(VtuWriter, UnwritableDirectoryReportsThePath) {
  const std::vector<Vec3> points = hex_block_points(51);
  Frame frame;
  frame.points = &points;
  const auto path = dir / "no_such_dir" / "x.vtu";
  try {
    write_vtu(path, frame);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rkpm::io::test
