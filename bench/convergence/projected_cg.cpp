#include "projected_cg.hpp"

#include <Eigen/LU>

#include <cmath>

namespace rkpm::study {

SolverReport solve_projected_cg(ElasticStiffness& K, const RigidModes& rigid, Field f, Field& d,
                                const SolverSettings& settings) {
  const auto n = static_cast<Index>(f.size());
  std::vector<Mat3> inverse_block = K.diagonal_blocks();
  for (auto& B : inverse_block) B = B.inverse().eval();
  auto precondition = [&](const Field& r, Field& z) {
    for (Index i = 0; i < n; ++i) z[i] = inverse_block[i] * r[i];
    rigid.remove_from(z);
  };

  rigid.remove_from(f);  // round-off only: the discrete load is equilibrated to ~1e-16
  const double f_norm = std::sqrt(dot(f, f));
  d.assign(f.size(), Vec3::Zero());
  SolverReport report;
  if (f_norm == 0.0) {
    report.converged = true;
    return report;
  }
  Field r = f, z(f.size()), p(f.size()), Kp(f.size());
  precondition(r, z);
  p = z;
  double rz = dot(r, z);
  for (int it = 1; it <= settings.max_iterations; ++it) {
    K.apply(p, Kp);
    const double pKp = dot(p, Kp);
    if (!(pKp > 0.0)) break;  // a direction of zero or negative energy: K is not positive on its range
    const double step = rz / pKp;
    axpy(step, p, d);
    axpy(-step, Kp, r);
    report.iterations = it;
    report.relative_residual = std::sqrt(dot(r, r)) / f_norm;
    if (report.relative_residual <= settings.relative_tolerance) {
      report.converged = true;
      break;
    }
    precondition(r, z);
    const double rz_next = dot(r, z);
    const double beta = rz_next / rz;
    rz = rz_next;
    for (Index i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
  }
  // Report the true residual, not the recursively updated one, which can drift.
  K.apply(d, Kp);
  axpy(-1.0, f, Kp);
  report.relative_residual = std::sqrt(dot(Kp, Kp)) / f_norm;
  report.converged = report.converged && report.relative_residual <= 10.0 * settings.relative_tolerance;
  return report;
}

}  // namespace rkpm::study
