#include "rkpm/sim/output.hpp"

#include "rkpm/sim/body_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rkpm::sim {

namespace {

// What a frame holds per point, in the order of the frame's fields: position (3),
// displacement (3), velocity (3), body_id, particle_id, volume, J, cauchy_stress (9),
// von_mises; then the fields the bodies' materials and the terms declare (FieldSlots).
constexpr int kBaseRecord = 23;

// The fields a body shows beyond the base record: its material's, then each term's for
// it (Term::output_fields), in term order.
std::vector<materials::OutputField> declared_fields(const World& world, const Body& body) {
  std::vector<materials::OutputField> fields = material_output_fields(body);
  for (const auto& t : world.terms)
    for (auto& f : t->output_fields(body)) fields.push_back(std::move(f));
  return fields;
}

// The declared fields of a frame: the union over its bodies of their declared_fields,
// in body order, each at its offset in the point record. A body that lacks one of them
// writes zeros there.
struct FieldSlot {
  std::string name;
  int components = 0;
  int offset = 0;  // in the point record
};
std::vector<FieldSlot> field_slots(const World& world) {
  std::vector<FieldSlot> slots;
  int offset = kBaseRecord;
  for (const auto& b : world.bodies)
    for (const auto& f : declared_fields(world, *b)) {
      const auto same = [&](const FieldSlot& s) { return s.name == f.name; };
      if (std::find_if(slots.begin(), slots.end(), same) != slots.end()) continue;
      slots.push_back({f.name, f.components, offset});
      offset += f.components;
    }
  return slots;
}
int record_size(const std::vector<FieldSlot>& slots) {
  return slots.empty() ? kBaseRecord : slots.back().offset + slots.back().components;
}

// Cauchy stress sigma = P F^T / J at one point, and its von Mises equivalent.
void stress_at(const Body& b, std::size_t L, double* sigma9, double& von_mises) {
  const Mat3& F = b.F[L];
  const Mat3 sigma = first_piola_at(b, static_cast<Index>(L)) * F.transpose() / F.determinant();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) sigma9[3 * r + c] = sigma(r, c);
  const Mat3 sym = 0.5 * (sigma + sigma.transpose());
  const Mat3 dev = sym - sym.trace() / 3.0 * Mat3::Identity();
  von_mises = std::sqrt(1.5 * dev.squaredNorm());
}

// The base record of particle J of a body whose generalized displacements and velocities
// (ghosts included) are d and v.
void point_record(const Body& b, Index J, const std::vector<Vec3>& d, const std::vector<Vec3>& v, double* out) {
  const Vec3 u = rk::interpolate(b.interpolation, d, J);  // physical displacement and velocity
  const Vec3 w = rk::interpolate(b.interpolation, v, J);
  const Vec3 p = b.cloud.X[J] + u;
  std::copy_n(p.data(), 3, out);
  std::copy_n(u.data(), 3, out + 3);
  std::copy_n(w.data(), 3, out + 6);
  out[9] = b.id;
  // The particle's number in a one-rank run, whatever the rank count: what a user
  // compares runs on different rank counts by (exact in a double below 2^53).
  out[10] = static_cast<double>(one_rank_id(b, J));
  out[11] = b.cloud.volume[J];
  out[12] = b.F[J].determinant();
  stress_at(b, static_cast<std::size_t>(J), out + 13, out[22]);
}

// The declared fields of particle J into its record, at the slots' offsets.
void declared_record(const std::vector<materials::OutputField>& own, const std::vector<FieldSlot>& slots, Index J,
                     double* out) {
  for (const auto& slot : slots) {
    double* to = out + slot.offset;
    std::fill(to, to + slot.components, 0.0);
    for (const auto& f : own)
      if (f.name == slot.name && f.values != nullptr)
        std::copy_n(f.values + static_cast<std::size_t>(J) * static_cast<std::size_t>(f.components),
                    std::min(f.components, slot.components), to);
  }
}

}  // namespace

namespace {
// A distributed body's owned values (`components` per particle, this rank's share) made
// the whole field in the one-process numbering: gathered in rank order, then each
// particle's row moved to its original id.
void gather_in_original_order(const par::Comm& comm, const std::vector<double>& ids, std::vector<double>& field,
                              std::size_t components) {
  const std::vector<double> all = comm.gather(field);
  field.assign(all.size(), 0.0);
  for (std::size_t k = 0; k < ids.size(); ++k)
    std::copy_n(&all[k * components], components, &field[static_cast<std::size_t>(ids[k]) * components]);
}
}  // namespace

BodyFields body_fields(const Body& b, const par::Comm& comm) {
  BodyFields f;
  const std::size_t n = static_cast<std::size_t>(b.owned_end() - b.owned_begin());
  for (auto* v : {&f.position, &f.displacement, &f.velocity}) v->resize(3 * n);
  f.volume.resize(n);
  f.J.resize(n);
  f.von_mises.resize(n);
  f.cauchy_stress.resize(9 * n);
  // A distributed body's interpolation reads its ghosts' current values.
  std::vector<Vec3> d = b.d, v = b.v;
  if (b.distributed()) {
    b.ghosts.pull(d);
    b.ghosts.pull(v);
  }
  double record[kBaseRecord];
  for (std::size_t k = 0; k < n; ++k) {
    point_record(b, b.owned_begin() + static_cast<Index>(k), d, v, record);
    std::copy_n(record, 3, &f.position[3 * k]);
    std::copy_n(record + 3, 3, &f.displacement[3 * k]);
    std::copy_n(record + 6, 3, &f.velocity[3 * k]);
    f.volume[k] = record[11];
    f.J[k] = record[12];
    std::copy_n(record + 13, 9, &f.cauchy_stress[9 * k]);
    f.von_mises[k] = record[22];
  }
  if (b.distributed()) {
    // A body left in the one-process numbering has no original ids (build_world.cpp).
    // Ids up to 2^53 are exact as doubles.
    std::vector<double> own_ids;
    for (Index i = b.owned_begin(); i < b.owned_end(); ++i)
      own_ids.push_back(static_cast<double>(one_rank_id(b, i)));
    const std::vector<double> ids = comm.gather(own_ids);
    for (auto* field : {&f.position, &f.displacement, &f.velocity})
      gather_in_original_order(comm, ids, *field, 3);
    for (auto* field : {&f.volume, &f.J, &f.von_mises}) gather_in_original_order(comm, ids, *field, 1);
    gather_in_original_order(comm, ids, f.cauchy_stress, 9);
  }
  return f;
}

namespace {

// The first point of the frame with a position or field value that is not finite,
// named by its body and particle (the body_id and particle_id fields, 2 and 3).
void require_finite(const World& world, const std::vector<Vec3>& positions,
                    const std::vector<io::PointField>& fields) {
  for (std::size_t p = 0; p < positions.size(); ++p) {
    std::string what;
    if (!positions[p].allFinite()) what = fmt::format("its position is ({}, {}, {})", positions[p].x(),
                                                      positions[p].y(), positions[p].z());
    for (std::size_t f = 0; f < fields.size() && what.empty(); ++f) {
      const auto nc = static_cast<std::size_t>(fields[f].components);
      for (std::size_t c = 0; c < nc; ++c)
        if (const double v = fields[f].values[p * nc + c]; !std::isfinite(v)) {
          what = fmt::format("'{}' (component {}) is {}", fields[f].name, c, v);
          break;
        }
    }
    if (what.empty()) continue;
    const auto body = static_cast<std::size_t>(fields[2].values[p]);
    const auto particle = static_cast<std::int64_t>(fields[3].values[p]);
    throw io::NonFiniteValue(fmt::format(
        "body '{}', particle {}: {} (an overflow: an extreme modulus, activity, anisotropy or load, or a blown-up state)",
        body < world.bodies.size() ? world.bodies[body]->name : "?", particle, what));
  }
}

}  // namespace

io::Frame make_frame(const World& world, CellOutput cells, std::vector<Vec3>& positions) {
  const std::vector<FieldSlot> slots = field_slots(world);
  const int record_length = record_size(slots);
  std::size_t total = 0;
  for (const auto& b : world.bodies) {
    total += static_cast<std::size_t>(b->owned_end() - b->owned_begin()) + b->output_halo.ghost_count();
  }

  io::Frame frame;
  std::vector<io::PointField> fields = {
      {"displacement", 3, {}}, {"velocity", 3, {}},      {"body_id", 1, {}},   {"particle_id", 1, {}}, {"volume", 1, {}},
      {"J", 1, {}},            {"cauchy_stress", 9, {}}, {"von_mises", 1, {}}};
  for (const auto& slot : slots) fields.push_back({slot.name, slot.components, {}});
  const std::size_t n_fields = fields.size();
  for (std::size_t f = 0; f < n_fields; ++f) fields[f].values.reserve(total * static_cast<std::size_t>(fields[f].components));
  positions.clear();
  positions.reserve(total);
  const auto append = [&](const double* record) {
    positions.emplace_back(record[0], record[1], record[2]);
    const double* value = record + 3;
    for (std::size_t f = 0; f < n_fields; ++f) {
      const int components = fields[f].components;
      fields[f].values.insert(fields[f].values.end(), value, value + components);
      value += components;
    }
  };

  // The cells of one body: the elements whose lowest node this rank owns (every element
  // on one rank), their nodes numbered by point(J).
  const auto add_cells = [&](const Body& b, const auto& point) {
    if (cells != CellOutput::Mesh) return;
    const auto& mesh = b.cloud.mesh;
    for (int e = 0; e < mesh.n_elements(); ++e) {
      const std::int32_t* nodes = mesh.element_nodes(e);
      const Index lowest = *std::min_element(nodes, nodes + mesh.element_size(e));
      if (lowest < b.owned_begin() || lowest >= b.owned_end()) continue;
      frame.cells.types.push_back(static_cast<std::uint8_t>(mesh.type[e]));
      for (int k = 0; k < mesh.element_size(e); ++k) frame.cells.connectivity.push_back(point(nodes[k]));
      frame.cells.offsets.push_back(static_cast<std::int64_t>(frame.cells.connectivity.size()));
    }
  };

  std::vector<Vec3> ghosted_d, ghosted_v;
  std::vector<double> records;
  std::vector<std::int64_t> point_of;  // distributed: particle -> point of this frame, or -1
  std::int64_t offset = 0;             // the body's first point in this frame
  std::vector<double> record(static_cast<std::size_t>(record_length));
  for (const auto& bp : world.bodies) {
    const Body& b = *bp;
    const Index begin = b.owned_begin(), end = b.owned_end();
    const std::vector<materials::OutputField> own = declared_fields(world, b);
    if (!b.distributed()) {
      for (Index J = 0; J < end; ++J) {
        point_record(b, J, b.d, b.v, record.data());
        declared_record(own, slots, J, record.data());
        append(record.data());
      }
      add_cells(b, [&](Index J) { return offset + J; });
      offset += end;
      continue;
    }
    // Distributed: this rank's piece holds its own particles, then the halo (the other
    // nodes of the elements it writes: those whose lowest node it owns), whose records
    // come from their owners.
    ghosted_d = b.d;
    ghosted_v = b.v;
    b.ghosts.pull(ghosted_d);
    b.ghosts.pull(ghosted_v);
    const auto length = static_cast<std::size_t>(record_length);
    records.assign(b.size() * length, 0.0);
    for (Index J = begin; J < end; ++J) {
      double* out = records.data() + length * static_cast<std::size_t>(J);
      point_record(b, J, ghosted_d, ghosted_v, out);
      declared_record(own, slots, J, out);
    }
    b.output_halo.pull(records.data(), record_length);
    point_of.assign(b.size(), -1);
    std::int64_t next = offset;
    frame.duplicate_points.resize(static_cast<std::size_t>(offset), 0);
    for (Index J = begin; J < end; ++J) {
      append(records.data() + length * static_cast<std::size_t>(J));
      point_of[static_cast<std::size_t>(J)] = next++;
    }
    frame.duplicate_points.resize(static_cast<std::size_t>(next), 0);
    // The halo serves the mesh cells only: a frame of points (one vertex cell each) has none.
    if (cells == CellOutput::Mesh)
      for (const auto& group : b.output_halo.ghosts_by_owner())
        for (Index J : group) {
          append(records.data() + length * static_cast<std::size_t>(J));
          point_of[static_cast<std::size_t>(J)] = next++;
        }
    frame.duplicate_points.resize(static_cast<std::size_t>(next), 1);
    add_cells(b, [&](Index J) { return point_of[static_cast<std::size_t>(J)]; });
    offset = next;
  }
  if (cells == CellOutput::Points) frame.cells = io::vertex_cells(positions.size());
  frame.points = &positions;
  require_finite(world, positions, fields);
  frame.point_fields = std::move(fields);
  return frame;
}

}  // namespace rkpm::sim
