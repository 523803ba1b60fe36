// Output of the convergence study: a CSV of every run and a markdown table with
// the observed convergence rates.
#pragma once

#include "lame_study.hpp"

#include <string>
#include <vector>

namespace rkpm::study {

struct RunRecord {
  CaseResult result;
  std::string failure;  // empty when the run produced a solution
};

// Least-squares slope of log(error) against log(h) over the finest `count` runs
// (all when count <= 0) of one scheme that produced a solution; NaN with fewer than two.
double fitted_rate(const std::vector<RunRecord>& runs, Scheme scheme, double CaseResult::*error, int count = 0);

void write_csv(const std::string& path, const std::vector<RunRecord>& runs);
void write_markdown(const std::string& path, const std::vector<RunRecord>& runs, const CaseSettings& settings);

}  // namespace rkpm::study
