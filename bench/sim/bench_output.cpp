// Output of one frame of the RBC scene: assembling the frame from the world
// (physical positions, stresses, director) and writing it as a compressed .vtu.
#include "counters.hpp"
#include "fixtures.hpp"

#include "rkpm/io/vtu_writer.hpp"
#include "rkpm/sim/output.hpp"

#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace rkpm::bench {

namespace {

namespace fs = std::filesystem;

// A directory of our own under the system's temporary directory, removed at exit.
struct ScratchDir {
  fs::path path = fs::temp_directory_path() / ("rkpm-bench-" + std::to_string(::getpid()));
  ScratchDir() { fs::create_directories(path); }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

void BM_MakeFrame_RBC(benchmark::State& state) {
  SceneFixture& f = rbc_fixture();
  std::vector<Vec3> positions;
  for (auto _ : state) {
    io::Frame frame = sim::make_frame(*f.world, sim::CellOutput::Mesh, positions);
    benchmark::DoNotOptimize(frame.point_fields.data());
  }
  set_counters(state, static_cast<double>(f.world->particle_count()), 0.0, bytes_per_particle(*f.world));
}
BENCHMARK(BM_MakeFrame_RBC)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WriteFrame_RBC(benchmark::State& state) {
  SceneFixture& f = rbc_fixture();
  const ScratchDir dir;
  const fs::path file = dir.path / "frame.vtu";
  std::vector<Vec3> positions;
  const io::Frame frame = sim::make_frame(*f.world, sim::CellOutput::Mesh, positions);
  for (auto _ : state) io::write_vtu(file, frame);
  const auto size = static_cast<double>(fs::file_size(file));
  set_counters(state, static_cast<double>(f.world->particle_count()), 0.0, bytes_per_particle(*f.world));
  state.counters["file_bytes"] = size;
  state.counters["write_rate"] =
      benchmark::Counter(size, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_WriteFrame_RBC)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

}  // namespace rkpm::bench
