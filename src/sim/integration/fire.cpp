#include "rkpm/sim/fire.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rkpm::sim {

FireParameters FireParameters::named(const std::string& method) {
  if (method == "fire") return bitzek2006();
  if (method == "fire2") return guenole2020();
  throw std::invalid_argument("unknown relax_method '" + method + "' (expected \"fire\" or \"fire2\")");
}

void stop_bodies(World& world) {
  for (auto& bp : world.bodies) {
    Body& b = *bp;
    std::fill(b.v.begin(), b.v.end(), Vec3::Zero());
    b.constraints.impose(b.d, b.v);
  }
}

FireStep Fire::update(World& world, double dt, double dt_max) {
  // P = F . v, |v|^2 and |F|^2 over every degree of freedom of every body (and rank),
  // summed exactly: they steer every step, so their bits must not depend on how the
  // particles are split over threads and ranks (common/exact_sum.hpp).
  ExactSum power_sum, vv_sum, ff_sum;
  for (const auto& bp : world.bodies) {
    const Body& b = *bp;
#pragma omp parallel for schedule(static) reduction(+ : power_sum, vv_sum, ff_sum)
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i) {
      power_sum.add(b.force[i].dot(b.v[i]));
      vv_sum.add(b.v[i].squaredNorm());
      ff_sum.add(b.force[i].squaredNorm());
    }
  }
  const std::vector<double> sums = world.comm->sum(std::vector<ExactSum>{power_sum, vv_sum, ff_sum});
  const double power = sums[0], vv = sums[1], ff = sums[2];
  FireStep result;
  result.dt = dt;
  if (power > 0.0) {
    // Downhill: steer the velocity toward the force direction, keeping its magnitude
    // at most; the kinetic energy this removes is dissipation.
    const double kinetic_before = kinetic_energy(world);
    const double mix = ff > 0.0 ? alpha_ * std::sqrt(vv / ff) : 0.0;
    for (auto& bp : world.bodies) {
      Body& b = *bp;
#pragma omp parallel for schedule(static)
      for (Index i = b.owned_begin(); i < b.owned_end(); ++i) b.v[i] = (1.0 - alpha_) * b.v[i] + mix * b.force[i];
      b.constraints.impose(b.d, b.v);
    }
    result.dissipated = kinetic_before - kinetic_energy(world);
    if (++positive_steps_ > p_.n_delay) {
      result.dt = std::min(dt * p_.f_inc, dt_max);
      alpha_ *= p_.f_alpha;
    }
    return result;
  }
  // Uphill: stop; all the kinetic energy is dissipated.
  result.dissipated = kinetic_energy(world);
  positive_steps_ = 0;
  if (!(p_.initial_delay && world.step < p_.n_delay)) {
    alpha_ = p_.alpha_start;
    result.dt = std::max(dt * p_.f_dec, p_.dt_min_fraction * dt_max);
  }
  if (p_.half_step_back)
    result.step_back = true;
  else
    stop_bodies(world);
  return result;
}

}  // namespace rkpm::sim
