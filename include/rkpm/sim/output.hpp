// What a frame shows: every body in one unstructured grid, at the physical
// positions X + u(X), with the fields the bodies' physics provide.
#pragma once

#include "rkpm/io/frame.hpp"
#include "rkpm/sim/world.hpp"

#include <vector>

namespace rkpm::sim {

enum class CellOutput { Mesh, Points };

// Point fields: displacement, velocity (physical, interpolated with Psi), body_id,
// particle_id (the particle's number in its body in a one-rank run), volume, J,
// cauchy_stress (9 components), von_mises; then every field a body's material declares
// (material_output_fields, by its declared name), zeros at bodies whose material has no
// such field. `positions` receives the points the frame refers to.
// Distributed: this rank's piece, its own particles and, after them, the other nodes of
// the elements it writes (those whose lowest node it owns), whose values come from
// their owners; a node at a piece boundary thus appears in more than one piece.
// A value that is not finite (a stress that overflowed at an extreme but accepted
// parameter, a blown-up state) throws io::NonFiniteValue naming the body, the
// particle, the field and the value, before anything is written.
// One body's point fields as a frame writes them (the same values, bit for bit), for
// every particle in the one-process numbering (a one-rank run's particle order), on
// every rank: collective for a distributed body, whose ghosts are pulled and whose
// ranks' values are gathered. Each vector holds n x components values, row by row.
struct BodyFields {
  std::vector<double> position, displacement, velocity, volume, J, cauchy_stress, von_mises;
};
BodyFields body_fields(const Body& body, const par::Comm& comm = par::Comm::self());

io::Frame make_frame(const World& world, CellOutput cells, std::vector<Vec3>& positions);

}  // namespace rkpm::sim
