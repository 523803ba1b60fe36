// Wave speed in a laterally confined column. Why the confined column: with every
// lateral face held in x and y, the continuum problem is exactly one-dimensional
// (uniaxial strain), its speed is the P-wave speed c_P = sqrt((K + 4 mu / 3) / rho)
// at every wavelength, and the linear RK basis reproduces the uniform lateral state
// exactly. A free slender bar would add the geometric (Pochhammer) dispersion of a
// two-cell cross-section to the discretisation's own, and its long-wave speed
// sqrt(E / rho) is reached only for wavelengths much longer than the column is wide.
//
// The RK discretisation is dispersive: short waves travel slower, so a step front
// spreads into a ramp with trailing oscillations. The long-wave speed is measured
// without bias by the displacement behind the front: for a velocity step v0 at z = 0,
// u(z, t) = v0 (t - z / c) once the front has passed, because the front's smearing
// has zero mean (the Airy-function front of a weakly dispersive chain). A straight
// line fitted to u(t) at a station therefore crosses zero at the arrival time z / c.
#include "sim_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace rkpm::sim {
namespace {

constexpr double kLength = 2.0, kSpacing = 0.05, kPushVelocity = 1e-4;  // m, m, m/s
constexpr double kC1 = 400.0, kC2 = 100.0, kLambda = 2000.0, kDensity = 1000.0;

const std::string kColumn = R"([scene]
name = "column"
[integrator]
t_end = 1.0
dt_safety = 0.5
[[body]]
name = "column"
density = 1000
[body.cloud]
generator = "block"
size = [0.1, 0.1, 2.0]
cells = [2, 2, 40]
[body.material]
model = "mooney_rivlin"
c1 = 400
c2 = 100
lambda = 2000
[[body.boundary]]
surface = "xmin"
axes = "xy"
[[body.boundary]]
surface = "xmax"
axes = "xy"
[[body.boundary]]
surface = "ymin"
axes = "xy"
[[body.boundary]]
surface = "ymax"
axes = "xy"
[[body.boundary]]
surface = "zmin"
type = "velocity"
value = [0, 0, 1e-4]
axes = "z"
)";

struct Sample {
  double t, u;
};

// Mean physical u_z over the particles of the cross-section at height z.
double mean_uz_at(const Body& body, const std::vector<Vec3>& u, double z) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < body.size(); ++i)
    if (std::abs(body.cloud.X[i].z() - z) < 0.25 * kSpacing) {
      sum += u[i].z();
      ++count;
    }
  EXPECT_GT(count, 0) << "no particles at z = " << z;
  return count > 0 ? sum / count : 0.0;
}

// Zero crossing of the least-squares line through the samples.
double zero_crossing(const std::vector<Sample>& s) {
  double st = 0, su = 0, stt = 0, stu = 0;
  for (const auto& p : s) {
    st += p.t;
    su += p.u;
    stt += p.t * p.t;
    stu += p.t * p.u;
  }
  const double n = static_cast<double>(s.size());
  const double slope = (n * stu - st * su) / (n * stt - st * st);
  const double intercept = (su - slope * st) / n;
  return -intercept / slope;
}

TEST(WaveSpeed, ConfinedColumnCarriesAStepAtThePWaveSpeed) {
  testing::ScopedThreads one(1);
  const double mu = 2.0 * (kC1 + kC2), K = 4.0 * kLambda;  // small-strain moduli (VERIFICATION section 2)
  const double c_p = std::sqrt((K + 4.0 * mu / 3.0) / kDensity);

  auto sw = testing::build_from_text(kColumn);
  Integrator integrator(*sw.world, sw.settings);
  integrator.initialize();
  const Body& body = *sw.world->bodies.front();

  // Two stations; each is sampled from well behind the front until well before the
  // wave reflected at the free top end returns.
  const std::vector<double> stations = {0.5, 1.0};
  std::vector<std::vector<Sample>> samples(stations.size());
  std::vector<Vec3> u;
  const double t_stop = (2.0 * kLength - stations.back()) / c_p - 0.1;
  while (sw.world->time < t_stop) {
    integrator.step();
    physical_displacement(body, u);
    for (std::size_t s = 0; s < stations.size(); ++s) {
      const double z = stations[s], t = sw.world->time;
      const double arrival = z / c_p, reflected = (2.0 * kLength - z) / c_p;
      if (t > arrival + 0.15 && t < reflected - 0.1) samples[s].push_back({t, mean_uz_at(body, u, z) / kPushVelocity});
    }
  }
  std::vector<double> arrival(stations.size());
  for (std::size_t s = 0; s < stations.size(); ++s) {
    ASSERT_GT(samples[s].size(), 10u);
    arrival[s] = zero_crossing(samples[s]);
    const double speed = stations[s] / arrival[s];
    std::printf("station z = %.2f m: arrival %.5f s, speed %.5f m/s, c_P = %.5f m/s, relative difference %+.3e\n",
                stations[s], arrival[s], speed, c_p, speed / c_p - 1.0);
    EXPECT_NEAR(speed / c_p, 1.0, 0.02);
  }
  const double between = (stations[1] - stations[0]) / (arrival[1] - arrival[0]);
  std::printf("between the stations: %.5f m/s, relative difference %+.3e (dt = %.4g s, %lld steps)\n", between,
              between / c_p - 1.0, integrator.dt(), static_cast<long long>(sw.world->step));
  EXPECT_NEAR(between / c_p, 1.0, 0.02);
}

}  // namespace
}  // namespace rkpm::sim
