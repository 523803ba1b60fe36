#include "rkpm/par/comm.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <numeric>

namespace rkpm::par {

namespace {
Comm& mutable_world() {
  static Comm comm;
  return comm;
}

template <class T>
MPI_Datatype mpi_type();
template <>
MPI_Datatype mpi_type<double>() { return MPI_DOUBLE; }
template <>
MPI_Datatype mpi_type<std::int64_t>() { return MPI_INT64_T; }

template <class T>
std::vector<T> gather_values(const Comm& comm, T value) {
  std::vector<T> all(static_cast<std::size_t>(comm.size()), value);
  if (comm.parallel())
    MPI_Allgather(&value, 1, mpi_type<T>(), all.data(), 1, mpi_type<T>(), MPI_COMM_WORLD);
  return all;
}

// Posts the receives and sends of one exchange and waits for all of them.
template <class T>
void post_and_wait(const std::vector<std::vector<T>>& send, std::vector<std::vector<T>>& recv, int tag) {
  std::vector<MPI_Request> requests;
  for (std::size_t p = 0; p < recv.size(); ++p)
    if (!recv[p].empty()) {
      requests.emplace_back();
      MPI_Irecv(recv[p].data(), static_cast<int>(recv[p].size()), mpi_type<T>(), static_cast<int>(p), tag,
                MPI_COMM_WORLD, &requests.back());
    }
  for (std::size_t p = 0; p < send.size(); ++p)
    if (!send[p].empty()) {
      requests.emplace_back();
      MPI_Isend(send[p].data(), static_cast<int>(send[p].size()), mpi_type<T>(), static_cast<int>(p), tag,
                MPI_COMM_WORLD, &requests.back());
    }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}
}  // namespace

const Comm& Comm::world() { return mutable_world(); }

const Comm& Comm::self() {
  static const Comm single;
  return single;
}

double Comm::sum(const ExactSum& value) const { return sum(std::vector<ExactSum>{value}).front(); }

std::vector<double> Comm::sum(const std::vector<ExactSum>& values) const {
  std::vector<ExactSum> total = values;
  if (parallel()) {
    constexpr int kWords = ExactSum::kWords;
    std::vector<std::int64_t> mine, all(static_cast<std::size_t>(size_) * values.size() * kWords);
    for (const auto& v : values) mine.insert(mine.end(), v.words().begin(), v.words().end());
    MPI_Allgather(mine.data(), static_cast<int>(mine.size()), MPI_INT64_T, all.data(), static_cast<int>(mine.size()),
                  MPI_INT64_T, MPI_COMM_WORLD);
    for (auto& t : total) t = ExactSum{};
    for (int r = 0; r < size_; ++r)
      for (std::size_t k = 0; k < values.size(); ++k) {
        ExactSum::Words words;
        std::copy_n(all.data() + (static_cast<std::size_t>(r) * values.size() + k) * kWords, kWords, words.begin());
        total[k] += ExactSum::from_words(words);
      }
  }
  std::vector<double> out;
  out.reserve(total.size());
  for (const auto& t : total) out.push_back(t.value());
  return out;
}

double Comm::sum(double value) const {
  const auto all = gather_values(*this, value);
  double s = 0.0;  // from zero, in rank order: the same bits on every rank
  for (double v : all) s += v;
  return s;
}

std::int64_t Comm::sum(std::int64_t value) const {
  const auto all = gather_values(*this, value);
  return std::accumulate(all.begin(), all.end(), std::int64_t{0});
}

double Comm::min(double value) const {
  const auto all = gather_values(*this, value);
  return *std::min_element(all.begin(), all.end());
}

double Comm::max(double value) const {
  const auto all = gather_values(*this, value);
  return *std::max_element(all.begin(), all.end());
}

std::int64_t Comm::max(std::int64_t value) const {
  const auto all = gather_values(*this, value);
  return *std::max_element(all.begin(), all.end());
}

std::vector<double> Comm::gather(double value) const { return gather_values(*this, value); }
std::vector<std::int64_t> Comm::gather(std::int64_t value) const { return gather_values(*this, value); }

std::vector<double> Comm::gather(const std::vector<double>& values) const {
  if (!parallel()) return values;
  const auto counts64 = gather_values(*this, static_cast<std::int64_t>(values.size()));
  std::vector<int> counts(counts64.begin(), counts64.end()), displacements(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) displacements[r] = displacements[r - 1] + counts[r - 1];
  std::vector<double> all(static_cast<std::size_t>(displacements.back() + counts.back()));
  MPI_Allgatherv(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, all.data(), counts.data(),
                 displacements.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  return all;
}

std::string Comm::broadcast(const std::string& text, int from) const {
  if (!parallel()) return text;
  std::int64_t n = rank_ == from ? static_cast<std::int64_t>(text.size()) : 0;
  MPI_Bcast(&n, 1, MPI_INT64_T, from, MPI_COMM_WORLD);
  std::string out = rank_ == from ? text : std::string(static_cast<std::size_t>(n), '\0');
  MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, from, MPI_COMM_WORLD);
  return out;
}

void Comm::exchange(const std::vector<std::vector<std::int64_t>>& send,
                    std::vector<std::vector<std::int64_t>>& recv) const {
  const auto p = static_cast<std::size_t>(size_);
  recv.assign(p, {});
  if (!parallel()) {
    recv[0] = send[0];
    return;
  }
  std::vector<std::int64_t> send_count(p), recv_count(p);
  for (std::size_t q = 0; q < p; ++q) send_count[q] = static_cast<std::int64_t>(send[q].size());
  MPI_Alltoall(send_count.data(), 1, MPI_INT64_T, recv_count.data(), 1, MPI_INT64_T, MPI_COMM_WORLD);
  for (std::size_t q = 0; q < p; ++q) recv[q].resize(static_cast<std::size_t>(recv_count[q]));
  post_and_wait(send, recv, 1);
}

void Comm::exchange_known(const std::vector<std::vector<double>>& send,
                          std::vector<std::vector<double>>& recv) const {
  if (!parallel()) {
    recv[0] = send[0];
    return;
  }
  post_and_wait(send, recv, 2);
}

void Comm::barrier() const {
  if (parallel()) MPI_Barrier(MPI_COMM_WORLD);
}

void Comm::abort(int code) const {
  if (parallel()) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

std::string Comm::first_error(const std::string& message) const {
  if (!parallel()) return message;
  const auto failed = gather(static_cast<std::int64_t>(message.empty() ? 0 : 1));
  for (std::size_t r = 0; r < failed.size(); ++r)
    if (failed[r] != 0) return broadcast(message, static_cast<int>(r));
  return {};
}

std::vector<Vec3> gather_owned(const Comm& comm, const std::vector<Vec3>& field, Index begin, Index end) {
  if (!comm.parallel()) return field;
  std::vector<double> mine;
  mine.reserve(3 * static_cast<std::size_t>(end - begin));
  for (Index i = begin; i < end; ++i) mine.insert(mine.end(), field[i].data(), field[i].data() + 3);
  const std::vector<double> all = comm.gather(mine);
  std::vector<Vec3> whole(all.size() / 3);
  for (std::size_t i = 0; i < whole.size(); ++i) whole[i] = Vec3(all[3 * i], all[3 * i + 1], all[3 * i + 2]);
  return whole;
}

std::vector<double> gather_owned(const Comm& comm, const std::vector<double>& field, Index begin, Index end) {
  if (!comm.parallel()) return field;
  return comm.gather(std::vector<double>(field.begin() + begin, field.begin() + end));
}

bool Session::launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

Session::Session(int& argc, char**& argv) {
  if (!launched_by_mpi()) return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
  adopt_world();
}

bool Session::join_running_mpi() {
  int running = 0;
  MPI_Initialized(&running);
  if (running == 0) return false;
  int finished = 0;
  MPI_Finalized(&finished);
  if (finished != 0) return false;
  adopt_world();
  return true;
}

void Session::adopt_world() {
  Comm& comm = mutable_world();
  MPI_Comm_rank(MPI_COMM_WORLD, &comm.rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &comm.size_);
  // The ranks that share this rank's memory (its node): MPI-3's shared-memory split.
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, comm.rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &comm.node_size_);
  MPI_Comm_free(&node);
}

Session::~Session() {
  if (!initialised_) return;
  MPI_Finalize();
  Comm& comm = mutable_world();
  comm.rank_ = 0;
  comm.size_ = 1;
  comm.node_size_ = 1;
}

}  // namespace rkpm::par
