// Builds a World from a validated scene: clouds, RK operators, materials, initial
// fields, boundary conditions and exactly the terms the scene declares.
#pragma once

#include "rkpm/par/comm.hpp"
#include "rkpm/scene/scene.hpp"
#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/world.hpp"

#include <memory>
#include <stdexcept>

namespace rkpm::sim {

// A scene that validated but cannot be built (a cloud file the importer rejects,
// a support too small for the cloud, a term this version does not provide). The
// message names the scene file and the body or term; the program exits with 2.
struct SetupError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// On more than one rank of `comm`, each body is partitioned (par/partition.hpp) and
// renumbered so that this rank owns one range of it, and its ghost layer is built.
std::unique_ptr<World> build_world(const scene::Scene& scene, const par::Comm& comm = par::Comm::world());

// Every material, the integrators and every term of the catalog run on more than one
// rank. A term that does not say so (Term::distributed: a new term before its
// exchanges are written) makes a run on more than one rank stop with a SetupError
// naming the scene's line, so that no rank count silently changes the physics. Passes
// on one rank.
void check_distributable_terms(const scene::Scene& scene, const World& world);

// relax_finish = "newton_krylov" runs on one process, and carries the materials' state
// with the coordinates, so a state that relaxes in time by itself (an LCE with
// mobility > 0, a viscous material) would be an
// unknown it does not solve for: either stops the run with a SetupError naming the
// scene's line. Passes when the scene has no such finish.
void check_newton_krylov_finish(const scene::Scene& scene, const World& world);

// The particle cloud of one body, as build_world makes it (generator or imported mesh).
// Throws particles::CloudError for a mesh the importer rejects.
particles::Cloud build_cloud(const scene::BodySpec& body);

IntegratorSettings integrator_settings(const scene::Scene& scene);

// The RK approximation a body's [body.rk] table asks for (support_shape = "auto"
// resolved from the cloud's size, as the pre-flight estimate resolves it), and the
// nodal-integration scheme.
rk::RKSettings rk_settings(const scene::BodySpec& body);
rk::Integration integration_scheme(const scene::ParamSet& rk_table);
rk::GradientPrecision gradient_precision(const scene::ParamSet& rk_table);
rk::FacetRule cell_quadrature(const scene::ParamSet& rk_table);

}  // namespace rkpm::sim
