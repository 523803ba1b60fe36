#include "rkpm/sim/newton_krylov.hpp"

#include "rkpm/sim/gmres.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rkpm::sim {

namespace {

// The free coordinates of every body as one vector (three entries per particle, bodies
// in order); the residual scaled per particle by 1 / (mu V_I^(2/3)), so that the largest
// norm of a particle's three entries is the integrator's residual measure and the
// 2-norm weighs every particle alike.
class Coordinates {
 public:
  Coordinates(World& world, const std::vector<double>& body_shear_modulus) : world_(world) {
    std::size_t n = 0;
    for (const auto& b : world.bodies) {
      offset_.push_back(n);
      n += b->size();
    }
    scale_.resize(static_cast<Eigen::Index>(3 * n));
    stiffness_.resize(scale_.size());
    double spacing_sum = 0.0;
    std::vector<double> steps;
    for (std::size_t k = 0; k < world.bodies.size(); ++k) {
      const Body& b = *world.bodies[k];
      particle_wave_steps(b, steps);
      for (std::size_t i = 0; i < b.size(); ++i) {
        const auto at = static_cast<Eigen::Index>(3 * (offset_[k] + i));
        const double s = 1.0 / (body_shear_modulus[k] * std::cbrt(b.cloud.volume[i] * b.cloud.volume[i]));
        // A particle's own stiffness, mass / (spacing / c)^2 = rho c^2 V / spacing^2: the
        // diagonal the preconditioner divides by.
        const double k_i = b.mass[i] / (steps[i] * steps[i]);
        scale_.segment<3>(at).setConstant(s);
        stiffness_.segment<3>(at).setConstant(s * k_i);
        spacing_sum += b.spacing[i];
      }
    }
    mean_spacing_ = n > 0 ? spacing_sum / static_cast<double>(n) : 0.0;
  }

  Eigen::Index size() const { return scale_.size(); }
  double mean_spacing() const { return mean_spacing_; }
  // The right preconditioner: the inverse of the scaled diagonal stiffness.
  Eigen::VectorXd preconditioner() const { return stiffness_.cwiseInverse(); }

  void read(Eigen::VectorXd& x) const {
    x.resize(size());
    for (std::size_t k = 0; k < world_.bodies.size(); ++k) {
      const Body& b = *world_.bodies[k];
      for (std::size_t i = 0; i < b.size(); ++i) x.segment<3>(static_cast<Eigen::Index>(3 * (offset_[k] + i))) = b.d[i];
    }
  }
  // Sets the coordinates, with the constrained ones following the free (the velocities
  // stay zero), and evaluates the forces there, with the materials' state carried to them by
  // `follow` when given: the scaled residual.
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, const std::function<void()>& follow = {}) {
    for (std::size_t k = 0; k < world_.bodies.size(); ++k) {
      Body& b = *world_.bodies[k];
      for (std::size_t i = 0; i < b.size(); ++i) b.d[i] = x.segment<3>(static_cast<Eigen::Index>(3 * (offset_[k] + i)));
      b.constraints.impose(b.d, b.v);
    }
    if (follow) follow();
    forces();
    residual(r);
  }
  // Whether the state of the last evaluation is one a step could reach: every J > 0 (a
  // force evaluation makes F at every point) and finite forces.
  bool admissible(const Eigen::VectorXd& r) const {
    if (!r.allFinite()) return false;
    for (const auto& b : world_.bodies)
      for (Index L = b->owned_begin(); L < b->owned_end(); ++L)
        if (!(b->F[L].determinant() > 0.0)) return false;
    return true;
  }
  // The scaled residual at the world's present forces.
  void residual(Eigen::VectorXd& r) const {
    r.resize(size());
    for (std::size_t k = 0; k < world_.bodies.size(); ++k) {
      const Body& b = *world_.bodies[k];
      for (std::size_t i = 0; i < b.size(); ++i) {
        const auto at = static_cast<Eigen::Index>(3 * (offset_[k] + i));
        r.segment<3>(at) = scale_[at] * b.force[i];
      }
    }
  }
  // x as each body's coordinates.
  std::vector<std::vector<Vec3>> split(const Eigen::VectorXd& x) const {
    std::vector<std::vector<Vec3>> d(world_.bodies.size());
    for (std::size_t k = 0; k < world_.bodies.size(); ++k) {
      d[k].resize(world_.bodies[k]->size());
      for (std::size_t i = 0; i < d[k].size(); ++i)
        d[k][i] = x.segment<3>(static_cast<Eigen::Index>(3 * (offset_[k] + i)));
    }
    return d;
  }

  std::int64_t evaluations = 0;

 private:
  void forces() {
    compute_forces(world_);
    for (auto& b : world_.bodies) b->constraints.transform_forces(b->force);
    ++evaluations;
  }

  World& world_;
  std::vector<std::size_t> offset_;
  Eigen::VectorXd scale_, stiffness_;
  double mean_spacing_ = 0.0;
};

}  // namespace

NewtonKrylovReport solve_static_equilibrium(World& world, const std::vector<double>& body_shear_modulus,
                                            const NewtonKrylovSettings& settings, const NewtonKrylovHooks& hooks) {
  for (auto& b : world.bodies) std::fill(b->v.begin(), b->v.end(), Vec3::Zero());
  Coordinates coords(world, body_shear_modulus);
  NewtonKrylovReport report;
  Eigen::VectorXd x, r, trial_x, trial_r, step, perturbed_r;
  coords.read(x);
  // The forces left by a step are those before its state update: evaluated again at
  // the present state, so that every difference below starts from the same state.
  coords.evaluate(x, r);
  report.residual = hooks.residual();
  const Eigen::VectorXd preconditioner = coords.preconditioner();
  double forcing = 0.1, previous_norm = r.norm();
  while (true) {
    if (report.residual < settings.force_tol) {
      report.converged = true;
      report.stop = "converged";
      break;
    }
    if (report.newton_steps >= settings.max_newton_steps) {
      report.stop = fmt::format("{} Newton steps without reaching the target", settings.max_newton_steps);
      break;
    }
    hooks.hold();
    // K v = -(f(d + eps v) - f(d)) / eps, K = -df/dd the tangent stiffness; the step moves
    // the largest perturbed coordinate by `perturbation` of the mean spacing, where the
    // difference's truncation (~ eps) and round-off (~ 1e-16 / eps) errors are both small.
    const double reach = settings.perturbation * coords.mean_spacing();
    auto apply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
      const double largest = v.cwiseAbs().maxCoeff();
      if (!(largest > 0.0)) {
        out.setZero(v.size());
        return;
      }
      const double eps = reach / largest;
      coords.evaluate(x + eps * v, perturbed_r, hooks.follow);
      out = (r - perturbed_r) / eps;
    };
    GmresSettings linear;
    linear.relative_tol = forcing;
    linear.max_iterations = settings.max_krylov_iterations;
    linear.restart = settings.restart;
    const GmresResult solved = gmres(apply, r, preconditioner, linear, step);
    report.krylov_iterations += solved.iterations;
    // Backtracking on the residual's 2-norm (Armijo's condition for |r|^2 / 2, whose
    // Newton direction descends whatever the forces' symmetry).
    const double norm = r.norm();
    double alpha = 1.0;
    bool accepted = false;
    for (int halving = 0; halving <= 10; ++halving, alpha *= 0.5) {
      trial_x = x + alpha * step;
      coords.evaluate(trial_x, trial_r, hooks.follow);
      // An inverted or non-finite trial state is shortened like one whose residual grew.
      if (coords.admissible(trial_r) && trial_r.norm() <= (1.0 - 1e-4 * alpha) * norm) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      coords.evaluate(x, r, hooks.follow);  // back to the last accepted state, its material state and forces
      report.stop = fmt::format(
          "the line search found no decrease of the residual after Newton step {} (GMRES's "
          "estimate: {:.2g} of its right-hand side after {} iterations)",
          report.newton_steps + 1, solved.relative_residual, solved.iterations);
      report.residual = hooks.residual();
      break;
    }
    const std::vector<std::vector<Vec3>> before = coords.split(x);
    x = trial_x;
    hooks.carry(before);
    coords.read(x);  // the constrained coordinates as imposed
    coords.residual(r);
    report.residual = hooks.residual();
    report.residuals.push_back(report.residual);
    ++report.newton_steps;
    report.force_evaluations = coords.evaluations;
    if (hooks.stepped) hooks.stepped(report);
    // Eisenstat and Walker's second choice (gamma 0.9, exponent 2) with its safeguard:
    // loose solves far from the solution, tighter ones as the residual falls.
    const double new_norm = r.norm();
    double next = 0.9 * (new_norm / previous_norm) * (new_norm / previous_norm);
    if (0.9 * forcing * forcing > 0.1) next = std::max(next, 0.9 * forcing * forcing);
    forcing = std::clamp(next, 1e-6, 0.5);
    previous_norm = new_norm;
  }
  report.force_evaluations = coords.evaluations;
  return report;
}

}  // namespace rkpm::sim
