#include "record.hpp"

#include <fmt/format.h>

#include <sstream>

namespace rkpm::scaling {

double SizeResult::other_setup_s() const {
  if (gradient_s <= 0.0) return 0.0;
  return (split_run_setup_s > 0.0 ? split_run_setup_s : setup_s) - cloud_s - tree_s - gradient_s - interpolation_s - boundary_s;
}

const std::vector<std::pair<const char*, double SizeResult::*>>& numeric_fields() {
  static const std::vector<std::pair<const char*, double SizeResult::*>> fields = {
      {"resolution", &SizeResult::resolution},
      {"particles", &SizeResult::particles},
      {"setup_s", &SizeResult::setup_s},
      {"init_s", &SizeResult::init_s},
      {"cloud_s", &SizeResult::cloud_s},
      {"tree_s", &SizeResult::tree_s},
      {"gradient_s", &SizeResult::gradient_s},
      {"interpolation_s", &SizeResult::interpolation_s},
      {"boundary_s", &SizeResult::boundary_s},
      {"query_s", &SizeResult::query_s},
      {"step_2t_s", &SizeResult::step_2t_s},
      {"step_1t_s", &SizeResult::step_1t_s},
      {"force_2t_s", &SizeResult::force_2t_s},
      {"force_1t_s", &SizeResult::force_1t_s},
      {"steps_timed", &SizeResult::steps_timed},
      {"peak_bytes", &SizeResult::peak_bytes},
      {"baseline_bytes", &SizeResult::baseline_bytes},
      {"operators_bytes", &SizeResult::operators_bytes},
      {"state_bytes", &SizeResult::state_bytes},
      {"cloud_bytes", &SizeResult::cloud_bytes},
      {"traffic_bytes", &SizeResult::traffic_bytes},
      {"force_flops", &SizeResult::force_flops},
      {"gradient_row_mean", &SizeResult::gradient_row_mean},
      {"gradient_row_p95", &SizeResult::gradient_row_p95},
      {"gradient_row_max", &SizeResult::gradient_row_max},
      {"interpolation_row_mean", &SizeResult::interpolation_row_mean},
      {"setup_runs", &SizeResult::setup_runs},
      {"split_run_setup_s", &SizeResult::split_run_setup_s},
  };
  return fields;
}

std::string to_line(const SizeResult& r) {
  std::string line = fmt::format("RESULT geometry={} status={}", r.geometry, r.status);
  for (const auto& [name, member] : numeric_fields()) line += fmt::format(" {}={:.9g}", name, r.*member);
  // The note is free text: last, and the rest of the line.
  return line + " note=" + r.note;
}

bool from_line(const std::string& line, SizeResult& r) {
  if (line.rfind("RESULT ", 0) != 0) return false;
  const auto note_at = line.find(" note=");
  if (note_at != std::string::npos) r.note = line.substr(note_at + 6);
  std::istringstream words(line.substr(7, note_at == std::string::npos ? std::string::npos : note_at - 7));
  std::string word;
  while (words >> word) {
    const auto eq = word.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = word.substr(0, eq), value = word.substr(eq + 1);
    if (key == "geometry") r.geometry = value;
    else if (key == "status") r.status = value;
    else
      for (const auto& [name, member] : numeric_fields())
        if (key == name) r.*member = std::stod(value);
  }
  return true;
}

}  // namespace rkpm::scaling
