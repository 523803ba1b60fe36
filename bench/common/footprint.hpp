// What a built Body holds in memory, and what its internal-force step must move.
//
// Both are computed from the sizes of the Body's own arrays (size() x element size),
// so they follow whatever storage the kernels use. Memory the Body's public arrays do
// not show (the kd-tree inside RKApproximation, the sparse LU of EssentialBC, vector
// slack beyond size()) is not in the footprint; the scaling study's peak-RSS column
// catches it. docs/verification/performance.md lists the arrays of each category.
#pragma once

#include "rkpm/sim/world.hpp"

#include <cstddef>

namespace rkpm::bench {

struct Footprint {
  std::size_t operators = 0;  // gradient and interpolation operators (no transposes are stored)
  std::size_t state = 0;      // per particle and point: d v force F, masses, director, material, scratch
  std::size_t cloud = 0;      // reference cloud: positions, volumes, mesh, boundary description
  std::size_t total() const { return operators + state + cloud; }
  Footprint& operator+=(const Footprint& o) {
    operators += o.operators;
    state += o.state;
    cloud += o.cloud;
    return *this;
  }
};

Footprint footprint(const sim::Body& body);
Footprint footprint(const sim::World& world);  // sum over bodies

// Bytes the internal-force step (sim::compute_internal_forces) must move: every
// operator array it streams plus every state array it reads, each counted once, and
// every array it writes, counted once (no write-allocate, as in STREAM). Re-reading
// an array the step wrote itself (F before the stress, P before the force) is not
// counted: a fused kernel need not do it. A lower bound on the traffic of any
// implementation that keeps these arrays.
struct Traffic {
  std::size_t operators = 0;
  std::size_t state_read = 0;
  std::size_t state_written = 0;
  std::size_t total() const { return operators + state_read + state_written; }
  Traffic& operator+=(const Traffic& o) {
    operators += o.operators;
    state_read += o.state_read;
    state_written += o.state_written;
    return *this;
  }
};

Traffic internal_force_traffic(const sim::Body& body);
Traffic internal_force_traffic(const sim::World& world);

// Operator entries one internal-force step processes: the gradient operator's entries
// (the F gather and the force gather each read all of them) plus the interpolation
// operator's entries when the stabilization is active (also read twice). The
// "pair updates" of the benchmarks' counters.
double internal_force_pair_updates(const sim::Body& body);

// Floating-point operations of one internal-force step, counted from the arithmetic of
// the operator loops (rk/row_kernels.hpp), per entry:
//   gather of F (and of Grad h)   3 subtractions, 9 multiplies, 9 adds     21 per field
//   scatter of the force (and of  9 multiplies and 6 adds for (w M) b~_k,
//   the Frank flux divergence)    3 adds into the sum, 3 for sum_k b~_k     21 per product
//   stabilization residual        3 subtractions, 3 multiplies, 4 adds     10
//   stabilization scatter         3 multiplies, 3 adds                       6
// and per row the 9 adds of I + Grad u, per scatter the 9 multiplies of w M and the 18 of
// the own-particle term, per stabilized row 9. The material's stress (a few hundred per row, with cube roots) is not counted,
// nor the widening of the stored floats: a lower bound, so a roofline point lies at or
// left of its true arithmetic intensity.
double internal_force_flops(const sim::Body& body);
double internal_force_flops(const sim::World& world);

}  // namespace rkpm::bench
