// Output that cannot be written, and a run killed with SIGKILL: the run ends with its
// own exit code and a message naming the file, the frames the .pvd lists stay
// readable, and a run resumed from the last checkpoint ends bit for bit like one that
// was never interrupted.
//
// A full disk is made with /dev/full (every write fails with ENOSPC): the file a run is
// about to write is a symbolic link to it.
#include "sim_fixtures.hpp"
#include "vtu_read_back.hpp"

#include "rkpm/io/pvd_series.hpp"
#include "rkpm/sim/run.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <sstream>
#include <thread>

namespace rkpm::sim {
namespace {

namespace fs = std::filesystem;

// A small block released from a stretch: 125 particles, a stable step of about 0.034 s,
// a frame every 4 s (about 120 steps), a checkpoint every 50 steps.
const std::string kBlock = R"([scene]
name = "output"
[integrator]
t_end = {t_end}
dt_safety = 0.4
[output]
every = 4
checkpoint_every = 50
[[body]]
name = "block"
density = 1000
[body.cloud]
generator = "block"
size = [1, 1, 1]
cells = [4, 4, 4]
[body.material]
model = "mooney_rivlin"
c1 = 400
lambda = 2000
[body.initial]
stretch = [1.05, 1, 1]
)";

struct RunResult {
  int code;
  std::string log;
};

RunResult run_in(const fs::path& dir, const std::string& text, const fs::path& restart = {}) {
  testing::write_text(dir / "scene.toml", text);
  const auto scene = scene::load_scene((dir / "scene.toml").string());
  RunOptions options;
  options.out_dir = dir / "out";
  options.restart = restart;
  options.quiet = true;
  std::ostringstream log;
  const int code = run_scene(scene, options, log);
  return {code, log.str()};
}

// Every frame the .pvd lists opens in VTK's reader.
void expect_listed_frames_readable(const fs::path& out, std::size_t at_least) {
  const auto entries = io::read_pvd(out / "frames.pvd");
  EXPECT_GE(entries.size(), at_least);
  for (const auto& e : entries) EXPECT_NO_THROW(io::test::read_vtu_back(out / e.file)) << e.file;
}

TEST(OutputFailure, UnwritableOutputFolderHasItsOwnExitCode) {
  const auto dir = testing::fresh_dir("unwritable");
  testing::write_text(dir / "a_file", "not a folder");
  testing::write_text(dir / "scene.toml", testing::with(kBlock, "t_end", "20"));
  const auto scene = scene::load_scene((dir / "scene.toml").string());
  RunOptions options;
  options.out_dir = dir / "a_file" / "out";  // a folder under a regular file cannot exist
  options.quiet = true;
  std::ostringstream log;
  EXPECT_EQ(run_scene(scene, options, log), kOutputFailed);
  EXPECT_NE(log.str().find("cannot create the output folder"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("a_file/out"), std::string::npos) << log.str();
}

TEST(OutputFailure, DiskFullOnAFrameEndsTheRunAndKeepsTheListedFrames) {
  const auto dir = testing::fresh_dir("full-frame");
  fs::create_directories(dir / "out");
  // The third frame's temporary file is the full disk.
  fs::create_symlink("/dev/full", dir / "out" / "frames_000002.vtu.tmp");
  ::testing::internal::CaptureStderr();
  const RunResult r = run_in(dir, testing::with(kBlock, "t_end", "20"));
  const std::string stderr_text = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(stderr_text.find("vtk"), std::string::npos) << "VTK's own report reached stderr:\n" << stderr_text;
  EXPECT_EQ(r.code, kOutputFailed) << r.log;
  EXPECT_NE(r.log.find("writing the output failed"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("frames_000002.vtu"), std::string::npos) << r.log;
  expect_listed_frames_readable(dir / "out", 2);
  EXPECT_EQ(io::read_pvd(dir / "out" / "frames.pvd").size(), 2u);
  EXPECT_NE(testing::read_text(dir / "out" / "summary.json").find("output failed"), std::string::npos);
}

TEST(OutputFailure, DiskFullOnHistoryEndsTheRunWithItsName) {
  const auto dir = testing::fresh_dir("full-history");
  fs::create_directories(dir / "out");
  fs::create_symlink("/dev/full", dir / "out" / "history.csv");
  const RunResult r = run_in(dir, testing::with(kBlock, "t_end", "20"));
  EXPECT_EQ(r.code, kOutputFailed) << r.log;
  EXPECT_NE(r.log.find("history.csv"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("disk full"), std::string::npos) << r.log;
}

// The rkpm program, as a child process that can be killed.
pid_t spawn_rkpm(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    std::string exe = RKPM_EXECUTABLE;
    argv.push_back(exe.data());
    std::vector<std::string> copy = args;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

int wait_exit_code(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

TEST(KillAndResume, ResumedRunEndsBitForBitLikeAnUninterruptedOne) {
  const auto dir = testing::fresh_dir("kill-resume");
  testing::write_text(dir / "scene.toml", testing::with(kBlock, "t_end", "300"));
  const std::string scene = (dir / "scene.toml").string();
  const auto whole = dir / "whole", killed = dir / "killed";
  ASSERT_EQ(wait_exit_code(spawn_rkpm({"run", scene, "--out", whole.string(), "--threads", "1", "--quiet"})), 0);

  // Kill the second run with SIGKILL once it has written a checkpoint and gone on.
  const pid_t pid = spawn_rkpm({"run", scene, "--out", killed.string(), "--threads", "1", "--quiet"});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(killed / "checkpoint.bin") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGKILL);
  const int killed_code = wait_exit_code(pid);
  ASSERT_EQ(killed_code, -SIGKILL) << "the run ended before it could be killed; lengthen t_end";
  ASSERT_FALSE(fs::exists(killed / "summary.json"));

  ASSERT_EQ(wait_exit_code(spawn_rkpm({"run", scene, "--out", killed.string(), "--threads", "1", "--quiet",
                                       "--restart", (killed / "checkpoint.bin").string()})),
            0);
  // Every frame, the series and the history are the same bytes.
  const auto frames = io::read_pvd(whole / "frames.pvd");
  ASSERT_EQ(io::read_pvd(killed / "frames.pvd").size(), frames.size());
  for (const auto& e : frames)
    EXPECT_EQ(testing::read_text(whole / e.file), testing::read_text(killed / e.file)) << e.file;
  EXPECT_EQ(testing::read_text(whole / "frames.pvd"), testing::read_text(killed / "frames.pvd"));
  EXPECT_EQ(testing::read_text(whole / "history.csv"), testing::read_text(killed / "history.csv"));
  EXPECT_EQ(testing::read_text(whole / "checkpoint.bin"), testing::read_text(killed / "checkpoint.bin"));
}

}  // namespace
}  // namespace rkpm::sim
