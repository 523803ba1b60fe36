#include "rkpm/sim/terms.hpp"

#include "rkpm/sim/build.hpp"
#include "rkpm/sim/contact.hpp"
#include "rkpm/sim/surface_tension.hpp"
#include "rkpm/sim/volume_constraint.hpp"
#include "rkpm/sim/wall_contact.hpp"

#include <fmt/format.h>

#include <cmath>

namespace rkpm::sim {

void BodyForce::add_forces(World&) {
  const auto n = static_cast<Index>(body_.size());
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) body_.force[i] += body_.mass[i] * g_;
}

double BodyForce::power(const World&) const {
  double p = 0.0;
  const auto n = static_cast<Index>(body_.size());
#pragma omp parallel for schedule(static) reduction(+ : p)
  for (Index i = 0; i < n; ++i) p += body_.mass[i] * g_.dot(body_.v[i]);
  return p;
}

SurfacePressure::SurfacePressure(Body& body, std::uint32_t surface_bit, double pressure)
    : body_(body), pressure_(pressure), force_(body.size(), Vec3::Zero()) {
  const auto& q = body.boundary;
  for (std::size_t f = 0; f < q.point.size(); ++f)
    if (surface_bit == 0u || (q.surface_mask[f] & surface_bit)) facets_.push_back(f);
}

void SurfacePressure::add_forces(World&) {
  const auto& q = body_.boundary;
  std::fill(force_.begin(), force_.end(), Vec3::Zero());
  // Serial over facets: scattering to particles in a fixed order keeps the sum deterministic.
  for (std::size_t f : facets_) {
    const Mat3& F = body_.F[q.owner[f]];
    const Vec3 current_area = F.determinant() * F.inverse().transpose() * q.area[f];
    for (Index k = q.row_offset[f]; k < q.row_offset[f + 1]; ++k) force_[q.col[k]] -= pressure_ * q.psi[k] * current_area;
  }
  for (std::size_t i = 0; i < force_.size(); ++i) body_.force[i] += force_[i];
}

double SurfacePressure::power(const World&) const {
  double p = 0.0;
  for (std::size_t i = 0; i < force_.size(); ++i) p += force_[i].dot(body_.v[i]);
  return p;
}

std::unique_ptr<Term> make_term(const scene::TermSpec& spec, World& world) {
  const auto& p = spec.params;
  const std::string type = spec.type();
  auto body_named = [&](const std::string& key) -> Body& {
    Body* b = world.find_body(p.text(key));
    if (!b) throw SetupError(fmt::format("{}:{}: [term] {} = \"{}\": no such body", p.file(), p.line(key), key, p.text(key)));
    return *b;
  };
  if (type == "body_force") return std::make_unique<BodyForce>(body_named("body"), p.vec3("acceleration"));
  if (type == "surface_pressure") {
    Body& b = body_named("body");
    const std::string surface = p.text("surface");
    return std::make_unique<SurfacePressure>(b, surface == "all" ? 0u : b.cloud.surface_bit(surface), p.real("pressure"));
  }
  if (type == "volume_constraint") {
    Body& b = body_named("body");
    const std::string surface = p.text("surface");
    return std::make_unique<VolumeConstraint>(b, surface == "all" ? 0u : b.cloud.surface_bit(surface), p.real("bulk"),
                                              p.real("target"));
  }
  if (type == "surface_tension") {
    Body& b = body_named("body");
    try {
      return std::make_unique<SurfaceTension>(b, p.text("surface"), p.real("gamma"));
    } catch (const std::invalid_argument& e) {
      throw SetupError(fmt::format("{}:{}: [term] {}", p.file(), p.table_line(), e.what()));
    }
  }
  if (type == "contact") {
    const auto& names = p.texts("bodies");
    Body* a = world.find_body(names[0]);
    Body* b = world.find_body(names[1]);
    if (!a || !b)
      throw SetupError(fmt::format("{}:{}: [term] bodies = [\"{}\", \"{}\"]: no such body", p.file(), p.line("bodies"),
                                   names[0], names[1]));
    ContactSettings s;
    s.epsilon = p.real("epsilon");
    s.s0 = p.real("s0");
    s.cutoff = p.real("cutoff");
    s.skin = p.real("skin");
    s.beta = {p.reals("beta")[0], p.reals("beta")[1]};
    s.law = p.choice("stiffness_law") == "linear" ? StiffnessLaw::linear : StiffnessLaw::none;
    if (s.law == StiffnessLaw::linear) s.substrate = p.text("substrate") == names[0] ? 0 : 1;
    s.stiffness_reference = p.real("stiffness_reference");
    s.report_surface = p.text("report_surface");
    s.contact_gap = p.real("contact_gap");
    try {
      return std::make_unique<Contact>(*a, *b, s);
    } catch (const std::invalid_argument& e) {
      throw SetupError(fmt::format("{}:{}: [term] {}", p.file(), p.table_line(), e.what()));
    }
  }
  if (type == "wall_contact") {
    WallContactSettings s;
    s.surface = p.text("surface");
    s.distance = p.real("distance");
    s.pressure = p.real("pressure");
    s.exclusion = p.real("exclusion");
    s.skin = p.real("skin");
    std::unique_ptr<WallContact> term;
    try {
      term = std::make_unique<WallContact>(body_named("body"), s);
    } catch (const std::invalid_argument& e) {
      throw SetupError(fmt::format("{}:{}: [term] {}", p.file(), p.table_line(), e.what()));
    }
    // A square lattice of spacing a has holes a / sqrt(2) from their corners: beyond
    // a = sqrt(2) s0 a particle of one wall can pass between those of the other.
    if (term->surface_spacing() > std::sqrt(2.0) * s.distance)
      world.setup_warnings.push_back(fmt::format(
          "{}:{}: [term] wall_contact: distance = {:.3g} m is below the particle spacing of surface \"{}\" "
          "divided by sqrt(2) (spacing {:.3g} m, the root of the mean particle area): a particle of one wall can "
          "pass between the particles of the other. Use distance >= {:.3g} m or a finer cloud.",
          p.file(), p.line("distance"), s.distance, s.surface, term->surface_spacing(),
          term->surface_spacing() / std::sqrt(2.0)));
    return term;
  }
  throw SetupError(fmt::format("{}:{}: [term] type = \"{}\": this term is declared in the scene format but not yet "
                               "available in this version of rkpm",
                               p.file(), p.table_line(), type));
}

}  // namespace rkpm::sim
