#include "rkpm/sim/checkpoint.hpp"

#include "rkpm/sim/body_state.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rkpm::sim {

namespace {

// File layout (native byte order):
//   magic "RKPMCKPT", u32 format version, u64 number of fields,
//   per field: u32 name length, name, u8 type, u32 components, u64 count, the values,
//   u64 FNV-1a digest of every byte before it.
constexpr char kMagic[8] = {'R', 'K', 'P', 'M', 'C', 'K', 'P', 'T'};
constexpr char kMagicFormat1[8] = {'R', 'K', 'P', 'M', 'C', 'K', 'P', '1'};  // positional fields, no version
constexpr std::uint32_t kFormatVersion = 7;  // 3: the inertia (mass scaling) per body; 4: the stable step's
                                             // calibration; 5: the rank and rank count; 6: each body's
                                             // forces instead of its accelerations; 7: the ledger's
                                             // material-state entry named ledger.state (any material's)

std::uint64_t fnv1a(const char* data, std::size_t n) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::size_t element_size(StateRecord::Type type) { return type == StateRecord::Type::Text ? 1 : 8; }

template <class T>
void append(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

std::string encode(const StateRecord& record) {
  std::string out(kMagic, sizeof kMagic);
  append(out, kFormatVersion);
  append<std::uint64_t>(out, record.size());
  for (const auto& [name, f] : record.fields()) {
    append<std::uint32_t>(out, static_cast<std::uint32_t>(name.size()));
    out += name;
    append(out, static_cast<std::uint8_t>(f.type));
    append(out, f.components);
    append(out, f.count);
    out += f.bytes;
  }
  append(out, fnv1a(out.data(), out.size()));
  return out;
}

class Decoder {
 public:
  Decoder(const std::string& bytes, std::string file) : bytes_(bytes), file_(std::move(file)) {}

  StateRecord decode() {
    if (bytes_.size() < sizeof kMagic) fail("not an rkpm checkpoint (the file is too short for a header)");
    if (std::memcmp(bytes_.data(), kMagicFormat1, sizeof kMagic) == 0)
      fail(fmt::format("written in checkpoint format 1 (positional fields); this build reads format {}",
                       kFormatVersion));
    if (std::memcmp(bytes_.data(), kMagic, sizeof kMagic) != 0) fail("not an rkpm checkpoint (bad header)");
    pos_ = sizeof kMagic;
    const auto version = value<std::uint32_t>("the format version");
    if (version != kFormatVersion)
      fail(fmt::format("checkpoint format version {}; this build reads version {}", version, kFormatVersion));
    const auto n = value<std::uint64_t>("the number of fields");
    StateRecord record;
    for (std::uint64_t k = 0; k < n; ++k) {
      const std::string where = fmt::format("field {} of {}", k + 1, n);
      const auto name_length = value<std::uint32_t>(where);
      if (name_length == 0 || name_length > 4096) fail(fmt::format("{}: corrupt name length {}", where, name_length));
      std::string name = take(name_length, where);
      StateRecord::Field f;
      const auto type = value<std::uint8_t>(name);
      if (type < 1 || type > 3) fail(fmt::format("field '{}': unknown type code {}", name, type));
      f.type = static_cast<StateRecord::Type>(type);
      f.components = value<std::uint32_t>(name);
      f.count = value<std::uint64_t>(name);
      const std::size_t left = bytes_.size() - pos_;
      const std::size_t unit = element_size(f.type);
      if (f.components == 0 || f.components > 16 || f.count > left / (unit * f.components))
        fail(fmt::format("field '{}': {} x {} values do not fit in the file (truncated or corrupt)", name,
                         f.count, f.components));
      f.bytes = take(f.count * f.components * unit, name);
      if (record.has(name)) fail(fmt::format("field '{}' appears twice", name));
      record.put_field(name, std::move(f));
    }
    const std::size_t body_end = pos_;
    const auto stored = value<std::uint64_t>("the closing digest");
    if (pos_ != bytes_.size()) fail(fmt::format("{} unexpected bytes after the last field", bytes_.size() - pos_));
    if (stored != fnv1a(bytes_.data(), body_end)) fail("the content does not match its digest (the file is corrupt)");
    return record;
  }

  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(fmt::format("checkpoint {}: {}", file_, why));
  }

 private:
  template <class T>
  T value(const std::string& what) {
    T v{};
    std::memcpy(&v, take(sizeof(T), what).data(), sizeof(T));
    return v;
  }
  std::string take(std::size_t n, const std::string& what) {
    if (n > bytes_.size() - pos_) fail(fmt::format("the file ends early, in {} (truncated?)", what));
    std::string s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }

  const std::string& bytes_;
  std::string file_;
  std::size_t pos_ = 0;
};

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : "\n") + n;
  return s;
}

std::string listed(const std::string& newline_separated) {
  if (newline_separated.empty()) return "none";
  std::string s = newline_separated;
  for (std::size_t p = 0; (p = s.find('\n', p)) != std::string::npos;) s.replace(p, 1, ", ");
  return s;
}

std::string body_names(const World& world) {
  std::vector<std::string> names;
  for (const auto& b : world.bodies) names.push_back(b->name);
  return joined(names);
}

std::string term_names(const World& world) {
  std::vector<std::string> names;
  for (const auto& t : world.terms) names.push_back(t->name());
  return joined(names);
}

std::string body_prefix(const Body& b) { return "body." + b.name + "."; }

// Real fields that may hold +infinity in a sound checkpoint: the motion limit of a
// run at rest (Integrator::motion_limited_dt).
bool may_be_infinite(const std::string& name) { return name == "integrator.motion_dt"; }

// A damaged or forged checkpoint must not carry a NaN or an infinity into the run (it
// would reach the output as one): every real value is finite, but for the named few
// that may be +infinity. Returns the first offending field and index, or "".
std::string first_non_finite(const StateRecord& r) {
  for (const auto& [name, f] : r.fields()) {
    if (f.type != StateRecord::Type::Real) continue;
    const std::size_t n = f.bytes.size() / sizeof(double);
    for (std::size_t i = 0; i < n; ++i) {
      double v;
      std::memcpy(&v, f.bytes.data() + i * sizeof(double), sizeof v);
      if (std::isfinite(v) || (v == INFINITY && may_be_infinite(name))) continue;
      return fmt::format("field '{}' holds {} at value {}, expected a finite number", name, v, i);
    }
  }
  return {};
}
std::string term_prefix(std::size_t k) { return fmt::format("term.{}.", k); }

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

StateRecord checkpoint_record(const World& world, const Integrator& integrator, const RunClock& clock,
                              std::uint64_t scene_digest) {
  StateRecord r;
  r.put_integer("scene_digest", static_cast<std::int64_t>(scene_digest));
  r.put_real("time", world.time);
  r.put_integer("step", world.step);
  // A distributed run writes one checkpoint per rank, each holding its rank's state.
  r.put_integer("rank", world.comm->rank());
  r.put_integer("ranks", world.comm->size());
  r.put_real("clock.next_output", clock.next_output);
  r.put_integer("clock.frames", clock.frames);
  r.put_record("integrator.", integrator.save_state());
  r.put_text("bodies", body_names(world));
  for (const auto& b : world.bodies) {
    const std::string p = body_prefix(*b);
    r.put_integer(p + "particles", static_cast<std::int64_t>(b->size()));
    r.put_vectors(p + "d", b->d);
    r.put_vectors(p + "v", b->v);
    // The forces of the step's evaluation, which the next half-kick reads as f / inertia:
    // a material's state has moved since (end_state_step), so forces recomputed at the
    // restored state would differ in the last bits.
    r.put_vectors(p + "force", b->force);
    r.put_reals(p + "inertia", b->inertia);
    save_material_state(*b, r, p);
    r.put_reals(p + "constraint_targets", b->constraints.targets());
  }
  r.put_text("terms", term_names(world));
  for (std::size_t k = 0; k < world.terms.size(); ++k) {
    StateRecord t;
    world.terms[k]->save_state(t);
    r.put_record(term_prefix(k), t);
  }
  return r;
}

void write_checkpoint(const std::filesystem::path& path, const World& world, const Integrator& integrator,
                      const RunClock& clock, std::uint64_t scene_digest) {
  const std::string bytes = encode(checkpoint_record(world, integrator, clock, scene_digest));
  const auto tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(fmt::format("checkpoint {}: cannot open for writing", tmp));
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw std::runtime_error(fmt::format("checkpoint {}: write failed", tmp));
  }
  std::filesystem::rename(tmp, path);
}

void read_checkpoint(const std::filesystem::path& path, World& world, Integrator& integrator, RunClock& clock,
                     std::uint64_t scene_digest) {
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(fmt::format("checkpoint {}: cannot open", path.string()));
    std::ostringstream ss;
    ss << in.rdbuf();
    bytes = ss.str();
  }
  Decoder decoder(bytes, path.string());
  const StateRecord r = decoder.decode();
  const auto fail = [&](const std::string& why) { decoder.fail(why); };
  try {
    // What the checkpoint was written for, before anything is loaded.
    const auto digest = static_cast<std::uint64_t>(r.integer("scene_digest"));
    if (digest != scene_digest)
      fail(fmt::format("written for another scene (scene digest {:016x}, this scene file's is {:016x}: the file "
                       "changed or is another scene)",
                       digest, scene_digest));
    if (r.integer("ranks") != world.comm->size() || r.integer("rank") != world.comm->rank())
      fail(fmt::format("written by rank {} of a run on {} rank(s); this is rank {} of {}: resume on the rank "
                       "count that wrote it",
                       r.integer("rank"), r.integer("ranks"), world.comm->rank(), world.comm->size()));
    if (r.text("bodies") != body_names(world))
      fail(fmt::format("the bodies differ: the checkpoint has {}, the scene has {}", listed(r.text("bodies")),
                       listed(body_names(world))));
    for (const auto& b : world.bodies) {
      const auto n = r.integer(body_prefix(*b) + "particles");
      if (n != static_cast<std::int64_t>(b->size()))
        fail(fmt::format("body '{}' has {} particles in the checkpoint, {} in the scene", b->name, n, b->size()));
    }
    if (r.text("terms") != term_names(world))
      fail(fmt::format("the terms differ: the checkpoint has {}, the scene has {}", listed(r.text("terms")),
                       listed(term_names(world))));

    world.time = r.real("time");
    world.step = r.integer("step");
    clock.next_output = r.real("clock.next_output");
    clock.frames = r.integer("clock.frames");
    // A run only counts forward from zero, and its clock is finite: anything else is a
    // damaged or forged file, which would otherwise loop or overflow the step counter.
    if (world.step < 0) fail(fmt::format("its step is {}, expected 0 or more", world.step));
    if (clock.frames < 0) fail(fmt::format("its frame count is {}, expected 0 or more", clock.frames));
    if (!std::isfinite(world.time) || world.time < 0.0)
      fail(fmt::format("its time is {}, expected a finite value of 0 or more", world.time));
    if (!std::isfinite(clock.next_output))
      fail(fmt::format("its next output time is {}, expected a finite value", clock.next_output));
    if (const std::string bad = first_non_finite(r); !bad.empty()) fail(bad);
    if (!(r.real("integrator.dt") > 0.0))
      fail(fmt::format("its step is {} s, expected a positive step", r.real("integrator.dt")));
    for (auto& b : world.bodies) {
      const std::string p = body_prefix(*b);
      b->d = r.vectors(p + "d", b->size());
      b->v = r.vectors(p + "v", b->size());
      b->inertia = r.reals(p + "inertia", b->size());
      for (std::size_t i = 0; i < b->inertia.size(); ++i)
        if (!(b->inertia[i] > 0.0))
          fail(fmt::format("body '{}' particle {} has inertia {}, expected a positive mass", b->name, i,
                           b->inertia[i]));
      load_material_state(*b, r, p);  // the material checks its own state (StateError)
      b->constraints.set_targets(r.reals(p + "constraint_targets", b->constraints.targets().size()));
    }
    for (std::size_t k = 0; k < world.terms.size(); ++k) world.terms[k]->load_state(r.record(term_prefix(k)));
    // F and the terms' per-step quantities at the restored state (deterministic: the same
    // as when written); the forces themselves as written (see save).
    compute_forces(world);
    for (auto& b : world.bodies) {
      b->constraints.transform_forces(b->force);
      b->force = r.vectors(body_prefix(*b) + "force", b->size());
    }
    integrator.load_state(r.record("integrator."));
  } catch (const StateError& e) {
    fail(e.what());
  }
}

}  // namespace rkpm::sim
