// A small set of particles whose values every rank keeps current: each update gathers
// the owners' values to every rank. For couplings whose solve needs the whole set on
// every rank (the essential boundary conditions' constrained particles: a surface
// subset, whose system the ranks solve in parts, sim/integration/constraint_solver.hpp).
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/par/comm.hpp"

#include <vector>

namespace rkpm::par {

class SharedParticles {
 public:
  // `offset` (ranks + 1 entries) gives each rank's range of particles; `ids` the set.
  void build(const Comm& comm, const std::vector<Index>& offset, std::vector<Index> ids);
  bool built() const { return comm_ != nullptr; }
  // field[i] = its owner's field[i], for every i of the set, on every rank.
  void update(std::vector<Vec3>& field) const;
  // The same for values stored by position in the set (values[k] belongs to the k-th
  // smallest id), as a term that keeps its own sorted particle list stores them.
  void update_packed(std::vector<Vec3>& values) const;
  std::size_t size() const { return ids_.size(); }

 private:
  const Comm* comm_ = nullptr;
  std::vector<Index> ids_;   // sorted: the ranks' owned subsets follow one another in rank order
  std::size_t first_mine_ = 0;  // this rank's ids are ids_[first_mine_, first_mine_ + mine_count_)
  std::size_t mine_count_ = 0;
  mutable std::vector<double> buffer_;
};

}  // namespace rkpm::par
