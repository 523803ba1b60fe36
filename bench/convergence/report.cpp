#include "report.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rkpm::study {

namespace {

std::vector<const RunRecord*> solved_runs(const std::vector<RunRecord>& runs, Scheme scheme) {
  std::vector<const RunRecord*> out;
  for (const auto& r : runs)
    if (r.result.scheme == scheme && r.failure.empty()) out.push_back(&r);
  return out;
}

double pair_rate(const CaseResult& coarse, const CaseResult& fine, double CaseResult::*error) {
  return std::log(coarse.*error / fine.*error) / std::log(coarse.h / fine.h);
}

std::string format_rate(double rate) { return std::isfinite(rate) ? fmt::format("{:.2f}", rate) : "-"; }

}  // namespace

double fitted_rate(const std::vector<RunRecord>& runs, Scheme scheme, double CaseResult::*error, int count) {
  auto solved = solved_runs(runs, scheme);
  std::sort(solved.begin(), solved.end(), [](const RunRecord* x, const RunRecord* y) { return x->result.h > y->result.h; });
  if (count > 0 && solved.size() > static_cast<std::size_t>(count))
    solved.erase(solved.begin(), solved.end() - count);
  if (solved.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(solved.size());
  for (const RunRecord* r : solved) {
    const double x = std::log(r->result.h), y = std::log(r->result.*error);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void write_csv(const std::string& path, const std::vector<RunRecord>& runs) {
  auto out = fmt::output_file(path);
  out.print("scheme,face_cells,layers,particles,h,l2_error,energy_error,setup_s,solve_s,cg_iterations,"
            "relative_residual,converged,stabilization_energy_fraction,failure\n");
  for (const auto& r : runs) {
    const CaseResult& c = r.result;
    out.print("{},{},{},{},{:.6g},{:.6e},{:.6e},{:.4f},{:.4f},{},{:.3e},{},{:.3e},\"{}\"\n", scheme_name(c.scheme),
              c.resolution.face_cells, c.resolution.layers, c.particles, c.h, c.l2_error, c.energy_error,
              c.setup_seconds, c.solve_seconds, c.solver.iterations, c.solver.relative_residual,
              c.solver.converged ? 1 : 0, c.stabilization_energy_fraction, r.failure);
  }
}

void write_markdown(const std::string& path, const std::vector<RunRecord>& runs, const CaseSettings& settings) {
  auto out = fmt::output_file(path);
  const LameSphere& p = settings.problem;
  out.print("Lame sphere a = {}, b = {}, E = {}, nu = {}, p = {}; cubic B-spline kernel, linear basis, "
            "support {} x local spacing ({}), gradients stored in {}, SCNI cell quadrature at the facets' {}; "
            "stabilization alpha = {}; CG tolerance {:.0e} (relative residual).\n\n",
            p.a, p.b, p.E, p.nu, p.p, settings.support,
            settings.support_shape == rk::SupportShape::Ellipsoid ? "ellipsoids" : "balls",
            settings.gradient_precision == rk::GradientPrecision::Float ? "single precision" : "double precision",
            settings.cell_quadrature == rk::FacetRule::Corners ? "corners" : "centroids",
            settings.alpha, settings.solver.relative_tolerance);
  for (Scheme scheme : {Scheme::StabilizedSCNI, Scheme::SCNI, Scheme::Direct}) {
    bool any = false;
    for (const auto& r : runs) any = any || r.result.scheme == scheme;
    if (!any) continue;
    out.print("**{}**: fitted rates (slope of log error vs log h) over all resolutions: L2 {}, energy {}; "
              "over the finest three: L2 {}, energy {}\n\n",
              scheme_name(scheme), format_rate(fitted_rate(runs, scheme, &CaseResult::l2_error)),
              format_rate(fitted_rate(runs, scheme, &CaseResult::energy_error)),
              format_rate(fitted_rate(runs, scheme, &CaseResult::l2_error, 3)),
              format_rate(fitted_rate(runs, scheme, &CaseResult::energy_error, 3)));
    out.print("| cells x layers | N | h | L2 error | rate | energy error | rate | set-up [s] | solve [s] | CG its | "
              "residual |\n");
    out.print("|---|---|---|---|---|---|---|---|---|---|---|\n");
    const CaseResult* previous = nullptr;
    for (const auto& r : runs) {
      const CaseResult& c = r.result;
      if (c.scheme != scheme) continue;
      if (!r.failure.empty()) {
        out.print("| {} x {} | {} | {:.4f} | failed: {} | | | | | | | |\n", c.resolution.face_cells, c.resolution.layers,
                  c.particles, c.h, r.failure);
        continue;
      }
      const double nan = std::numeric_limits<double>::quiet_NaN();
      out.print("| {} x {} | {} | {:.4f} | {:.3e} | {} | {:.3e} | {} | {:.2f} | {:.2f} | {}{} | {:.1e} |\n",
                c.resolution.face_cells, c.resolution.layers, c.particles, c.h, c.l2_error,
                format_rate(previous ? pair_rate(*previous, c, &CaseResult::l2_error) : nan), c.energy_error,
                format_rate(previous ? pair_rate(*previous, c, &CaseResult::energy_error) : nan), c.setup_seconds,
                c.solve_seconds, c.solver.iterations, c.solver.converged ? "" : " (not converged)",
                c.solver.relative_residual);
      previous = &c;
    }
    out.print("\n");
  }
}

}  // namespace rkpm::study
