// rkpm_convergence: convergence study of the reproducing-kernel discretisation with
// nodal integration on the Lame thick-walled sphere under internal pressure.
// For every scheme and resolution: relative L2 displacement and energy-norm errors,
// set-up and solve wall times. Writes a CSV and a markdown table (see
// docs/verification/convergence.md; `scripts/study convergence` regenerates both).
#include "lame_study.hpp"
#include "report.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <exception>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

// "14x7" -> 14 face cells, 7 layers.
rkpm::study::Resolution parse_resolution(const std::string& text) {
  rkpm::study::Resolution r;
  char x = 0;
  std::istringstream in(text);
  if (!(in >> r.face_cells >> x >> r.layers) || x != 'x' || !in.eof() || r.face_cells < 1 || r.layers < 2)
    throw std::invalid_argument("--resolutions: '" + text + "' is not FACE_CELLSxLAYERS (e.g. 14x7, layers >= 2)");
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rkpm::study;
  CLI::App app{"Convergence study: Lame sphere under internal pressure, RK approximation with nodal integration"};
  std::vector<std::string> resolutions = {"5x3", "7x4", "9x5", "14x7", "19x9", "28x13"};
  // Plain SCNI and direct nodal integration are contrasts; their stiffness is nearly
  // singular (spurious low-energy modes), so CG needs thousands of iterations and
  // they are run on the coarser clouds only.
  std::vector<std::string> contrast_resolutions = {"5x3", "7x4", "9x5", "14x7"};
  std::vector<std::string> schemes = {"scni-stabilized", "scni", "direct"};
  std::string csv_path = "convergence.csv";
  std::string markdown_path = "convergence-table.md";
  CaseSettings settings;
  app.add_option("--resolutions", resolutions, "cubed-sphere face cells x particle layers, coarse to fine")
      ->delimiter(',');
  app.add_option("--contrast-resolutions", contrast_resolutions, "the same for the schemes scni and direct")
      ->delimiter(',');
  app.add_option("--schemes", schemes, "scni-stabilized, scni, direct")->delimiter(',');
  app.add_option("--csv", csv_path, "CSV output");
  app.add_option("--markdown", markdown_path, "markdown table output");
  app.add_option("--alpha", settings.alpha, "stabilization coefficient of scni-stabilized");
  app.add_option("--support", settings.support, "support radius / local particle spacing");
  const std::map<std::string, rkpm::rk::SupportShape> shapes{{"sphere", rkpm::rk::SupportShape::Sphere},
                                                              {"ellipsoid", rkpm::rk::SupportShape::Ellipsoid}};
  app.add_option("--support-shape", settings.support_shape, "[body.rk] support_shape: sphere or ellipsoid")
      ->transform(CLI::CheckedTransformer(shapes));
  const std::map<std::string, rkpm::rk::GradientPrecision> precisions{{"double", rkpm::rk::GradientPrecision::Double},
                                                                      {"float", rkpm::rk::GradientPrecision::Float}};
  app.add_option("--gradient-precision", settings.gradient_precision,
                 "[body.rk] gradient_precision: double or float storage of the smoothed gradients")
      ->transform(CLI::CheckedTransformer(precisions));
  const std::map<std::string, rkpm::rk::FacetRule> rules{{"corners", rkpm::rk::FacetRule::Corners},
                                                          {"centroids", rkpm::rk::FacetRule::Centroids}};
  app.add_option("--cell-quadrature", settings.cell_quadrature,
                 "[body.rk] cell_quadrature: corners or centroids of the smoothing cells' facets")
      ->transform(CLI::CheckedTransformer(rules));
  app.add_option("--tolerance", settings.solver.relative_tolerance, "CG relative residual tolerance");
  app.add_option("--max-iterations", settings.solver.max_iterations, "CG iteration limit");
  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<RunRecord> runs;
    for (const auto& scheme_text : schemes) {
      const Scheme scheme = parse_scheme(scheme_text);
      for (const auto& res_text : scheme == Scheme::StabilizedSCNI ? resolutions : contrast_resolutions) {
        RunRecord record;
        record.result.scheme = scheme;
        record.result.resolution = parse_resolution(res_text);
        try {
          record.result = run_lame_case(scheme, record.result.resolution, settings);
        } catch (const std::exception& e) {
          record.failure = e.what();  // e.g. a singular moment matrix: reported, not hidden
        }
        const CaseResult& c = record.result;
        fmt::print(stderr, "{:16} {:>3}x{:<3} N={:<7} h={:.4f}  L2={:.3e}  energy={:.3e}  setup={:.2f}s solve={:.2f}s "
                           "its={}{} residual={:.1e}{}\n",
                   scheme_name(scheme), c.resolution.face_cells, c.resolution.layers, c.particles, c.h, c.l2_error,
                   c.energy_error, c.setup_seconds, c.solve_seconds, c.solver.iterations,
                   c.solver.converged ? "" : " (NOT converged)", c.solver.relative_residual,
                   record.failure.empty() ? "" : "  FAILED: " + record.failure);
        runs.push_back(std::move(record));
      }
    }
    write_csv(csv_path, runs);
    write_markdown(markdown_path, runs, settings);
  } catch (const std::exception& e) {
    fmt::print(stderr, "rkpm_convergence: {}\n", e.what());
    return 1;
  }
  return 0;
}
