#include "rkpm/sim/history.hpp"

#include "rkpm/io/atomic_file.hpp"
#include "rkpm/io/frame.hpp"
#include "rkpm/io/json.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <algorithm>
#include <iterator>
#include <string_view>

namespace rkpm::sim {

namespace {
// X + u(X) of every particle. Distributed: each rank computes its own particles' (it
// holds their interpolation rows) and every rank gathers all of them, in rank order,
// which is the particle order (each rank owns one range). Collective.
std::vector<Vec3> physical_positions(const Body& body, const par::Comm& comm) {
  std::vector<Vec3> u;
  physical_displacement(body, u);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] += body.cloud.X[i];
  if (!body.distributed()) return u;
  return par::gather_owned(comm, u, body.owned_begin(), body.owned_end());
}
}  // namespace

namespace {
// Resuming at `step`: keep the header and the rows of steps up to it. A run killed after
// its checkpoint has written rows the resumed run writes again, and perhaps half a row.
void keep_rows_up_to(const std::filesystem::path& path, std::int64_t step) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("cannot resume '{}': it cannot be read", path.string()));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string kept;
  std::size_t start = 0;
  for (bool header = true; start < text.size(); header = false) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) break;  // a row cut short by the kill
    const std::string row = text.substr(start, end + 1 - start);
    start = end + 1;
    if (!header && std::strtoll(row.c_str(), nullptr, 10) > step) break;
    kept += row;
  }
  io::write_text_atomically(path, kept);
}
}  // namespace

// A row is written only when every value in it is finite: an infinity or a NaN is the
// simulation's failure, reported as such (the run stops with a diagnosis, exit 3)
// instead of a history that ends in "inf".
void History::refuse_non_finite(const std::string& row) const {
  std::size_t k = 0, begin = 0;
  while (begin <= row.size()) {
    const std::size_t end = std::min(row.find(',', begin), row.size());
    const std::string_view value(row.data() + begin, end - begin);
    if (value.find("inf") != std::string_view::npos || value.find("nan") != std::string_view::npos)
      throw io::NonFiniteValue(fmt::format("history.csv: {} = {}", k < columns_.size() ? columns_[k] : "a column",
                                           std::string(value)));
    ++k;
    begin = end + 1;
  }
}

History::History(const std::filesystem::path& path, const World& world, const Body* shape_body, bool resume)
    : writes_(world.comm->root()), path_(path), shape_body_(shape_body) {
  if (!writes_) return;
  columns_ = {"step", "time", "dt", "kinetic", "strain", "interface", "external_work", "active_work",
              "state_work", "dissipated", "energy_error", "residual", "min_J"};
  for (const auto& t : world.terms)
    for (const auto& column : t->history_columns()) columns_.push_back(column);
  if (shape_body_)
    for (const char* column : {"volume", "area", "reduced_volume", "h_min_over_h_max", "inner_gap_min"})
      columns_.push_back(column);
  if (resume) keep_rows_up_to(path, world.step);
  out_.open(path, resume ? std::ios::app : std::ios::trunc);
  if (!out_) throw std::runtime_error(fmt::format("cannot open '{}' for writing", path.string()));
  if (resume) return;
  for (std::size_t k = 0; k < columns_.size(); ++k) out_ << (k ? "," : "") << columns_[k];
  out_ << "\n";
}

void History::record(const World& world, Integrator& integrator) {
  const auto& e = integrator.measure_energy();
  std::string term_values;  // on every rank: a distributed term's values are collective
  for (const auto& t : world.terms) term_values += t->history_values(world);
  // The whole shape report is a pass over the surface particles: cheap next to a step.
  // Fields that cannot be measured in this state stay empty.
  std::string shape_values;
  if (shape_body_) {
    try {
      const ShapeReport s = final_shape(*shape_body_, *world.comm);
      shape_values = fmt::format(",{:.10g},{:.10g},{:.6g},{:.6g},", s.volume, s.area, s.reduced_volume, s.h_min / s.h_max);
      if (s.has_inner_gap) shape_values += fmt::format("{:.6g}", s.inner_gap_min);
    } catch (const std::runtime_error&) {
      shape_values = ",,,,";
    }
  }
  if (!writes_) return;
  const std::string row =
      fmt::format("{},{:.10g},{:.6g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.6g},{:.6g},{:.8g}",
                  world.step, world.time, integrator.dt(), e.kinetic, e.strain, e.interface, e.external, e.active,
                  e.state, e.dissipated, e.relative_error(), integrator.residual(), integrator.min_J()) +
      term_values + shape_values;
  refuse_non_finite(row);
  out_ << row << "\n";
  out_.flush();
  if (!out_) throw std::runtime_error(fmt::format("failed writing '{}' (disk full?)", path_.string()));
}

ShapeReport final_shape(const Body& body, const par::Comm& comm) {
  return measure_shape(body.cloud, physical_positions(body, comm), "outer");
}

io::Json shape_entries(const ShapeReport& s) {
  io::Json j = io::Json::object();
  j.set("diameter", s.diameter);
  j.set("h_min", s.h_min);
  j.set("h_max", s.h_max);
  j.set("h_min_over_h_max", s.h_min / s.h_max);
  j.set("r_hmax_over_R", s.r_hmax_over_R);
  j.set("updown_asymmetry", s.updown_asymmetry);
  j.set("axial_asymmetry", s.axial_asymmetry);
  j.set("volume", s.volume);
  j.set("area", s.area);
  j.set("reduced_volume", s.reduced_volume);
  j.set("rms_vs_evans_fung_over_D", s.rms_vs_evans_fung);
  if (s.has_inner_gap) {
    j.set("inner_gap_centre", s.inner_gap_centre);
    j.set("inner_gap_min", s.inner_gap_min);
    j.set("wall_thickness_centre", s.wall_thickness_centre);
    j.set("walls_crossed", s.walls_crossed);
  }
  j.set("biconcave", s.biconcave);
  j.set("matches_evans_fung", s.matches_evans_fung);
  return j;
}

void write_shape(const ShapeReport& s, const std::filesystem::path& profile_csv, io::Json& summary) {
  summary.set("shape", shape_entries(s));
  // The inner surface's columns are left empty in the bins it does not reach.
  std::ofstream out(profile_csv);
  out << "r,thickness,top,bottom,evans_fung,inner_top,inner_bottom\n";
  for (std::size_t k = 0; k < s.r.size(); ++k) {
    out << fmt::format("{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}", s.r[k], s.thickness[k], s.top[k], s.bottom[k],
                       s.evans_fung[k]);
    if (s.inner_in_bin[k])
      out << fmt::format(",{:.8g},{:.8g}\n", s.inner_top[k], s.inner_bottom[k]);
    else
      out << ",,\n";
  }
}

}  // namespace rkpm::sim
