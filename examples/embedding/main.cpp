// rkpm as a library: this program composes a scene in C++, relaxes it step by step
// with the library's integrator, reads the displacement field and checks it against
// the closed form. Given a scene file it runs that instead, as `rkpm run` would.
//
//   embed_rkpm                      a neo-Hookean bar pulled at both ends
//   embed_rkpm SCENE.toml [OUT_DIR] any scene, output in OUT_DIR (default out/)
#include <rkpm/scene/scene.hpp>
#include <rkpm/sim/build.hpp>
#include <rkpm/sim/integrator.hpp>
#include <rkpm/sim/run.hpp>

#include <fmt/format.h>

#include <cmath>
#include <iostream>

namespace {

constexpr double kMu = 1000.0, kLambda = 4000.0;  // Pa
constexpr double kLength = 1.0;                   // m

// A bar of 1 x 0.6 x 0.6 m pulled by `tension` on both ends, written as a scene.
std::string bar_scene(double tension) {
  return fmt::format(R"([scene]
name = "embedded_bar"
[integrator]
mode = "relax"
relax_force_tol = 1e-7
relax_velocity_tol = 1e-12
[[body]]
name = "bar"
[body.cloud]
generator = "block"
size = [{length}, 0.6, 0.6]
cells = [6, 4, 4]
[body.material]
model = "neo_hookean"
mu = {mu}
lambda = {lambda}
[[term]]
type = "surface_pressure"
body = "bar"
surface = "xmin"
pressure = {pressure}
[[term]]
type = "surface_pressure"
body = "bar"
surface = "xmax"
pressure = {pressure}
)",
                     fmt::arg("length", kLength), fmt::arg("mu", kMu), fmt::arg("lambda", kLambda),
                     fmt::arg("pressure", -tension));
}

// Uniaxial tension T of W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2: F = diag(l, t, t)
// with mu (t^2 - 1) + lambda ln J = 0 (free sides) and mu (l^2 - t^2) / J = T. Newton's
// method on the two equations.
double closed_form_stretch(double tension) {
  double l = 1.0, t = 1.0;
  for (int it = 0; it < 50; ++it) {
    const auto r = [&](double a, double b) {
      const double J = a * b * b;
      return std::pair<double, double>{kMu * (a * a - b * b) / J - tension, kMu * (b * b - 1.0) + kLambda * std::log(J)};
    };
    const auto [r1, r2] = r(l, t);
    const double h = 1e-7;
    const auto [a1, a2] = r(l + h, t);
    const auto [b1, b2] = r(l, t + h);
    const double j11 = (a1 - r1) / h, j21 = (a2 - r2) / h, j12 = (b1 - r1) / h, j22 = (b2 - r2) / h;
    const double det = j11 * j22 - j12 * j21;
    l -= (j22 * r1 - j12 * r2) / det;
    t -= (-j21 * r1 + j11 * r2) / det;
  }
  return l;
}

int run_scene_file(const char* path, const char* out) {
  try {
    const rkpm::scene::Scene scene = rkpm::scene::load_scene(path);
    rkpm::sim::RunOptions options;
    options.out_dir = out;
    return rkpm::sim::run_scene(scene, options, std::cerr);
  } catch (const rkpm::scene::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return rkpm::sim::kBadInput;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) return run_scene_file(argv[1], argc > 2 ? argv[2] : "out");

  const double tension = 300.0;  // Pa
  const rkpm::scene::Scene scene = rkpm::scene::parse_scene(bar_scene(tension), "embedded_bar.toml");
  const auto world = rkpm::sim::build_world(scene);
  rkpm::sim::Integrator integrator(*world, rkpm::sim::integrator_settings(scene));
  integrator.initialize();
  while (!(world->step > 0 && integrator.converged()) && world->step < 100000) integrator.step();

  // The bar's stretch from its end faces' mean physical displacement.
  const rkpm::sim::Body& bar = *world->bodies.front();
  std::vector<rkpm::Vec3> u;
  rkpm::sim::physical_displacement(bar, u);
  double left = 0.0, right = 0.0;
  int n_left = 0, n_right = 0;
  for (std::size_t i = 0; i < bar.size(); ++i) {
    const double x = bar.cloud.X[i].x();
    if (x < 1e-12) left += u[i].x(), ++n_left;
    if (x > kLength - 1e-12) right += u[i].x(), ++n_right;
  }
  const double stretch = 1.0 + (right / n_right - left / n_left) / kLength;
  const double expected = closed_form_stretch(tension);
  const double error = std::abs(stretch - expected) / (expected - 1.0);
  fmt::print("{} particles relaxed in {} steps ({}); stretch {:.6f}, closed form {:.6f}, error {:.2e} of the strain\n",
             bar.size(), world->step, integrator.converged() ? "converged" : "not converged", stretch, expected, error);
  return integrator.converged() && error < 1e-3 ? 0 : 1;
}
