#include "rkpm/sim/body_state.hpp"

#include <type_traits>
#include <variant>

namespace rkpm::sim {

namespace {
// Calls `f` with the body's material (its catalog alternative), const as the body is.
template <class AnyBody, class F>
decltype(auto) with_material(AnyBody& body, F&& f) {
  return std::visit(std::forward<F>(f), body.material);
}
}  // namespace

bool has_material_state(const Body& body) {
  return with_material(body, [](const auto& m) {
    return !std::is_base_of_v<materials::Stateless, std::decay_t<decltype(m)>>;
  });
}

void prepare_material_state(Body& body, const materials::StateDemand& demand) {
  with_material(body, [&](auto& m) { m.prepare(body, demand); });
}

void begin_state_step(Body& body) {
  with_material(body, [&](auto& m) { m.begin_step(body); });
}

materials::StateUpdate end_state_step(Body& body, double dt) {
  return with_material(body, [&](auto& m) { return m.end_step(body, dt); });
}

materials::StateUpdate state_work_since(const Body& body, const std::vector<Mat3>& F_from) {
  return with_material(body, [&](const auto& m) { return m.work_since(body, F_from); });
}

double state_stable_dt(const Body& body) {
  return with_material(body, [&](const auto& m) { return m.stable_dt(body); });
}

bool state_evolves_in_time(const Body& body) {
  return with_material(body, [](const auto& m) { return m.evolves_in_time(); });
}

double state_residual(const Body& body) {
  return with_material(body, [&](const auto& m) { return m.residual(body); });
}

void save_material_state(const Body& body, StateRecord& record, const std::string& prefix) {
  with_material(body, [&](const auto& m) { m.save_state(record, prefix); });
}

void load_material_state(Body& body, const StateRecord& record, const std::string& prefix) {
  with_material(body, [&](auto& m) { m.load_state(record, prefix, body); });
}

std::vector<materials::OutputField> material_output_fields(const Body& body) {
  return with_material(body, [](const auto& m) { return m.output_fields(); });
}

void transfer_material_state(const Body& from, Body& to, const materials::VectorInterpolation& interpolate) {
  with_material(to, [&](auto& m) {
    using Model = std::decay_t<decltype(m)>;
    // Levels of one scene: the same model on every cloud.
    if (const auto* source = std::get_if<Model>(&from.material)) m.transfer_state(*source, interpolate);
  });
}

}  // namespace rkpm::sim
