#include "parallel/session.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <thread>

#ifdef MESOCHAIN_HAVE_MPI
#include <mpi.h>
#endif

namespace mesochain::parallel {

namespace {
// Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE; PMIx and PMI launchers (srun, hydra) the others.
bool underLauncher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (std::getenv(v)) return true;
  return false;
}
#ifdef MESOCHAIN_HAVE_MPI
// A copy of MPI_COMM_WORLD used only by endAfterError, so that its barrier never matches a
// collective of the computation that other ranks may still be inside.
MPI_Comm errorComm = MPI_COMM_NULL;
#endif
}  // namespace

Session::Session(int& argc, char**& argv) {
#ifdef MESOCHAIN_HAVE_MPI
  if (!underLauncher()) return;
  int provided = 0;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    std::cerr << "mesochain: error: MPI_Init_thread failed\n";
    std::exit(1);
  }
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm_dup(MPI_COMM_WORLD, &errorComm);
#else
  (void)argc;
  (void)argv;
  (void)underLauncher;
#endif
}

Session::~Session() {
#ifdef MESOCHAIN_HAVE_MPI
  if (!initialised_) return;
  std::cout.flush();
  std::cerr.flush();
  if (errorComm != MPI_COMM_NULL) MPI_Comm_free(&errorComm);
  MPI_Finalize();
#endif
}

void Session::silenceOtherRanks() {
  if (rank_ == 0 || size_ == 1) return;
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  savedStderr_ = ::dup(STDERR_FILENO);
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::close(null);
  }
}

void Session::endAfterError(const std::string& message, int exitCode, double seconds) {
#ifdef MESOCHAIN_HAVE_MPI
  if (!initialised_ || size_ == 1) return;
  MPI_Request request;
  MPI_Ibarrier(errorComm, &request);
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int done = 0;
  while (!done && std::chrono::steady_clock::now() < end) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (!done) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (done) return;
  if (rank_ != 0 && savedStderr_ >= 0) {
    const std::string line =
        "mesochain: error (rank " + std::to_string(rank_) + "): " + message + "\n";
    [[maybe_unused]] const auto n = ::write(savedStderr_, line.data(), line.size());
  }
  MPI_Abort(MPI_COMM_WORLD, exitCode);
#else
  (void)message;
  (void)exitCode;
  (void)seconds;
#endif
}

}  // namespace mesochain::parallel
