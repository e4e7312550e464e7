#pragma once
// parallel::Communicator: the one interface through which mesochain talks to MPI (dftb/ and the
// drivers call this, never MPI itself). Built without MPI (MESOCHAIN_MPI=OFF, or no MPI found),
// or run without an MPI launcher (plain `mesochain ...`, the Python module, the unit tests),
// every communicator is the serial one: one rank, and every collective is a copy.
//
// What goes over the wire is small and typed: doubles gathered in rank order (the eigenvalues of
// the k-points a rank owns), 64-bit integers summed exactly (the fixed-point density sums of
// parallel/exact_sum.hpp, so a sum does not depend on how the terms were split over ranks),
// text broadcast from one rank (scan points as JSON), and the agreement on failures: an error
// on one rank of a distributed loop becomes the same error on every rank (firstFailure), so all
// ranks leave the collective code together and rank 0 prints the message once.
//
// MPI is called from the thread that called parallel::Session's constructor only (OpenMP threads
// inside a rank never communicate; MPI_THREAD_FUNNELED).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mesochain::parallel {

// True when the library was built with MPI (CMake MESOCHAIN_MPI).
bool builtWithMpi();
// True when MPI is initialised (a Session was started under an MPI launcher) and not finalised.
bool mpiActive();

class Communicator {
 public:
  // All processes of the run: MPI_COMM_WORLD when MPI is active, otherwise the serial one.
  static Communicator world();
  // One rank, no communication (also under mpirun: each process on its own).
  static Communicator serial();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isRoot() const { return rank_ == 0; }

  // The ranks of the same `color` (>= 0) as a communicator of their own, ordered by their rank
  // here (MPI_Comm_split). Collective over this communicator.
  Communicator split(int color) const;

  // Every rank's `mine` (of any length) concatenated in rank order; the same on every rank.
  std::vector<double> allgather(const std::vector<double>& mine) const;
  // Every rank's text, in rank order; the same on every rank.
  std::vector<std::string> allgatherText(const std::string& mine) const;
  // The element-wise sum over ranks, in place on every rank. Integer addition is exact and
  // associative, so the sum does not depend on the reduction tree.
  void sumInPlace(std::vector<std::int64_t>& values) const;
  // `text` of rank `root` on every rank.
  void broadcast(std::string& text, int root = 0) const;
  void barrier() const;
  // Agreement on a failure inside a distributed section: every rank passes the text of its
  // failure (empty: none) and gets the first non-empty one in rank order (empty when no rank
  // failed), the same on every rank. Collective.
  std::string firstFailure(const std::string& mine) const;

  struct Handle;  // the MPI communicator (parallel/communicator.cpp)

 private:
  Communicator(std::shared_ptr<Handle> handle, int rank, int size)
      : handle_(std::move(handle)), rank_(rank), size_(size) {}
  std::shared_ptr<Handle> handle_;  // null: serial
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace mesochain::parallel
