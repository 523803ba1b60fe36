#include "report.hpp"

#include "fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <map>
#include <stdexcept>
#include <thread>

namespace rkpm::scaling {

namespace {

std::ofstream open(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  return out;
}

bool ok(const SizeResult& r) { return r.status == "ok"; }

double per_particle(double bytes, const SizeResult& r) { return r.particles > 0 ? bytes / r.particles : NAN; }
double arrays_bytes(const SizeResult& r) { return r.operators_bytes + r.state_bytes + r.cloud_bytes; }

std::string csv_text(std::string s) {
  std::replace(s.begin(), s.end(), ',', ';');
  std::replace(s.begin(), s.end(), '"', '\'');
  return s;
}

// Three significant digits, in the unit given by `scale` (1e3: ms).
std::string num(double v, double scale = 1.0) {
  if (!std::isfinite(v)) return "-";
  v *= scale;
  if (v == 0.0) return "0";
  const int digits = std::max(0, 2 - static_cast<int>(std::floor(std::log10(std::abs(v)))));
  return fmt::format("{:.{}f}", v, digits);
}

std::string count(double n) {
  std::string s = fmt::format("{:.0f}", n), out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (i > 0 && (s.size() - i) % 3 == 0) out += ',';
    out += s[i];
  }
  return out;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

// The 1-minute load average when the report is written: above ~0.5 the machine
// was shared and the times are not to be trusted.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string first;
  return in >> first ? first : "unknown";
}

std::string today() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
  return text;
}

std::vector<std::string> geometries_of(const StudyResult& s) {
  std::vector<std::string> names;
  for (const auto& r : s.sizes)
    if (std::find(names.begin(), names.end(), r.geometry) == names.end()) names.push_back(r.geometry);
  return names;
}

// The largest measured size of a geometry (where the targets are judged), or null.
const SizeResult* largest(const StudyResult& s, const std::string& geometry) {
  const SizeResult* best = nullptr;
  for (const auto& r : s.sizes)
    if (r.geometry == geometry && ok(r) && (!best || r.particles > best->particles)) best = &r;
  return best;
}

struct Fits {
  PowerFit step_2t, step_1t, force, setup;
  PowerFit setup_large;  // over the sizes from Targets::setup_exponent_from up
  double n_min = NAN, n_max = NAN;
};

Fits fits_of(const StudyResult& s, const std::string& geometry) {
  std::vector<double> n, step2, step1, force, setup, n_large, setup_large;
  Fits f;
  for (const auto& r : s.sizes) {
    if (r.geometry != geometry || !ok(r)) continue;
    n.push_back(r.particles);
    step2.push_back(r.step_2t_s);
    step1.push_back(r.step_1t_s);
    force.push_back(r.force_2t_s);
    setup.push_back(setup_total_s(r));
    if (r.particles >= Targets{}.setup_exponent_from) {
      n_large.push_back(r.particles);
      setup_large.push_back(setup_total_s(r));
    }
  }
  f.setup_large = fit_power_law(n_large, setup_large);
  if (!n.empty()) {
    f.n_min = *std::min_element(n.begin(), n.end());
    f.n_max = *std::max_element(n.begin(), n.end());
  }
  f.step_2t = fit_power_law(n, step2);
  f.step_1t = fit_power_law(n, step1);
  f.force = fit_power_law(n, force);
  f.setup = fit_power_law(n, setup);
  return f;
}

std::string status_cell(const SizeResult& r) { return ok(r) ? "" : r.status + ": " + r.note; }

void write_tables(std::ostream& md, const StudyResult& s) {
  md << "#### Set-up\n\n"
        "| geometry | particles | build_world [s] | cloud | kd-tree + spacing | gradient operator | interpolation "
        "operator | (its search) | boundary quadrature | other | initialize [s] | s per 100k particles |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& r : s.sizes) {
    if (!ok(r)) {
      md << fmt::format("| {} | {} | {} |||||||||\n", r.geometry, count(r.particles), status_cell(r));
      continue;
    }
    const bool split = r.gradient_s > 0;
    md << fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r.geometry,
                      count(r.particles), num(r.setup_s), split ? num(r.cloud_s) : "-", split ? num(r.tree_s) : "-",
                      split ? num(r.gradient_s) : "-", split ? num(r.interpolation_s) : "-",
                      split ? num(r.query_s) : "-", split ? num(r.boundary_s) : "-",
                      // Negative when the stages, timed again, took longer than build_world: noise.
                      split && r.other_setup_s() >= 0 ? num(r.other_setup_s()) : "n/a", num(r.init_s),
                      num(setup_total_s(r) / (r.particles / 1e5)));
  }
  md << "\n#### Step\n\n"
        "| geometry | particles | step, 2 threads [ms] | step, 1 thread [ms] | speed-up | ns per particle-step "
        "(2 threads) | internal force, 2 threads [ms] | 1 thread [ms] | bytes moved per step [MB] | achieved "
        "[GB/s] | of the bandwidth bound |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& r : s.sizes) {
    if (!ok(r)) {
      md << fmt::format("| {} | {} | {} |||||||||\n", r.geometry, count(r.particles), status_cell(r));
      continue;
    }
    const double fraction = bandwidth_fraction(r, s.triad);
    md << fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r.geometry, count(r.particles),
                      num(r.step_2t_s, 1e3), num(r.step_1t_s, 1e3), num(r.step_1t_s / r.step_2t_s),
                      num(r.step_2t_s / r.particles, 1e9), num(r.force_2t_s, 1e3), num(r.force_1t_s, 1e3),
                      num(r.traffic_bytes, 1e-6), num(r.traffic_bytes / r.force_2t_s, 1e-9),
                      std::isfinite(fraction) ? fmt::format("{:.0f} %", 100.0 * fraction) : "-");
  }
  md << "\n#### Memory\n\n"
        "| geometry | particles | peak RSS per particle [B] | Body arrays per particle [B] | of which operators | "
        "state | cloud | gradient row: mean / p95 / max | interpolation row: mean | notes |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const auto& r : s.sizes) {
    if (!ok(r)) {
      md << fmt::format("| {} | {} | {} ||||||||\n", r.geometry, count(r.particles), status_cell(r));
      continue;
    }
    md << fmt::format("| {} | {} | {:.0f} | {:.0f} | {:.0f} | {:.0f} | {:.0f} | {:.0f} / {:.0f} / {:.0f} | {:.0f} | {} |\n",
                      r.geometry, count(r.particles), per_particle(r.peak_bytes, r), per_particle(arrays_bytes(r), r),
                      per_particle(r.operators_bytes, r), per_particle(r.state_bytes, r),
                      per_particle(r.cloud_bytes, r), r.gradient_row_mean, r.gradient_row_p95, r.gradient_row_max,
                      r.interpolation_row_mean, r.note);
  }
  md << "\n#### Roofline of the internal force (2 threads)\n\n";
  md << fmt::format("Ceilings: the triad's {:.2f} GB/s and the arithmetic peak without fused multiply-adds, "
                    "{} threads: **{:.1f} GFLOP/s** on {} vectors ({} doubles), **{:.1f} GFLOP/s** scalar. "
                    "Ridge point {:.2f} flop/B (vector peak / triad). Operations counted from the kernels' "
                    "arithmetic, the stress left out (bench/common/footprint.hpp).\n\n",
                    s.triad.gb_per_s, s.peak.threads, s.peak.vector_gflops, s.peak.isa, s.peak.vector_lanes,
                    s.peak.scalar_gflops, s.peak.vector_gflops / s.triad.gb_per_s);
  md << "| geometry | particles | flops per particle-step | bytes per particle-step | intensity [flop/B] | "
        "achieved [GFLOP/s] | of the vector peak | of the scalar peak | roofline time [ms] | measured [ms] | "
        "of the roofline |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const auto percent = [](double f) { return std::isfinite(f) ? fmt::format("{:.0f} %", 100.0 * f) : "-"; };
  for (const auto& r : s.sizes) {
    if (!ok(r)) continue;
    const double bound = roofline_s(r, s.triad, s.peak);
    md << fmt::format("| {} | {} | {:.0f} | {:.0f} | {} | {} | {} | {} | {} | {} | {} |\n", r.geometry,
                      count(r.particles), r.force_flops / r.particles, r.traffic_bytes / r.particles,
                      num(intensity(r)), num(gflops(r)), percent(gflops(r) / s.peak.vector_gflops),
                      percent(gflops(r) / s.peak.scalar_gflops), num(bound, 1e3), num(r.force_2t_s, 1e3),
                      percent(bound / r.force_2t_s));
  }
  md << "\n#### Fitted exponents p of t ~ N^p\n\n"
        "| geometry | sizes | particles | step, 2 threads | step, 1 thread | internal force | set-up | set-up "
        "from 1e5 |\n"
        "|---|---:|---|---:|---:|---:|---:|---:|\n";
  for (const auto& g : geometries_of(s)) {
    const Fits f = fits_of(s, g);
    if (f.step_2t.points == 0) {
      md << fmt::format("| {} | 0 | no size measured |||||\n", g);
      continue;
    }
    md << fmt::format("| {} | {} | {} - {} | {} | {} | {} | {} | {} |\n", g, f.step_2t.points, count(f.n_min),
                      count(f.n_max), num(f.step_2t.exponent), num(f.step_1t.exponent), num(f.force.exponent),
                      num(f.setup.exponent), num(f.setup_large.exponent));
  }
}

std::string verdict(bool assessed, bool met) { return !assessed ? "not assessed" : met ? "met" : "not met"; }

void write_targets(std::ostream& md, const StudyResult& s, const RbcRelaxation& rbc) {
  const Targets t;
  md << "\n#### Targets\n\n| target | measured | verdict |\n|---|---|---|\n";
  for (const auto& g : geometries_of(s)) {
    const SizeResult* r = largest(s, g);
    if (!r) {
      md << fmt::format("| {}: all targets | no size measured | not assessed |\n", g);
      continue;
    }
    const std::string at = fmt::format("at {} particles", count(r->particles));
    const double fraction = bandwidth_fraction(*r, s.triad);
    md << fmt::format("| {}: internal force >= {:.0f} % of the bandwidth bound | {} {} | {} |\n", g,
                      100 * t.bandwidth_fraction,
                      std::isfinite(fraction) ? fmt::format("{:.0f} %", 100 * fraction) : "-", at,
                      verdict(std::isfinite(fraction), fraction >= t.bandwidth_fraction));
    const Fits f = fits_of(s, g);
    // The exponent target is about 1e3 to 1e6: a study that stopped short does not decide it.
    const bool full_range = f.step_2t.points >= 3 && f.n_min <= 2e3 && f.n_max >= 0.9e6;
    md << fmt::format("| {}: step exponent <= {} from 1e3 to 1e6 particles | {} over {} - {} particles | {} |\n", g,
                      t.step_exponent, num(f.step_2t.exponent), count(f.n_min), count(f.n_max),
                      verdict(full_range, f.step_2t.exponent <= t.step_exponent));
    // The largest peak over the judged sizes (the largest size alone unless the target
    // names a range).
    const MemoryTarget memory = Targets::memory(g);
    const SizeResult* worst = r;
    for (const auto& q : s.sizes)
      if (q.geometry == g && ok(q) && memory.from_particles > 0 && q.particles >= memory.from_particles &&
          per_particle(q.peak_bytes, q) > per_particle(worst->peak_bytes, *worst))
        worst = &q;
    const double bpp = per_particle(worst->peak_bytes, *worst);
    const std::string sizes = memory.from_particles > 0
                                  ? fmt::format(" at every size from {} particles", count(memory.from_particles))
                                  : "";
    md << fmt::format("| {}: <= {:.0f} B per particle (peak RSS){} | {:.0f} B at {} particles | {} |\n", g,
                      memory.bytes_per_particle, sizes, bpp, count(worst->particles),
                      verdict(std::isfinite(bpp), bpp <= memory.bytes_per_particle));
    const double setup = setup_total_s(*r) / (r->particles / 1e5);
    md << fmt::format("| {}: set-up <= {} s per 100k particles | {} s {} | {} |\n", g, num(t.setup_s_per_100k),
                      num(setup), at, verdict(true, setup <= t.setup_s_per_100k));
    const bool large_range = f.setup_large.points >= 2 && f.n_max >= 0.9e6;
    md << fmt::format("| {}: set-up exponent <= {} from 1e5 to 1e6 particles | {} over {} sizes | {} |\n", g,
                      num(t.setup_exponent), num(f.setup_large.exponent), f.setup_large.points,
                      verdict(large_range, f.setup_large.exponent <= t.setup_exponent));
  }
  if (rbc.wall_s >= 0)
    md << fmt::format("| default RBC relaxation (examples/rbc/rbc.toml, 2 threads) <= {:.0f} s wall | {} s, {} "
                      "steps, {} | {} |\n",
                      t.rbc_relaxation_s, num(rbc.wall_s), rbc.steps, rbc.status,
                      verdict(true, rbc.wall_s <= t.rbc_relaxation_s && rbc.status == "completed"));
  else
    md << fmt::format("| default RBC relaxation (examples/rbc/rbc.toml, 2 threads) <= {:.0f} s wall | not run "
                      "(--no-rbc-run) | not assessed |\n",
                      t.rbc_relaxation_s);
}

}  // namespace

double setup_total_s(const SizeResult& r) { return r.setup_s + r.init_s; }

double intensity(const SizeResult& r) {
  return ok(r) && r.traffic_bytes > 0 && r.force_flops > 0 ? r.force_flops / r.traffic_bytes : NAN;
}

double gflops(const SizeResult& r) { return ok(r) && r.force_2t_s > 0 ? r.force_flops / r.force_2t_s / 1e9 : NAN; }

double roofline_s(const SizeResult& r, const TriadResult& triad, const PeakResult& peak) {
  if (!ok(r) || triad.gb_per_s <= 0 || peak.vector_gflops <= 0) return NAN;
  return std::max(r.traffic_bytes / (triad.gb_per_s * 1e9), r.force_flops / (peak.vector_gflops * 1e9));
}

double bandwidth_fraction(const SizeResult& r, const TriadResult& triad) {
  if (!ok(r) || triad.gb_per_s <= 0 || r.force_2t_s <= 0) return NAN;
  return (r.traffic_bytes / (triad.gb_per_s * 1e9)) / r.force_2t_s;
}

void write_csv(const std::string& path, const StudyResult& s) {
  std::ofstream out = open(path);
  out << "geometry,status";
  for (const auto& [name, member] : numeric_fields()) out << ',' << name;
  out << ",other_setup_s,setup_total_s,peak_bytes_per_particle,array_bytes_per_particle,speedup_2t,"
         "ns_per_particle_step_2t,bandwidth_fraction,triad_gb_per_s,intensity_flop_per_byte,gflops_2t,roofline_s,"
         "peak_vector_gflops,peak_scalar_gflops,vector_lanes,isa,note\n";
  for (const auto& r : s.sizes) {
    out << r.geometry << ',' << r.status;
    for (const auto& [name, member] : numeric_fields()) out << ',' << fmt::format("{:.6g}", r.*member);
    const bool measured = ok(r);
    const auto value = [&](double v) { return measured && std::isfinite(v) ? fmt::format("{:.6g}", v) : ""; };
    out << ',' << value(r.other_setup_s()) << ',' << value(setup_total_s(r)) << ','
        << value(per_particle(r.peak_bytes, r)) << ',' << value(per_particle(arrays_bytes(r), r)) << ','
        << value(r.step_1t_s / r.step_2t_s) << ',' << value(1e9 * r.step_2t_s / r.particles) << ','
        << value(bandwidth_fraction(r, s.triad)) << ',' << fmt::format("{:.6g}", s.triad.gb_per_s) << ','
        << value(intensity(r)) << ',' << value(gflops(r)) << ',' << value(roofline_s(r, s.triad, s.peak)) << ','
        << fmt::format("{:.6g},{:.6g},{},{}", s.peak.vector_gflops, s.peak.scalar_gflops, s.peak.vector_lanes,
                       s.peak.isa)
        << ',' << csv_text(r.note) << '\n';
  }
}

void write_markdown(const std::string& path, const StudyResult& s, const RbcRelaxation& rbc,
                    const std::string& command) {
  std::ofstream md = open(path);
  double largest_n = 0;
  for (const auto& r : s.sizes) largest_n = std::max(largest_n, r.particles);
  md << fmt::format("Generated by `{}` on {} (UTC), on {}, {} hardware threads; sizes up "
                    "to {} particles.\n\n",
                    command, today(), cpu_model(), std::thread::hardware_concurrency(), count(largest_n));
  md << fmt::format("Load average when the study ended: {} (other work on the machine inflates every time).\n\n",
                    load_average());
  md << fmt::format("Built for {} ({} doubles per vector register){}.\n\n", s.peak.isa, s.peak.vector_lanes,
                    s.peak.isa == "SSE2" ? ", the portable build" : ", a build for this machine (-DRKPM_NATIVE=ON)");
  md << fmt::format("Every geometry's scene declares `[body.rk] support_shape = \"{}\"`, `particle_order = \"{}\"`, "
                    "`gradient_precision = \"{}\"`.\n\n",
                    s.rk.support_shape, s.rk.particle_order, s.rk.gradient_precision);
  double fewest_runs = HUGE_VAL, most_runs = 0;
  for (const auto& r : s.sizes)
    if (ok(r) && r.particles >= Targets{}.setup_exponent_from) {
      fewest_runs = std::min(fewest_runs, r.setup_runs);
      most_runs = std::max(most_runs, r.setup_runs);
    }
  if (most_runs > 1)
    md << fmt::format("From {} particles on, each size's set-up (build_world and initialize) is the median of {} "
                      "processes; the parts of build_world are one run's, and \"other\" is that run's remainder.\n\n",
                      count(Targets{}.setup_exponent_from),
                      fewest_runs == most_runs ? fmt::format("{:.0f}", most_runs)
                                               : fmt::format("{:.0f} to {:.0f}", fewest_runs, most_runs));
  if (largest_n < 0.9e6)
    md << "**A development run: it stops short of 1e6 particles, so the exponent targets are not assessed. "
          "Regenerate with the full command on a quiet machine before quoting these numbers.**\n\n";
  md << fmt::format("Bandwidth bound: STREAM triad a = b + s c, {} threads, 3 arrays of {} MiB, best of {}: "
                    "**{:.2f} GB/s** (24 B per element; write-allocate not counted).\n\n",
                    s.triad.threads, s.triad.array_bytes >> 20, s.triad.repetitions, s.triad.gb_per_s);
  write_tables(md, s);
  write_targets(md, s, rbc);
}

}  // namespace rkpm::scaling
