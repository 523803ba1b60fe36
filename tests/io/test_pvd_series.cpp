// The time series: numbering, the .pvd listing, crash safety (a rejected frame
// leaves every file as it was), and resuming after a restart.
#include "io_test_support.hpp"
#include "vtu_read_back.hpp"

#include "rkpm/io/atomic_file.hpp"
#include "rkpm/io/pvd_series.hpp"

#include <limits>
#include <map>
#include <regex>

namespace rkpm::io::test {
namespace {

// Parses the .pvd with a regular expression, independently of read_pvd.
std::vector<std::pair<double, std::string>> pvd_listing(const std::filesystem::path& pvd) {
  const std::string text = read_text(pvd);
  const std::regex dataset(R"re(<DataSet\s+timestep="([^"]*)"\s+group=""\s+part="0"\s+file="([^"]*)"\s*/>)re");
  std::vector<std::pair<double, std::string>> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset); it != std::sregex_iterator(); ++it) {
    out.emplace_back(std::stod((*it)[1]), (*it)[2]);
  }
  return out;
}

struct Cloud {
  std::vector<Vec3> points = hex_block_points(7);
  Frame frame_at(double time) const {
    Frame f;
    f.points = &points;
    f.cells = hex_block_cells();
    f.point_fields = sample_fields(points.size(), 8);
    f.point_fields[0].values.assign(f.point_fields[0].values.size(), time);  // tag each frame
    f.field_data.push_back({"TimeValue", 1, {time}});
    return f;
  }
};

bool has_temporaries(const std::filesystem::path& dir) {
  for (const std::string& name : file_names(dir)) {
    if (name.find(".tmp") != std::string::npos) return true;
  }
  return false;
}

using PvdSeriesTest = ScratchDir;

TEST_F(PvdSeriesTest, ListsEveryFrameInOrderWithItsTime) {
  Cloud cloud;
  PvdSeries series(dir / "out", "cell");
  const std::vector<double> times = {0.0, 0.1, 0.30000000000000004};
  for (double t : times) series.write(t, cloud.frame_at(t));

  EXPECT_EQ(series.frames_written(), 3);
  EXPECT_EQ(series.pvd_path(), dir / "out" / "cell.pvd");
  const auto listing = pvd_listing(series.pvd_path());
  ASSERT_EQ(listing.size(), 3u);
  for (std::size_t k = 0; k < times.size(); ++k) {
    EXPECT_EQ(listing[k].first, times[k]);  // printed precisely enough to read back exactly
    EXPECT_EQ(listing[k].second, "cell_00000" + std::to_string(k) + ".vtu");
    const ReadBack frame = read_vtu_back(dir / "out" / listing[k].second);
    EXPECT_EQ(frame.field_data.at("TimeValue").values, std::vector<double>{times[k]});
    EXPECT_EQ(frame.point_fields.at("displacement").values.front(), times[k]);
  }
  EXPECT_EQ(read_pvd(series.pvd_path()).size(), 3u);
  EXPECT_FALSE(has_temporaries(dir / "out"));
}

TEST_F(PvdSeriesTest, NewSeriesStartsWithAnEmptyListing) {
  PvdSeries series(dir, "empty");
  EXPECT_TRUE(std::filesystem::exists(series.pvd_path()));
  EXPECT_TRUE(pvd_listing(series.pvd_path()).empty());
  EXPECT_EQ(series.frames_written(), 0);
}

TEST_F(PvdSeriesTest, RejectedFrameLeavesFilesUntouched) {
  Cloud cloud;
  PvdSeries series(dir, "cell");
  series.write(0.0, cloud.frame_at(0.0));
  series.write(1.0, cloud.frame_at(1.0));
  const std::string pvd_before = read_text(series.pvd_path());
  const std::string frame1_before = read_text(series.frame_path(1));
  const auto names_before = file_names(dir);

  Frame bad = cloud.frame_at(2.0);
  bad.point_fields[1].values[3 * 5 + 2] = std::numeric_limits<double>::quiet_NaN();  // velocity, particle 5
  try {
    series.write(2.0, bad);
    FAIL() << "NaN frame was accepted";
  } catch (const NonFiniteValue& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'velocity'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("particle 5"), std::string::npos) << msg;
  }
  Frame wrong_size = cloud.frame_at(2.0);
  wrong_size.point_fields[3].values.resize(4);
  EXPECT_THROW(series.write(2.0, wrong_size), FrameError);
  EXPECT_THROW(series.write(1.0, cloud.frame_at(1.0)), FrameError);  // time not increasing
  EXPECT_THROW(series.write(std::numeric_limits<double>::infinity(), cloud.frame_at(0.0)), NonFiniteValue);

  EXPECT_EQ(read_text(series.pvd_path()), pvd_before);
  EXPECT_EQ(read_text(series.frame_path(1)), frame1_before);
  EXPECT_EQ(file_names(dir), names_before);
  EXPECT_EQ(series.frames_written(), 2);

  // The series carries on with the next number after the last good frame.
  EXPECT_EQ(series.write(2.0, cloud.frame_at(2.0)), series.frame_path(2));
  EXPECT_EQ(pvd_listing(series.pvd_path()).size(), 3u);
}

TEST_F(PvdSeriesTest, InterruptedWriteLeavesPvdListingOnlyCompleteFrames) {
  // What a kill during a frame write leaves: a partial temporary next to the
  // listed frames. The .pvd never names it, and every listed frame reads.
  Cloud cloud;
  {
    PvdSeries series(dir, "cell");
    series.write(0.0, cloud.frame_at(0.0));
    series.write(0.5, cloud.frame_at(0.5));
    std::ofstream(temporary_path_for(series.frame_path(2))) << "<?xml version=\"1.0\"?><VTKFile type=\"Unstr";
  }
  const auto listing = pvd_listing(dir / "cell.pvd");
  ASSERT_EQ(listing.size(), 2u);
  for (const auto& [t, file] : listing) EXPECT_EQ(read_vtu_back(dir / file).points.size(), cloud.points.size());

  // A restart replaces the partial temporary with a complete frame.
  PvdSeries resumed = PvdSeries::resume(dir, "cell", 0.5);
  resumed.write(1.0, cloud.frame_at(1.0));
  EXPECT_FALSE(has_temporaries(dir));
  EXPECT_EQ(read_vtu_back(resumed.frame_path(2)).field_data.at("TimeValue").values, std::vector<double>{1.0});
}

TEST_F(PvdSeriesTest, ResumeKeepsEarlierFramesAndContinuesNumbering) {
  Cloud cloud;
  {
    PvdSeries series(dir, "cell");
    for (double t : {0.0, 1.0, 2.0, 3.0}) series.write(t, cloud.frame_at(t));
  }
  PvdSeries resumed = PvdSeries::resume(dir, "cell", 1.5);
  EXPECT_EQ(resumed.frames_written(), 2);
  auto listing = pvd_listing(resumed.pvd_path());
  ASSERT_EQ(listing.size(), 2u);
  EXPECT_EQ(listing[1].second, "cell_000001.vtu");
  // The abandoned future (t = 2, 3) is gone from the listing and from disk.
  EXPECT_FALSE(std::filesystem::exists(dir / "cell_000002.vtu"));
  EXPECT_FALSE(std::filesystem::exists(dir / "cell_000003.vtu"));

  EXPECT_EQ(resumed.write(1.75, cloud.frame_at(1.75)), dir / "cell_000002.vtu");
  EXPECT_THROW(resumed.write(1.0, cloud.frame_at(1.0)), FrameError);  // before the kept frames
  listing = pvd_listing(resumed.pvd_path());
  ASSERT_EQ(listing.size(), 3u);
  EXPECT_EQ(listing[2].first, 1.75);
  EXPECT_EQ(listing[2].second, "cell_000002.vtu");
}

TEST_F(PvdSeriesTest, ResumeAtExactFrameTimeKeepsThatFrame) {
  Cloud cloud;
  {
    PvdSeries series(dir, "cell");
    for (double t : {0.0, 0.1, 0.2}) series.write(t, cloud.frame_at(t));
  }
  EXPECT_EQ(PvdSeries::resume(dir, "cell", 0.1).frames_written(), 2);
}

TEST_F(PvdSeriesTest, ResumeReportsMissingFiles) {
  EXPECT_THROW(PvdSeries::resume(dir, "nothing", 1.0), std::runtime_error);
  Cloud cloud;
  {
    PvdSeries series(dir, "cell");
    series.write(0.0, cloud.frame_at(0.0));
  }
  std::filesystem::remove(dir / "cell_000000.vtu");
  try {
    PvdSeries::resume(dir, "cell", 1.0);
    FAIL() << "resume accepted a listing with a missing frame";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cell_000000.vtu"), std::string::npos) << e.what();
  }
}

TEST_F(PvdSeriesTest, BasenameMustBeAPlainName) {
  EXPECT_THROW(PvdSeries(dir, ""), std::invalid_argument);
  EXPECT_THROW(PvdSeries(dir, "a/b"), std::invalid_argument);
  EXPECT_THROW(PvdSeries(dir, "a\"b"), std::invalid_argument);
}

TEST_F(PvdSeriesTest, ReadPvdParsesAttributesInAnyOrder) {
  const auto pvd = dir / "hand.pvd";
  std::ofstream(pvd) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n"
                        "<DataSet part='0' file='a_000000.vtu' timestep='2.5e-3'/>\n"
                        "<DataSet timestep = \"7\" file=\"a_000001.vtu\" />\n</Collection>\n</VTKFile>\n";
  const auto entries = read_pvd(pvd);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].time, 2.5e-3);
  EXPECT_EQ(entries[0].file, "a_000000.vtu");
  EXPECT_EQ(entries[1].time, 7.0);
  EXPECT_EQ(entries[1].file, "a_000001.vtu");

  std::ofstream(pvd) << "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"x\" file=\"a.vtu\"/>";
  EXPECT_THROW(read_pvd(pvd), std::runtime_error);
}

TEST_F(PvdSeriesTest, ReplaceAtomicallyKeepsTargetWhenWriterFails) {
  const auto target = dir / "summary.json";
  write_text_atomically(target, "old");
  EXPECT_THROW(replace_atomically(target,
                                  [](const std::filesystem::path& tmp) {
                                    std::ofstream(tmp) << "half written";
                                    throw std::runtime_error("disk full");
                                  }),
               std::runtime_error);
  EXPECT_EQ(read_text(target), "old");
  EXPECT_FALSE(has_temporaries(dir));
}

}  // namespace
}  // namespace rkpm::io::test
