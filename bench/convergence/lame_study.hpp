// One run of the convergence study: the Lame sphere (lame_sphere.hpp) discretised
// by a cubed-sphere shell cloud, solved with one nodal-integration scheme, and its
// errors against the closed form.
#pragma once

#include "lame_sphere.hpp"
#include "projected_cg.hpp"

#include <string>

namespace rkpm::study {

enum class Scheme {
  StabilizedSCNI,  // SCNI + interpolation-residual stabilization: what the simulator runs
  SCNI,            // smoothed gradients alone
  Direct,          // gradients of the shape functions at the particles (contrast)
};
std::string scheme_name(Scheme s);
Scheme parse_scheme(const std::string& name);  // throws std::invalid_argument

struct Resolution {
  int face_cells = 8;  // cubed-sphere cells along a face edge
  int layers = 4;      // particle layers through the wall
};

struct CaseSettings {
  LameSphere problem;
  double support = 2.0;  // support radius / local spacing (RKSettings::support)
  double alpha = 0.1;    // stabilization coefficient, used by StabilizedSCNI only
  rk::SupportShape support_shape = rk::SupportShape::Sphere;              // [body.rk] support_shape
  rk::GradientPrecision gradient_precision = rk::GradientPrecision::Double;  // [body.rk] gradient_precision
  rk::FacetRule cell_quadrature = rk::FacetRule::Corners;                    // [body.rk] cell_quadrature
  SolverSettings solver;
};

struct CaseResult {
  Scheme scheme = Scheme::StabilizedSCNI;
  Resolution resolution;
  std::size_t particles = 0;
  double h = 0.0;             // mean spacing (volume / particles)^(1/3)
  double l2_error = 0.0;      // relative, displacement at the particles
  double energy_error = 0.0;  // relative, strain energy norm at the integration points
  double setup_seconds = 0.0; // RK set-up and every operator (cloud generation excluded)
  double solve_seconds = 0.0;
  SolverReport solver;
  double stabilization_energy_fraction = 0.0;  // E_stab / E_strain of the solution
};

CaseResult run_lame_case(Scheme scheme, Resolution resolution, const CaseSettings& settings);

}  // namespace rkpm::study
