#pragma once
// parallel::Session: MPI's lifetime in the program (app/main.cpp). Under an MPI launcher
// (mpirun sets OMPI_COMM_WORLD_SIZE, PMIX_RANK or PMI_SIZE) the constructor initialises MPI
// (MPI_THREAD_FUNNELED: OpenMP threads inside a rank, MPI from the main thread only) and the
// destructor finalises it; without one, or built without MPI, it does nothing and the run is
// serial. Plain `mesochain ...` therefore never starts MPI.
#include <string>

namespace mesochain::parallel {

class Session {
 public:
  Session(int& argc, char**& argv);
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  ~Session();

  int rank() const { return rank_; }
  int size() const { return size_; }

  // Ranks other than 0 are silent: their standard output and error go to /dev/null (the
  // original standard error is kept for endAfterError). No-op on rank 0 and in serial runs.
  void silenceOtherRanks();

  // Called by every rank that caught an error (rank 0 has printed it). When every rank of the
  // run reaches this within `seconds` (an error all ranks met together: bad input, or a failure
  // agreed through Communicator::firstFailure) it returns and the program ends normally with its
  // exit code; otherwise (an error of this rank alone) the message is printed on the original
  // standard error, with the rank, unless this is rank 0 (which printed it already), and
  // MPI_Abort ends every rank with `exitCode`.
  void endAfterError(const std::string& message, int exitCode, double seconds = 10.0);

 private:
  bool initialised_ = false;
  int rank_ = 0;
  int size_ = 1;
  int savedStderr_ = -1;
};

}  // namespace mesochain::parallel
