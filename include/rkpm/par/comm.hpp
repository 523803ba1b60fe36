// The ranks of a run: the one place rkpm talks to MPI.
//
// A process started without an MPI launcher (no mpirun) is rank 0 of 1 and never
// initialises MPI: the same binary runs as one process without the MPI runtime's
// start-up cost, and every collective below is then the identity. Under mpirun the
// process joins MPI_COMM_WORLD (see Session).
//
// Every reduction is deterministic for a given rank count: sums are gathered and
// added in rank order on every rank, so all ranks hold the bit-identical result and
// a rerun reproduces it (MPI_Allreduce does not promise either for floating point).
#pragma once

#include "rkpm/common/exact_sum.hpp"
#include "rkpm/common/types.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace rkpm::par {

class Comm {
 public:
  // The communicator of this process: every rank of the run, or a single rank.
  static const Comm& world();
  // A single rank (rank 0 of 1) in any process: what a serial reference is built on.
  static const Comm& self();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool parallel() const { return size_ > 1; }
  bool root() const { return rank_ == 0; }
  // The ranks on this rank's node, itself included: they share its memory.
  int node_size() const { return node_size_; }

  // Reductions over the ranks, the same on every rank.
  // Exact sums merged over the ranks and rounded once: the same bits for any split of
  // the terms over ranks and threads (common/exact_sum.hpp). What steers a run is
  // summed this way; `sum(double)` adds the ranks' values in rank order.
  double sum(const ExactSum& value) const;
  // The same for several sums in one collective; returns their values in order.
  std::vector<double> sum(const std::vector<ExactSum>& values) const;
  double sum(double value) const;
  std::int64_t sum(std::int64_t value) const;
  double min(double value) const;
  double max(double value) const;
  std::int64_t max(std::int64_t value) const;
  // Every rank's value, in rank order.
  std::vector<double> gather(double value) const;
  std::vector<std::int64_t> gather(std::int64_t value) const;
  // Every rank's values concatenated in rank order, on every rank.
  std::vector<double> gather(const std::vector<double>& values) const;
  // Rank `from`'s text on every rank.
  std::string broadcast(const std::string& text, int from) const;
  // The `message` of the lowest rank whose message is not empty, on every rank (empty
  // when none has one): a check that may fail on some ranks only, agreed on by all.
  std::string first_error(const std::string& message) const;

  // Point-to-point exchange: send[p] goes to rank p, recv[p] comes from rank p (its
  // size is sent first). Empty messages are not sent. Every rank must call it.
  void exchange(const std::vector<std::vector<std::int64_t>>& send,
                std::vector<std::vector<std::int64_t>>& recv) const;
  // The same for doubles whose sizes both sides already know (recv[p] sized by the caller).
  void exchange_known(const std::vector<std::vector<double>>& send, std::vector<std::vector<double>>& recv) const;

  void barrier() const;
  // Ends every rank at once with `code` (an error found on one rank only).
  [[noreturn]] void abort(int code) const;

 private:
  friend class Session;
  int rank_ = 0;
  int size_ = 1;
  int node_size_ = 1;
};

// The whole of a per-particle field on every rank, from each rank's own range
// [begin, end): the ranges tile the particles in rank order (par/partition.hpp), so the
// ranks' slices, concatenated in rank order, are the field in particle order. Collective.
std::vector<Vec3> gather_owned(const Comm& comm, const std::vector<Vec3>& field, Index begin, Index end);
std::vector<double> gather_owned(const Comm& comm, const std::vector<double>& field, Index begin, Index end);

// MPI's lifetime in a program: initialised (MPI_THREAD_FUNNELED: OpenMP threads never
// call MPI) when an MPI launcher started the process, finalised at the end of main.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  // True when the environment says an MPI launcher (mpirun, srun) started this process.
  static bool launched_by_mpi();
  // For a host that initialised MPI itself (Python with mpi4py): Comm::world() becomes
  // the running MPI's world, which the host finalises. False when MPI is not running.
  static bool join_running_mpi();

 private:
  static void adopt_world();
  bool initialised_ = false;
};

}  // namespace rkpm::par
