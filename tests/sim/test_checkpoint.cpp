// Checkpoints with named, versioned fields: a checkpoint is only loaded into the
// scene, bodies, particle counts and terms it was written for, and a file of another
// format version, a truncated or a corrupt file is refused with the file named; the
// run then exits with the bad-input code. (The bit-for-bit restart itself is in
// test_run_loop.cpp.)
#include "sim_fixtures.hpp"

#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/checkpoint.hpp"
#include "rkpm/sim/run.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>

namespace rkpm::sim {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::with;
using testing::write_text;

const std::string kCube = R"([scene]
name = "{name}"
[integrator]
t_end = 1.0
[output]
every = 1.0
checkpoint_every = 5
[[body]]
name = "{body}"
[body.cloud]
generator = "block"
size = [1e-5, 1e-5, 1e-5]
cells = [{cells}, 3, 3]
[body.material]
model = "mooney_rivlin"
c1 = 400
lambda = 4000
[body.initial]
stretch = [1.05, 1.0, 1.0]
[[body.boundary]]
surface = "zmin"
)";

const std::string kGravity = R"([[term]]
type = "body_force"
body = "cube"
acceleration = [0, 0, -1e3]
)";

std::string cube(const std::string& name = "cube_scene", int cells = 3, const std::string& body = "cube") {
  return with(with(with(kCube, "name", name), "cells", std::to_string(cells)), "body", body);
}

struct RunResult {
  int code = -1;
  std::string log;
};

RunResult run_file(const fs::path& scene_file, const fs::path& out, std::int64_t max_steps,
                   const fs::path& restart = {}) {
  const scene::Scene scene = scene::load_scene(scene_file.string());
  RunOptions options;
  options.out_dir = out;
  options.restart = restart;
  options.max_steps_override = max_steps;
  options.quiet = true;
  std::ostringstream log;
  RunResult r;
  r.code = run_scene(scene, options, log);
  r.log = log.str();
  return r;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A checkpoint of the cube scene after 10 steps, in `dir`/first.
fs::path cube_checkpoint(const fs::path& dir) {
  write_text(dir / "cube.toml", cube());
  const RunResult r = run_file(dir / "cube.toml", dir / "first", 10);
  if (r.code != kSuccess) throw std::runtime_error("the first run failed: " + r.log);
  fs::copy_file(dir / "first" / "checkpoint.bin", dir / "step10.bin");
  return dir / "step10.bin";
}

// Restarts the cube scene from `checkpoint`, expecting the bad-input exit code and a
// message naming the checkpoint and containing `why`.
void expect_refused(const fs::path& dir, const fs::path& checkpoint, const std::string& why,
                    const std::string& scene_file = "cube.toml") {
  const RunResult r = run_file(dir / scene_file, dir / "again", 20, checkpoint);
  std::printf("restart from %s: exit code %d; log: %s", checkpoint.filename().string().c_str(), r.code, r.log.c_str());
  EXPECT_EQ(r.code, kBadInput);
  EXPECT_TRUE(contains(r.log, "error: checkpoint " + checkpoint.string() + ": ")) << r.log;
  EXPECT_TRUE(contains(r.log, why)) << r.log;
}

TEST(StateRecord, FieldsAreFoundByNameAndAMissingOrMisSizedOneIsNamed) {
  StateRecord r;
  r.put_real("dt", 1.5e-9);
  r.put_integer("step", -42);
  r.put_reals("targets", {1.0, 2.0, 3.0});
  r.put_vectors("d", {Vec3(1, 2, 3), Vec3(4, 5, 6)});
  r.put_text("names", "a\nb");
  EXPECT_EQ(r.real("dt"), 1.5e-9);
  EXPECT_EQ(r.integer("step"), -42);
  EXPECT_EQ(r.reals("targets", 3), (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_EQ(r.vectors("d", 2)[1], Vec3(4, 5, 6));
  EXPECT_EQ(r.text("names"), "a\nb");

  auto message = [](auto&& read) {
    try {
      read();
    } catch (const StateError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([&] { r.real("time"); }), "field 'time' is missing");
  EXPECT_EQ(message([&] { r.reals("targets", 4); }), "field 'targets' has 3 values, expected 4");
  EXPECT_EQ(message([&] { r.vectors("d", 3); }), "field 'd' has 2 vectors, expected 3");
  EXPECT_EQ(message([&] { r.real("step"); }), "field 'step' holds integer x 1 values, expected real x 1");
  EXPECT_EQ(message([&] { r.reals("d"); }), "field 'd' holds real x 3 values, expected real x 1");
  EXPECT_EQ(message([&] { r.real("targets"); }), "field 'targets' has 3 values, expected 1");

  StateRecord outer;
  outer.put_record("integrator.", r);
  EXPECT_TRUE(outer.has("integrator.dt"));
  EXPECT_FALSE(outer.has("dt"));
  const StateRecord inner = outer.record("integrator.");
  EXPECT_EQ(inner.size(), r.size());
  EXPECT_EQ(inner.real("dt"), 1.5e-9);
}

TEST(StateRecord, IntegratorStateIsNamed) {
  testing::ScopedThreads one(1);
  auto sw = testing::build_from_text(cube());
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  const StateRecord saved = integrator.save_state();
  for (const char* name : {"dt", "stable_dt", "ledger.initial", "fire.alpha", "fire.positive_steps", "centre"})
    EXPECT_TRUE(saved.has(name)) << name;
  StateRecord without_alpha;
  for (const auto& [name, field] : saved.fields())
    if (name != "fire.alpha") without_alpha.put_field(name, field);
  try {
    integrator.load_state(without_alpha);
    ADD_FAILURE() << "a missing field was accepted";
  } catch (const StateError& e) {
    EXPECT_STREQ(e.what(), "field 'fire.alpha' is missing");
  }
}

TEST(Checkpoint, ResumesTheSceneItWasWrittenFor) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("checkpoint_ok");
  const fs::path checkpoint = cube_checkpoint(dir);
  const RunResult r = run_file(dir / "cube.toml", dir / "first", 20, checkpoint);
  EXPECT_EQ(r.code, kSuccess) << r.log;
  fs::remove_all(dir);
}

TEST(Checkpoint, OfAnotherSceneIsRefusedWithExitCode2) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("checkpoint_scene");
  const fs::path checkpoint = cube_checkpoint(dir);
  write_text(dir / "other.toml", cube("other_scene"));
  expect_refused(dir, checkpoint, "written for another scene", "other.toml");
  fs::remove_all(dir);
}

TEST(Checkpoint, TruncatedFileIsRefusedWithExitCode2) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("checkpoint_truncated");
  const fs::path checkpoint = cube_checkpoint(dir);
  const std::string bytes = read_text(checkpoint);
  write_text(dir / "half.bin", bytes.substr(0, bytes.size() / 2));
  expect_refused(dir, dir / "half.bin", "truncated");
  write_text(dir / "short.bin", bytes.substr(0, bytes.size() - 3));  // cut inside the closing digest
  expect_refused(dir, dir / "short.bin", "the file ends early");
  write_text(dir / "empty.bin", "");
  expect_refused(dir, dir / "empty.bin", "not an rkpm checkpoint");
  fs::remove_all(dir);
}

TEST(Checkpoint, CorruptFileIsRefusedWithExitCode2) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("checkpoint_corrupt");
  const fs::path checkpoint = cube_checkpoint(dir);
  std::string bytes = read_text(checkpoint);
  bytes[bytes.size() / 2] ^= 0x10;  // one bit of a stored value
  write_text(dir / "flipped.bin", bytes);
  expect_refused(dir, dir / "flipped.bin", "the file is corrupt");
  std::string header = read_text(checkpoint);
  header[2] = 'X';
  write_text(dir / "header.bin", header);
  expect_refused(dir, dir / "header.bin", "not an rkpm checkpoint (bad header)");
  fs::remove_all(dir);
}

TEST(Checkpoint, AnotherFormatVersionIsRefusedWithExitCode2) {
  testing::ScopedThreads one(1);
  const fs::path dir = testing::fresh_dir("checkpoint_version");
  const fs::path checkpoint = cube_checkpoint(dir);
  std::string bytes = read_text(checkpoint);
  const std::uint32_t version = 2;  // before the inertia (mass scaling) was saved
  std::memcpy(&bytes[8], &version, sizeof version);  // after the 8-byte magic
  write_text(dir / "v2.bin", bytes);
  expect_refused(dir, dir / "v2.bin", "checkpoint format version 2; this build reads version 7");
  // The format before versions and names: positional fields.
  std::string old = read_text(checkpoint);
  old[7] = '1';
  write_text(dir / "v1.bin", old);
  expect_refused(dir, dir / "v1.bin", "written in checkpoint format 1");
  fs::remove_all(dir);
}

// The scene digest is not the only guard: a world of the same scene digest but other
// particle counts, bodies or terms is refused by the reader itself, naming what differs.
// `forge` may alter the written world and clock before they are written.
std::string read_into(const std::string& written_toml, const std::string& read_toml, const fs::path& file,
                      const std::function<void(World&, RunClock&)>& forge = {}) {
  testing::ScopedThreads one(1);
  constexpr std::uint64_t kDigest = 0x1234;
  {
    auto sw = testing::build_from_text(written_toml);
    Integrator integrator(*sw.world, sw.settings);
    integrator.initialize();
    integrator.step();
    RunClock clock;
    if (forge) forge(*sw.world, clock);
    write_checkpoint(file, *sw.world, integrator, clock, kDigest);
  }
  auto sw = testing::build_from_text(read_toml);
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  RunClock clock;
  try {
    read_checkpoint(file, *sw.world, integrator, clock, kDigest);
  } catch (const std::runtime_error& e) {
    std::printf("%s\n", e.what());
    return e.what();
  }
  return "no error";
}

TEST(Checkpoint, AnotherParticleCountBodyListOrTermListIsNamed) {
  const fs::path dir = testing::fresh_dir("checkpoint_world");
  const fs::path file = dir / "state.bin";
  const std::string prefix = "checkpoint " + file.string() + ": ";
  EXPECT_EQ(read_into(cube(), cube("cube_scene", 4), file),
            prefix + "body 'cube' has 64 particles in the checkpoint, 80 in the scene");
  EXPECT_EQ(read_into(cube(), cube("cube_scene", 3, "block"), file),
            prefix + "the bodies differ: the checkpoint has cube, the scene has block");
  EXPECT_EQ(read_into(cube(), cube() + kGravity, file),
            prefix + "the terms differ: the checkpoint has none, the scene has body_force");
  EXPECT_EQ(read_into(cube(), cube(), file), "no error");
  fs::remove_all(dir);
}

// A damaged or forged clock would loop or overflow the step counter: refused, named.
TEST(Checkpoint, ANegativeStepOrANonFiniteClockIsRefused) {
  const fs::path dir = testing::fresh_dir("checkpoint_clock");
  const fs::path file = dir / "state.bin";
  const std::string prefix = "checkpoint " + file.string() + ": ";
  EXPECT_EQ(read_into(cube(), cube(), file, [](World& w, RunClock&) { w.step = -4611686018427387904; }),
            prefix + "its step is -4611686018427387904, expected 0 or more");
  EXPECT_EQ(read_into(cube(), cube(), file, [](World&, RunClock& c) { c.frames = -1; }),
            prefix + "its frame count is -1, expected 0 or more");
  EXPECT_EQ(read_into(cube(), cube(), file,
                      [](World& w, RunClock&) { w.time = std::numeric_limits<double>::infinity(); }),
            prefix + "its time is inf, expected a finite value of 0 or more");
  EXPECT_EQ(read_into(cube(), cube(), file,
                      [](World&, RunClock& c) { c.next_output = std::numeric_limits<double>::quiet_NaN(); }),
            prefix + "its next output time is nan, expected a finite value");
  fs::remove_all(dir);
}

// Forged state (found with fuzz_checkpoint): a NaN or an infinity in any real field, a
// non-positive mass, would reach the output through the run; refused, named.
TEST(Checkpoint, ANonFiniteValueOrANonPositiveMassIsRefused) {
  const fs::path dir = testing::fresh_dir("checkpoint_values");
  const fs::path file = dir / "state.bin";
  const std::string prefix = "checkpoint " + file.string() + ": ";
  EXPECT_EQ(read_into(cube(), cube(), file,
                      [](World& w, RunClock&) { w.bodies[0]->v[7].y() = std::numeric_limits<double>::quiet_NaN(); }),
            prefix + "field 'body.cube.v' holds nan at value 22, expected a finite number");
  EXPECT_EQ(read_into(cube(), cube(), file,
                      [](World& w, RunClock&) { w.bodies[0]->d[0].x() = -std::numeric_limits<double>::infinity(); }),
            prefix + "field 'body.cube.d' holds -inf at value 0, expected a finite number");
  EXPECT_EQ(read_into(cube(), cube(), file, [](World& w, RunClock&) { w.bodies[0]->inertia[3] = 0.0; }),
            prefix + "body 'cube' particle 3 has inertia 0, expected a positive mass");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rkpm::sim
