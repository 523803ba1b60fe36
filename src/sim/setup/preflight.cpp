#include "rkpm/sim/preflight.hpp"

#include "rkpm/common/types.hpp"
#include "clouds/catalog.hpp"
#include "rkpm/sim/nested_iteration.hpp"
#include "sim/setup/row_model.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace rkpm::sim {

namespace {

// Bytes per particle of the run's state beyond the operators: X, d, v, force (4 x 24),
// F per point (72; the stress, positions and accelerations are not stored), mass,
// inertia, volume, spacing, stabilization weight, a surface term's quadrature, the
// set-up's kd-tree and support radii (freed before the run, but part of the peak), the
// per-point state of a stateful material (an LCE body's arrays) and the
// force pass's per-thread buffers. The largest of the geometries' measured peaks beyond
// the operators (the RBC shell's), rounded up, plus what the volume constraint's copy of
// its rows in particle order adds on that shell; docs/verification/performance.md holds
// the measurements. Kept as a margin: the scaling study measures the peaks again, and a
// state that grows past this must raise it.
constexpr double kStateBytes = 1750.0;
// Bytes per operator entry at the set-up peak: a smoothed-gradient entry is a 4-byte
// column and a vector of 24 bytes (double storage) or 12 (float), built in blocks that
// are freed as they are joined (a margin of 12 for the blocks in flight and the
// vectors' spare capacity); an interpolation entry is a column and a float value (8),
// built the same way.
constexpr double kGradientEntryMargin = 12.0;
constexpr double kInterpolationEntryBytes = 16.0;
// One frame, uncompressed: the position and 22 point-field components in doubles, the
// cells (8 connectivity ids, an offset and a type per hexahedron, in 64-bit ids).
constexpr double kFramePointBytes = 25.0 * 8.0;
constexpr double kFrameElementBytes = 10.0 * 8.0 + 1.0;
// What the process holds before any body: the libraries (VTK, OpenMP) and the scene.
constexpr double kProcessBytes = 30e6;
// A checkpoint: d, v, the force and a material's state vector per particle, and the inertia.
constexpr double kCheckpointBytes = 4.0 * 24.0 + 8.0;
// The address space a process maps before its arrays (libraries, thread stacks).
constexpr double kAddressSpaceBaseline = 1.0e9;

BodyEstimate estimate_body(const scene::BodySpec& spec, int ranks) {
  BodyEstimate e;
  e.name = spec.name();
  e.generator = spec.generator();
  const clouds::CloudSize grid = clouds::estimate_cloud(spec);
  e.particles = grid.particles;
  e.elements = grid.elements;
  e.size_key = grid.size_key;
  const auto entries = [&](rk::SupportShape shape) {
    const RowModel rows = row_model(spec, grid, shape);
    return std::pair{e.particles * rows.gradient, e.particles * rows.interpolation};
  };
  const double gradient_entry_bytes =
      4.0 + (spec.rk.choice("gradient_precision") == "float" ? 12.0 : 24.0) + kGradientEntryMargin;
  // Distributed: a rank's rows are its share of the operators; the state stays whole.
  const auto memory = [&](const std::pair<double, double>& gradient_and_interpolation) {
    return e.particles * kStateBytes + (gradient_and_interpolation.first * gradient_entry_bytes +
                                        gradient_and_interpolation.second * kInterpolationEntryBytes) / ranks;
  };
  const rk::SupportShape shape = resolved_support_shape(spec, grid);
  e.support_shape = shape == rk::SupportShape::Ellipsoid ? "ellipsoid" : "sphere";
  const auto declared = entries(shape);
  e.gradient_entries = declared.first;
  e.interpolation_entries = declared.second;
  e.memory_bytes = memory(declared);
  e.memory_bytes_with_ellipsoids =
      shape == rk::SupportShape::Ellipsoid ? e.memory_bytes : memory(entries(rk::SupportShape::Ellipsoid));
  return e;
}

std::optional<double> read_number_file(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text == "max") return std::nullopt;
  try {
    return std::stod(text);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<double> proc_status_kb(const std::string& file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) != 0) continue;
    std::istringstream fields(line.substr(key.size()));
    double kb = 0.0;
    if (fields >> kb) return kb * 1024.0;
  }
  return std::nullopt;
}

std::optional<double> least(std::optional<double> a, std::optional<double> b) {
  if (!a) return b;
  if (!b) return a;
  return std::min(*a, *b);
}

}  // namespace

RunEstimate estimate_run(const scene::Scene& scene, int ranks, int ranks_on_node) {
  RunEstimate r;
  r.ranks = std::max(ranks, 1);
  r.ranks_on_node = std::max(ranks_on_node, 1);
  double points = 0.0, elements = 0.0;
  for (const auto& spec : scene.bodies) {
    r.bodies.push_back(estimate_body(spec, r.ranks));
    r.particles += r.bodies.back().particles;
    r.memory_bytes += r.bodies.back().memory_bytes;
    points += r.bodies.back().particles;
    elements += r.bodies.back().elements;
  }
  r.memory_bytes += kProcessBytes;
  r.frame_bytes = points * kFramePointBytes + elements * kFrameElementBytes;
  r.checkpoint_bytes = scene.output.integer("checkpoint_every") > 0 ? points * kCheckpointBytes : 0.0;
  const auto& integrator = scene.integrator;
  if (integrator.has("t_end")) {
    const double t_end = integrator.real("t_end");
    const double every = scene.output.has("every") ? scene.output.real("every") : t_end / 50.0;
    // The first frame, one per `every`, and the last; at most one per step.
    r.frames = std::min(std::floor(t_end / every) + 2.0, static_cast<double>(integrator.integer("max_steps")) + 2.0);
  } else if (!scene.output.has("every")) {
    r.frames = 2.0;  // relaxing without t_end or every: the start and the end
  }
  r.output_bytes = r.frame_bytes * (r.frames ? *r.frames : 2.0) + r.checkpoint_bytes;
  for (const double factor : nested_level_factors(scene)) r.level_particles.push_back(level_particles(scene, factor));
  return r;
}

std::optional<double> available_node_memory() {
  std::optional<double> limit = proc_status_kb("/proc/meminfo", "MemAvailable:");
  if (const auto max = read_number_file("/sys/fs/cgroup/memory.max")) {
    const double used = read_number_file("/sys/fs/cgroup/memory.current").value_or(0.0);
    limit = least(limit, *max - used);
  }
  return limit;
}

std::optional<double> available_address_space() {
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) != 0 || as.rlim_cur == RLIM_INFINITY) return std::nullopt;
  const double mapped = proc_status_kb("/proc/self/status", "VmSize:").value_or(kAddressSpaceBaseline);
  return static_cast<double>(as.rlim_cur) - std::max(mapped, kAddressSpaceBaseline);
}

std::optional<double> available_memory() { return least(available_node_memory(), available_address_space()); }

std::optional<double> available_disk(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(dir, ec);
  if (ec) return std::nullopt;
  while (!p.empty() && !std::filesystem::exists(p, ec)) {
    if (p == p.parent_path()) break;
    p = p.parent_path();
  }
  const auto space = std::filesystem::space(p, ec);
  if (ec) return std::nullopt;
  return static_cast<double>(space.available);
}

void check_memory(const RunEstimate& estimate, const RunLimits& limits) {
  constexpr double kIndexLimit = static_cast<double>(std::numeric_limits<Index>::max());
  for (const auto& b : estimate.bodies) {
    if (b.particles > kIndexLimit)
      throw PreflightError(fmt::format(
          "{}: body '{}' would have {:.4g} particles, more than the {} a 32-bit particle index can address; "
          "expected a count below that (a coarser cloud)",
          b.size_key, b.name, b.particles, std::numeric_limits<Index>::max()));
    // A rank stores the entries of its own rows.
    if (b.gradient_entries / estimate.ranks > kIndexLimit)
      throw PreflightError(fmt::format(
          "{}: body '{}' would have about {:.3g} operator entries ({:.4g} particles) on a rank, more than the {} a "
          "32-bit index can address; expected a coarser cloud, a smaller [body.rk] support or more ranks",
          b.size_key, b.name, b.gradient_entries / estimate.ranks, b.particles, std::numeric_limits<Index>::max()));
  }
  // The node's memory (and the job's cgroup) holds every rank on the node; the address-
  // space limit (ulimit -v) holds each process alone. One process: the least of them.
  const auto node_memory = limits.memory_bytes ? limits.memory_bytes : available_node_memory();
  const auto address_space = limits.memory_bytes ? std::nullopt : available_address_space();
  // The binding limit: the node's (all its ranks together) or one process's.
  double needed = 0.0, available = 0.0;
  std::string on_node;
  if (node_memory && estimate.node_memory_bytes() > *node_memory) {
    needed = estimate.node_memory_bytes();
    available = *node_memory;
    if (estimate.ranks_on_node > 1)
      on_node = fmt::format(" for the {} ranks on this node, {} each", estimate.ranks_on_node,
                            human_bytes(estimate.memory_bytes));
  } else if (address_space && estimate.memory_bytes > *address_space) {
    needed = estimate.memory_bytes;
    available = *address_space;
  } else {
    return;
  }
  const auto largest = std::max_element(estimate.bodies.begin(), estimate.bodies.end(),
                                        [](const auto& a, const auto& b) { return a.memory_bytes < b.memory_bytes; });
  // Ball supports on a cloud whose spacing differs between directions (a refined shell
  // keeps its layers) hold many times the particles an ellipsoid does: when ellipsoids
  // would fit, say so, with the key, rather than only asking for a coarser cloud.
  double saved = 0.0;
  for (const auto& b : estimate.bodies) saved += b.memory_bytes - b.memory_bytes_with_ellipsoids;
  const double with_ellipsoids = needed * (estimate.memory_bytes - saved) / estimate.memory_bytes;
  const std::string ellipsoids =
      saved > 0.0 && with_ellipsoids <= available
          ? fmt::format(" or [body.rk] support_shape = \"ellipsoid\" (about {} with it: supports shaped by the "
                        "cloud's own spacing)",
                        human_bytes(with_ellipsoids))
          : "";
  throw PreflightError(fmt::format(
      "{}: the run needs about {} of memory{} ({:.4g} particles; body '{}' alone {}), more than the {} {}; "
      "expected a coarser cloud{}{}{}",
      largest->size_key, human_bytes(needed), on_node, estimate.particles, largest->name,
      human_bytes(largest->memory_bytes), human_bytes(available),
      limits.memory_bytes ? "given by --memory-limit" : "available to this process", ellipsoids,
      limits.memory_bytes ? " or a larger --memory-limit" : "", on_node.empty() ? "" : " or fewer ranks per node"));
}

double frames_expected(const scene::Scene& scene, const RunEstimate& estimate, std::optional<double> dt,
                       std::int64_t step_limit) {
  const bool dynamic = scene.integrator.choice("mode") == "dynamic";
  if (!dynamic || !dt || !(*dt > 0.0) || !estimate.frames) return 2.0;
  double steps = std::ceil(scene.integrator.real("t_end") / *dt);
  if (step_limit > 0) steps = std::min(steps, static_cast<double>(step_limit));
  return std::min(*estimate.frames, steps + 2.0);
}

void check_disk(const scene::Scene& scene, const RunEstimate& estimate, double frames, const RunLimits& limits,
                const std::filesystem::path& out_dir) {
  const double bytes = frames * estimate.frame_bytes + estimate.checkpoint_bytes;
  const auto disk = limits.disk_bytes ? limits.disk_bytes : available_disk(out_dir);
  if (disk && bytes > *disk) {
    throw PreflightError(fmt::format(
        "{}:{}: [output] every: {:.0f} frames of about {} each (uncompressed) need up to {}, more than the {} free "
        "in {}; expected fewer frames (a larger `every`), a coarser cloud or another --out folder",
        scene.output.file(), scene.output.line("every"), frames, human_bytes(estimate.frame_bytes),
        human_bytes(bytes), human_bytes(*disk), out_dir.string()));
  }
}

void print_estimate(std::ostream& out, const scene::Scene& scene, const RunEstimate& estimate,
                    const RunLimits& limits, const std::filesystem::path& out_dir) {
  out << fmt::format("scene {} ({})\n", scene.scene.text("name"), scene.file);
  out << fmt::format("{:<16} {:<10} {:>12} {:>10} {:>16} {:>12}\n", "body", "cloud", "particles", "supports",
                     "operator entries", "memory");
  for (const auto& b : estimate.bodies)
    out << fmt::format("{:<16} {:<10} {:>12.0f} {:>10} {:>16.3g} {:>12}\n", b.name, b.generator, b.particles,
                       b.support_shape, b.gradient_entries + b.interpolation_entries, human_bytes(b.memory_bytes));
  if (!estimate.level_particles.empty()) {
    out << "nested levels, relaxed first:";
    for (const double n : estimate.level_particles) out << fmt::format(" {:.0f}", n);
    out << " particles\n";
  }
  out << fmt::format("run: {:.0f} particles, about {} of memory", estimate.particles,
                     human_bytes(estimate.node_memory_bytes()));
  if (estimate.ranks > 1)
    out << fmt::format(" on this node ({} ranks of {}, {} each: a rank keeps its share of the operators and the "
                       "whole state)",
                       estimate.ranks_on_node, estimate.ranks, human_bytes(estimate.memory_bytes));
  const auto memory = limits.memory_bytes ? limits.memory_bytes : available_memory();
  out << (memory ? fmt::format(" (limit {})\n", human_bytes(*memory)) : std::string(" (limit unknown)\n"));
  out << fmt::format("output: {} per frame (uncompressed), {}; up to {}", human_bytes(estimate.frame_bytes),
                     estimate.frames ? fmt::format("at most {:.0f} frames", *estimate.frames)
                                     : std::string("frames until convergence"),
                     human_bytes(estimate.output_bytes));
  const auto disk = limits.disk_bytes ? limits.disk_bytes : available_disk(out_dir);
  out << (disk ? fmt::format(" ({} free in {})\n", human_bytes(*disk), out_dir.string()) : std::string("\n"));
}

std::string human_bytes(double bytes) {
  const char* units[] = {"B", "KB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (std::abs(bytes) >= 1000.0 && u < 5) {
    bytes /= 1000.0;
    ++u;
  }
  if (u == 5 && std::abs(bytes) >= 1000.0) return fmt::format("{:.3g} PB", bytes);
  return fmt::format(u == 0 ? "{:.0f} {}" : "{:.3g} {}", bytes, units[u]);
}

double parse_byte_size(const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const std::string unit = text.substr(used);
  double scale = 0.0;
  if (unit.empty() || unit == "B") scale = 1.0;
  else if (unit == "K" || unit == "KB") scale = 1e3;
  else if (unit == "M" || unit == "MB") scale = 1e6;
  else if (unit == "G" || unit == "GB") scale = 1e9;
  else if (unit == "T" || unit == "TB") scale = 1e12;
  if (used == 0 || scale == 0.0 || !(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(fmt::format("--memory-limit {}: expected a positive size in bytes, "
                                            "optionally with a unit K, M, G or T (powers of 1000), e.g. 8G",
                                            text));
  return value * scale;
}

}  // namespace rkpm::sim
