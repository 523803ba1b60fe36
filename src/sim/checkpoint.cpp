#include "rkpm/sim/checkpoint.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace rkpm::sim {

namespace {

constexpr char kMagic[8] = {'R', 'K', 'P', 'M', 'C', 'K', 'P', '1'};

class Writer {
 public:
  explicit Writer(std::ofstream& out) : out_(out) {}
  template <class T>
  void value(const T& v) { out_.write(reinterpret_cast<const char*>(&v), sizeof(T)); }
  template <class T>
  void array(const std::vector<T>& v) {
    value<std::uint64_t>(v.size());
    out_.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
  }

 private:
  std::ofstream& out_;
};

class Reader {
 public:
  Reader(std::ifstream& in, std::string file) : in_(in), file_(std::move(file)) {}
  template <class T>
  T value() {
    T v{};
    in_.read(reinterpret_cast<char*>(&v), sizeof(T));
    if (!in_) fail("file ends early");
    return v;
  }
  template <class T>
  void array(std::vector<T>& v, std::size_t expected, const char* what) {
    const auto n = value<std::uint64_t>();
    if (n != expected) fail(fmt::format("{} has {} entries, the scene has {}", what, n, expected));
    v.resize(n);
    in_.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
    if (!in_) fail("file ends early");
  }
  template <class T>
  std::vector<T> array() {
    const auto n = value<std::uint64_t>();
    if (n > (1u << 30)) fail("corrupt array length");
    std::vector<T> v(n);
    in_.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
    if (!in_) fail("file ends early");
    return v;
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(fmt::format("checkpoint {}: {}", file_, why));
  }

 private:
  std::ifstream& in_;
  std::string file_;
};

}  // namespace

std::uint64_t file_digest(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) {
    h ^= static_cast<unsigned char>(*it);
    h *= 0x100000001b3ULL;
  }
  return h;
}

void write_checkpoint(const std::filesystem::path& path, const World& world, const Integrator& integrator,
                      const RunClock& clock, std::uint64_t scene_digest) {
  const auto tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(fmt::format("checkpoint {}: cannot open for writing", tmp));
    Writer w(out);
    out.write(kMagic, sizeof kMagic);
    w.value(scene_digest);
    w.value(world.time);
    w.value(world.step);
    w.value(clock.next_output);
    w.value(clock.frames);
    w.array(integrator.save_state());
    w.value<std::uint64_t>(world.bodies.size());
    for (const auto& b : world.bodies) {
      w.array(b->d);
      w.array(b->v);
      w.array(b->a);
      w.array(b->director ? b->director->h : std::vector<Vec3>{});
      w.array(b->constraints.targets());
    }
    w.value<std::uint64_t>(world.terms.size());
    for (const auto& t : world.terms) w.array(t->save_state());
    out.flush();
    if (!out) throw std::runtime_error(fmt::format("checkpoint {}: write failed", tmp));
  }
  std::filesystem::rename(tmp, path);
}

void read_checkpoint(const std::filesystem::path& path, World& world, Integrator& integrator, RunClock& clock,
                     std::uint64_t scene_digest) {
  std::ifstream in(path, std::ios::binary);
  Reader r(in, path.string());
  if (!in) r.fail("cannot open");
  char magic[8];
  in.read(magic, sizeof magic);
  if (!in || !std::equal(magic, magic + 8, kMagic)) r.fail("not an rkpm checkpoint (bad header)");
  if (r.value<std::uint64_t>() != scene_digest) r.fail("written for a different scene file (its content changed)");
  world.time = r.value<double>();
  world.step = r.value<std::int64_t>();
  clock.next_output = r.value<double>();
  clock.frames = r.value<std::int64_t>();
  const auto integrator_state = r.array<double>();
  if (r.value<std::uint64_t>() != world.bodies.size()) r.fail("number of bodies differs from the scene");
  for (auto& b : world.bodies) {
    r.array(b->d, b->size(), "displacement");
    r.array(b->v, b->size(), "velocity");
    r.array(b->a, b->size(), "acceleration");
    std::vector<Vec3> h;
    r.array(h, b->director ? b->size() : 0, "director");
    if (b->director) b->director->h = std::move(h);
    b->constraints.set_targets(r.array<double>());
    update_positions(*b);
  }
  if (r.value<std::uint64_t>() != world.terms.size()) r.fail("number of terms differs from the scene");
  for (auto& t : world.terms) t->load_state(r.array<double>());
  // Forces, F and P at the restored state (deterministic: the same as when written).
  compute_forces(world);
  for (auto& b : world.bodies) b->constraints.transform_forces(b->force);
  integrator.load_state(integrator_state);
}

}  // namespace rkpm::sim
