#include "rkpm/sim/build.hpp"

#include "clouds/catalog.hpp"
#include "sim/setup/row_model.hpp"
#include "materials/catalog.hpp"
#include "rkpm/common/split_mix64.hpp"
#include "rkpm/particles/generators.hpp"
#include "rkpm/par/partition.hpp"
#include "rkpm/particles/renumber.hpp"
#include "rkpm/sim/body_points.hpp"
#include "rkpm/sim/body_state.hpp"
#include "terms/catalog.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rkpm::sim {

namespace {

std::string where(const scene::ParamSet& p) { return fmt::format("{}:{}: [{}]", p.file(), p.table_line(), p.section()); }

// Small-strain shear modulus at each point: the stiffness scale of the stabilization.
std::vector<double> shear_moduli(const Body& body) {
  std::vector<double> mu(body.size());
  for (std::size_t i = 0; i < mu.size(); ++i) mu[i] = shear_modulus(body, static_cast<Index>(i));
  return mu;
}

// The stabilization coefficient alpha of [body.rk], at the wall's own thickness when it
// is given for a reference thickness: alpha (T / T_ref)^2 (docs/theory/numerics.md,
// "Walls of another thickness").
double stabilization_coefficient(const scene::BodySpec& spec) {
  const double alpha = spec.rk.real("stabilization");
  const double reference = spec.rk.real("stabilization_reference_thickness");
  if (reference == 0.0) return alpha;
  const double thickness = clouds::wall_thickness(spec);
  if (!(thickness > 0.0))
    throw SetupError(spec.rk.error("stabilization_reference_thickness",
                                   fmt::format("a cloud with a wall thickness (generator = \"shell\", not \"{}\"), or 0",
                                               spec.generator()))
                         .what());
  // A reference more than ten times off the wall is a unit slip (um for m), which would
  // switch the stabilization off or make it dominate the wall.
  const double ratio = thickness / reference;
  if (ratio < 0.1 || ratio > 10.0)
    throw SetupError(spec.rk.error("stabilization_reference_thickness",
                                   fmt::format("a thickness within a factor 10 of the wall's ({:g} m), in metres",
                                               thickness))
                         .what());
  return alpha * ratio * ratio;
}

// Shortest mesh edge at each particle: the length scale of the stable time step.
std::vector<double> shortest_edges(const particles::Cloud& cloud) {
  std::vector<double> h(cloud.size(), INFINITY);
  for (int e = 0; e < cloud.mesh.n_elements(); ++e) {
    const auto* nodes = cloud.mesh.element_nodes(e);
    const int m = cloud.mesh.element_size(e);
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j) {
        const double len = (cloud.X[nodes[i]] - cloud.X[nodes[j]]).norm();
        h[nodes[i]] = std::min(h[nodes[i]], len);
        h[nodes[j]] = std::min(h[nodes[j]], len);
      }
  }
  return h;
}

std::vector<ConstrainedComponent> constrained_components(const scene::BodySpec& spec, const particles::Cloud& cloud) {
  std::vector<ConstrainedComponent> out;
  for (const auto& bc : spec.boundaries) {
    const std::string surface = bc.text("surface");
    const std::uint32_t bit = surface == "all" ? 0u : cloud.surface_bit(surface);
    const Vec3 value = bc.choice("type") == "velocity" ? bc.vec3("value") : Vec3::Zero();
    const std::string axes = bc.text("axes");
    for (Index p : cloud.boundary_particles) {
      if (bit != 0u && !(cloud.surface_mask[p] & bit)) continue;
      for (int a = 0; a < 3; ++a)
        if (axes.find("xyz"[a]) != std::string::npos) out.push_back({p, a, value[a]});
    }
  }
  return out;
}

std::unique_ptr<Body> build_body(const scene::BodySpec& spec, int id, std::uint64_t seed, const par::Comm& comm,
                                 std::string& warning) {
  auto body = std::make_unique<Body>();
  body->name = spec.name();
  body->id = id;
  body->density = spec.body.real("density");
  try {
    body->cloud = build_cloud(spec);
  } catch (const particles::CloudError& e) {
    throw SetupError(fmt::format("{} body '{}': {}", where(spec.cloud), body->name, e.what()));
  }
  body->cloud.name = body->name;
  par::Partition partition;
  if (comm.parallel()) {
    try {
      partition = par::partition_cloud(body->cloud, comm.size());
    } catch (const std::invalid_argument& e) {
      throw SetupError(fmt::format("{} body '{}': {}", where(spec.cloud), body->name, e.what()));
    }
    // The curve partition keeps the one-process numbering (par/partition.hpp): nothing
    // to renumber, and the particle ids are already the one-process ones.
    if (!std::is_sorted(partition.order.begin(), partition.order.end())) {
      particles::renumber(body->cloud, partition.order);
      body->original_id.assign(partition.order.begin(), partition.order.end());
    }
  }
  const auto& cloud = body->cloud;
  const std::size_t n = cloud.size();
  const std::vector<ConstrainedComponent> constrained = constrained_components(spec, cloud);

  try {
    body->rk_settings = rk_settings(spec);
    body->cell_quadrature = cell_quadrature(spec.rk);
    const rk::RKApproximation rk = approximation(*body);
    const auto scheme = integration_scheme(spec.rk);
    // Distributed: this rank builds the rows of the points it owns (and, of the
    // interpolation, those of the constrained particles too, whose small system every
    // rank solves); the others' rows stay empty, so the operators' memory and set-up
    // time are divided over the ranks.
    std::vector<char> own_rows, interpolation_rows;
    if (comm.parallel()) {
      own_rows.assign(n, 0);
      std::fill(own_rows.begin() + partition.offset[static_cast<std::size_t>(comm.rank())],
                own_rows.begin() + partition.offset[static_cast<std::size_t>(comm.rank()) + 1], 1);
      interpolation_rows = own_rows;
      for (const auto& c : constrained) interpolation_rows[static_cast<std::size_t>(c.particle)] = 1;
    }
    body->gradient =
        rk::build_gradient_operator(cloud, rk, scheme, gradient_precision(spec.rk), own_rows, body->cell_quadrature);
    body->interpolation = rk::build_nodal_interpolation(cloud, rk, interpolation_rows);
  } catch (const rk::ApproximationError& e) {
    throw SetupError(fmt::format("{} body '{}': {}", where(spec.rk), body->name, e.what()));
  }
  body->spacing = shortest_edges(cloud);
  body->mass.resize(n);
  for (std::size_t i = 0; i < n; ++i) body->mass[i] = body->density * cloud.volume[i];
  body->inertia = body->mass;

  // Initial state: homogeneous stretch about the centroid, velocity plus random noise.
  const Vec3 stretch = spec.initial.vec3("stretch");
  const Vec3 centre = reference_centroid(*body);
  const Vec3 velocity = spec.initial.vec3("velocity");
  const double noise = spec.initial.real("random_velocity");
  SplitMix64 random(seed * 0x100000001b3ULL + static_cast<std::uint64_t>(id));
  // The noise is drawn in the one-rank numbering, so every rank count starts alike.
  std::vector<Vec3> kick(noise > 0.0 ? n : 0);
  for (auto& k : kick) k = noise * Vec3(random.symmetric_unit(), random.symmetric_unit(), random.symmetric_unit());
  body->d.resize(n);
  body->v.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    body->d[i] = (stretch.array() - 1.0).matrix().cwiseProduct(cloud.X[i] - centre);
    body->v[i] = velocity;
    if (!kick.empty()) body->v[i] += kick[body->original_id.empty() ? i : static_cast<std::size_t>(body->original_id[i])];
  }
  body->force.assign(n, Vec3::Zero());
  body->F.assign(n, Mat3::Identity());

  warning = materials::make_material(spec, *body);
  body->stabilization =
      rk::build_stabilization(cloud.volume, shear_moduli(*body), stabilization_coefficient(spec));
  try {
    body->constraints = EssentialBC(body->interpolation, constrained, body->d);
  } catch (const std::runtime_error& e) {
    throw SetupError(fmt::format("{}: body '{}': {}", spec.body.file(), body->name, e.what()));
  }
  // The rows this rank owns reference the ghosts: through the smoothed gradients and,
  // for the stabilization and the physical displacement, the interpolation.
  if (comm.parallel()) {
    // The current normals at an owned surface particle (a material state anchored to the surface) read
    // the nodes of every surface face it belongs to.
    std::vector<Index> face_nodes;
    for (const auto& face : cloud.boundary_faces) {
      const auto* nodes = face.nodes;
      const bool touches = std::any_of(nodes, nodes + face.n_nodes, [&](std::int32_t i) {
        return i >= partition.offset[static_cast<std::size_t>(comm.rank())] &&
               i < partition.offset[static_cast<std::size_t>(comm.rank()) + 1];
      });
      if (touches) face_nodes.insert(face_nodes.end(), nodes, nodes + face.n_nodes);
    }
    body->ghosts.build(comm, partition.offset,
                       {{&body->gradient.row_offset, &body->gradient.col},
                        {&body->interpolation.row_offset, &body->interpolation.col}},
                       std::move(face_nodes));
    body->constraints.distribute(comm, partition.offset);
    // A frame's piece holds the elements whose lowest node this rank owns (each element
    // written once over the ranks), with their other nodes as a halo.
    std::vector<Index> halo;
    const auto& mesh = cloud.mesh;
    for (int e = 0; e < mesh.n_elements(); ++e) {
      const std::int32_t* nodes = mesh.element_nodes(e);
      const Index lowest = *std::min_element(nodes, nodes + mesh.element_size(e));
      if (lowest >= body->owned_begin() && lowest < body->owned_end()) halo.insert(halo.end(), nodes, nodes + mesh.element_size(e));
    }
    body->output_halo.build(comm, partition.offset, std::move(halo));
  }
  return body;
}

}  // namespace

particles::Cloud build_cloud(const scene::BodySpec& spec) {
  particles::Cloud cloud = clouds::make_cloud(spec);
  if (spec.rk.choice("particle_order") == "morton") particles::renumber(cloud, particles::morton_order(cloud.X));
  return cloud;
}

rk::RKSettings rk_settings(const scene::BodySpec& spec) {
  const scene::ParamSet& p = spec.rk;
  rk::RKSettings s;
  s.kernel = p.choice("kernel") == "quintic" ? rk::KernelType::QuinticBSpline : rk::KernelType::CubicBSpline;
  s.support = p.real("support");
  s.shape = resolved_support_shape(spec);
  s.basis = p.choice("basis") == "quadratic" ? rk::Basis::Quadratic : rk::Basis::Linear;
  return s;
}

rk::Integration integration_scheme(const scene::ParamSet& p) {
  return p.choice("integration") == "direct" ? rk::Integration::Direct : rk::Integration::SCNI;
}

rk::GradientPrecision gradient_precision(const scene::ParamSet& p) {
  return p.choice("gradient_precision") == "float" ? rk::GradientPrecision::Float : rk::GradientPrecision::Double;
}

rk::FacetRule cell_quadrature(const scene::ParamSet& p) {
  return p.choice("cell_quadrature") == "centroids" ? rk::FacetRule::Centroids : rk::FacetRule::Corners;
}

IntegratorSettings integrator_settings(const scene::Scene& scene) {
  const auto& p = scene.integrator;
  IntegratorSettings s;
  s.mode = p.choice("mode") == "relax" ? Mode::Relax : Mode::Dynamic;
  s.dt = p.real("dt");
  s.dt_safety = p.real("dt_safety");
  s.damping = p.real("damping");
  s.relax_force_tol = p.real("relax_force_tol");
  s.relax_velocity_tol = p.real("relax_velocity_tol");
  s.relax_state_tol = p.real("relax_state_tol");
  s.mass_scaling = p.flag("mass_scaling");
  s.contact_mass_scaling = p.flag("contact_mass_scaling");
  s.fire = FireParameters::named(p.choice("relax_method"));
  s.newton_krylov_finish = p.choice("relax_finish") == "newton_krylov";
  s.newton.force_tol = p.real("finish_force_tol");
  s.newton.max_newton_steps = static_cast<int>(p.integer("finish_max_newton_steps"));
  s.measured_stable_step = p.choice("stable_step") == "measured";
  s.stable_step_auto = p.choice("stable_step") == "auto";
  s.stable_step_interval = p.integer("stable_step_interval");
  return s;
}

void check_distributable_terms(const scene::Scene& scene, const World& world) {
  if (!world.comm->parallel()) return;
  for (std::size_t k = 0; k < world.terms.size(); ++k)
    if (!world.terms[k]->distributed()) {
      const auto& term = scene.terms[k].params;
      throw SetupError(fmt::format("{}:{}: [[term]] type = \"{}\" does not run on more than one rank yet (this run "
                                   "has {}); run the scene as one process (without mpirun), or see "
                                   "docs/development/adding-a-term.md for what a term needs to run distributed",
                                   term.file(), term.table_line(), scene.terms[k].type(), world.comm->size()));
    }
}

void check_newton_krylov_finish(const scene::Scene& scene, const World& world) {
  const auto& p = scene.integrator;
  if (p.choice("relax_finish") != "newton_krylov") return;
  std::string why;
  if (world.comm->parallel()) why = fmt::format("it runs on one process (this run has {} ranks)", world.comm->size());
  for (const auto& b : world.bodies)
    if (why.empty() && state_evolves_in_time(*b))
      why = fmt::format("body '{}' has a material state that relaxes in time by itself (an LCE with mobility > 0, "
                        "a viscous material); the finish solves for the coordinates with the state carried, so it "
                        "needs a state that follows the motion alone (an LCE with mobility = 0)",
                        b->name);
  if (!why.empty())
    throw SetupError(fmt::format("{}:{}: [integrator] relax_finish = \"newton_krylov\": {}", p.file(),
                                 p.line("relax_finish"), why));
}

std::unique_ptr<World> build_world(const scene::Scene& scene, const par::Comm& comm) {
  auto world = std::make_unique<World>();
  world->comm = &comm;
  const auto seed = static_cast<std::uint64_t>(scene.integrator.integer("seed"));
  int id = 0;
  for (const auto& spec : scene.bodies) {
    std::string warning;
    world->bodies.push_back(build_body(spec, id++, seed, comm, warning));
    if (!warning.empty()) world->setup_warnings.push_back(warning);
  }
  for (const auto& term : scene.terms) world->terms.push_back(terms::make_term(term, *world));
  return world;
}

}  // namespace rkpm::sim
