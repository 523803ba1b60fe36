// validate_frame is the gate that keeps NaN and malformed frames off disk.
#include "io_test_support.hpp"

#include <cmath>
#include <limits>

namespace rkpm::io::test {
namespace {

struct ValidFrame {
  std::vector<Vec3> points = hex_block_points(1);
  Frame frame;
  ValidFrame() {
    frame.points = &points;
    frame.cells = hex_block_cells();
    frame.point_fields = sample_fields(points.size(), 2);
  }
};

std::string message_of(const Frame& frame) {
  try {
    validate_frame(frame);
  } catch (const FrameError& e) {
    return e.what();
  }
  return "";
}

TEST(FrameValidation, SampleFrameIsValid) {
  ValidFrame f;
  EXPECT_NO_THROW(validate_frame(f.frame));
}

TEST(FrameValidation, NaNNamesFieldParticleComponentAndValue) {
  ValidFrame f;
  f.frame.point_fields[4].values[7 * 9 + 5] = std::numeric_limits<double>::quiet_NaN();  // cauchy_stress
  EXPECT_THROW(validate_frame(f.frame), NonFiniteValue);
  const std::string msg = message_of(f.frame);
  EXPECT_NE(msg.find("'cauchy_stress'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("particle 7"), std::string::npos) << msg;
  EXPECT_NE(msg.find("component 5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nan"), std::string::npos) << msg;
}

TEST(FrameValidation, InfinitePositionIsRejected) {
  ValidFrame f;
  f.points[3].y() = -std::numeric_limits<double>::infinity();
  EXPECT_THROW(validate_frame(f.frame), NonFiniteValue);
  const std::string msg = message_of(f.frame);
  EXPECT_NE(msg.find("particle 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("-inf"), std::string::npos) << msg;
}

TEST(FrameValidation, NonFiniteFieldDataIsRejected) {
  ValidFrame f;
  f.frame.field_data.push_back({"TimeValue", 1, {std::numeric_limits<double>::infinity()}});
  EXPECT_THROW(validate_frame(f.frame), NonFiniteValue);
}

TEST(FrameValidation, FieldSizeMustMatchPointCount) {
  ValidFrame f;
  f.frame.point_fields[0].values.pop_back();  // displacement now has 3n - 1 values
  EXPECT_THROW(validate_frame(f.frame), FrameError);
  ValidFrame g;
  g.frame.point_fields[2].values.push_back(0.0);  // body_id: n + 1 scalars
  const std::string msg = message_of(g.frame);
  EXPECT_NE(msg.find("'body_id'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected 18 points"), std::string::npos) << msg;
}

TEST(FrameValidation, BadComponentsAndNamesAreRejected) {
  ValidFrame f;
  f.frame.point_fields[1].components = 0;
  EXPECT_THROW(validate_frame(f.frame), FrameError);
  ValidFrame g;
  g.frame.point_fields[1].name = "displacement";  // duplicate
  EXPECT_NE(message_of(g.frame).find("appears twice"), std::string::npos);
  ValidFrame h;
  h.frame.point_fields[1].name.clear();
  EXPECT_THROW(validate_frame(h.frame), FrameError);
}

TEST(FrameValidation, CellsMustBeConsistent) {
  ValidFrame bad_index;
  bad_index.frame.cells.connectivity[5] = 18;  // one past the last point
  EXPECT_THROW(validate_frame(bad_index.frame), FrameError);
  ValidFrame negative;
  negative.frame.cells.connectivity[0] = -1;
  EXPECT_THROW(validate_frame(negative.frame), FrameError);
  ValidFrame short_offsets;
  short_offsets.frame.cells.offsets.pop_back();
  EXPECT_THROW(validate_frame(short_offsets.frame), FrameError);
  ValidFrame decreasing;
  decreasing.frame.cells.offsets[1] = 20;  // 0, 20, 16, ...
  EXPECT_THROW(validate_frame(decreasing.frame), FrameError);
  ValidFrame missing_points;
  missing_points.frame.points = nullptr;
  EXPECT_THROW(validate_frame(missing_points.frame), FrameError);
}

TEST(FrameValidation, VertexCellsCoverEveryPointOnce) {
  const CellBlock cells = vertex_cells(4);
  EXPECT_EQ(cells.types, (std::vector<std::uint8_t>{1, 1, 1, 1}));
  EXPECT_EQ(cells.offsets, (std::vector<std::int64_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(cells.connectivity, (std::vector<std::int64_t>{0, 1, 2, 3}));
  EXPECT_EQ(vertex_cells(0).offsets, (std::vector<std::int64_t>{0}));
}

}  // namespace
}  // namespace rkpm::io::test
