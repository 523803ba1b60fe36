#include "rkpm/par/shared_particles.hpp"

#include <algorithm>
#include <stdexcept>

namespace rkpm::par {

void SharedParticles::build(const Comm& comm, const std::vector<Index>& offset, std::vector<Index> ids) {
  comm_ = &comm;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  ids_ = std::move(ids);
  const Index begin = offset[static_cast<std::size_t>(comm.rank())];
  const Index end = offset[static_cast<std::size_t>(comm.rank()) + 1];
  // This rank's ids are one run of the sorted set.
  first_mine_ = static_cast<std::size_t>(std::lower_bound(ids_.begin(), ids_.end(), begin) - ids_.begin());
  mine_count_ = static_cast<std::size_t>(std::lower_bound(ids_.begin(), ids_.end(), end) - ids_.begin()) - first_mine_;
}

void SharedParticles::update_packed(std::vector<Vec3>& values) const {
  if (!comm_->parallel()) return;
  if (values.size() != ids_.size()) throw std::logic_error("shared particles: values do not match the set");
  buffer_.resize(3 * mine_count_);
  for (std::size_t k = 0; k < mine_count_; ++k)
    for (int c = 0; c < 3; ++c) buffer_[3 * k + static_cast<std::size_t>(c)] = values[first_mine_ + k][c];
  const std::vector<double> all = comm_->gather(buffer_);
  if (all.size() != 3 * ids_.size())
    throw std::logic_error("shared particles: the ranks' owned subsets do not add up to the set");
  for (std::size_t k = 0; k < ids_.size(); ++k) values[k] = Vec3(all[3 * k], all[3 * k + 1], all[3 * k + 2]);
}

void SharedParticles::update(std::vector<Vec3>& field) const {
  if (!comm_->parallel()) return;
  std::vector<Vec3> values(ids_.size());
  for (std::size_t k = 0; k < ids_.size(); ++k) values[k] = field[static_cast<std::size_t>(ids_[k])];
  update_packed(values);
  for (std::size_t k = 0; k < ids_.size(); ++k) field[static_cast<std::size_t>(ids_[k])] = values[k];
}

}  // namespace rkpm::par
