#include "parallel/communicator.hpp"

#include <algorithm>
#include <stdexcept>

#ifdef MESOCHAIN_HAVE_MPI
#include <mpi.h>
#endif

namespace mesochain::parallel {

#ifdef MESOCHAIN_HAVE_MPI
struct Communicator::Handle {
  MPI_Comm comm = MPI_COMM_NULL;
  bool owned = false;  // from MPI_Comm_split: freed with the last copy (before MPI_Finalize)
  ~Handle() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (owned && !finalized && comm != MPI_COMM_NULL) MPI_Comm_free(&comm);
  }
};

namespace {
void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) {
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(rc, text, &length);
    throw std::runtime_error(std::string("MPI ") + what + ": " + std::string(text, length));
  }
}

// Every rank's count (counts), where its part starts (offsets) and the total, for Allgatherv.
int gatherCounts(MPI_Comm comm, int size, int count, std::vector<int>& counts, std::vector<int>& offsets) {
  counts.assign(size, 0), offsets.assign(size, 0);
  check(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm), "Allgather");
  int total = 0;
  for (int r = 0; r < size; ++r) {
    offsets[r] = total;
    total += counts[r];
  }
  return total;
}
}  // namespace

bool builtWithMpi() { return true; }

bool mpiActive() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}

Communicator Communicator::world() {
  if (!mpiActive()) return serial();
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  auto h = std::make_shared<Handle>();
  h->comm = MPI_COMM_WORLD;
  return Communicator(std::move(h), rank, size);
}

Communicator Communicator::split(int color) const {
  if (color < 0) throw std::invalid_argument("Communicator::split: negative color");
  if (!handle_) return serial();
  auto h = std::make_shared<Handle>();
  check(MPI_Comm_split(handle_->comm, color, rank_, &h->comm), "Comm_split");
  h->owned = true;
  int rank = 0, size = 1;
  MPI_Comm_rank(h->comm, &rank);
  MPI_Comm_size(h->comm, &size);
  return Communicator(std::move(h), rank, size);
}

std::vector<double> Communicator::allgather(const std::vector<double>& mine) const {
  if (!handle_ || size_ == 1) return mine;
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts, offsets;
  const int total = gatherCounts(handle_->comm, size_, count, counts, offsets);
  std::vector<double> all(total);
  check(MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                       MPI_DOUBLE, handle_->comm),
        "Allgatherv");
  return all;
}

std::vector<std::string> Communicator::allgatherText(const std::string& mine) const {
  if (!handle_ || size_ == 1) return {mine};
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts, offsets;
  const int total = gatherCounts(handle_->comm, size_, count, counts, offsets);
  std::string all(static_cast<std::size_t>(total), '\0');
  check(MPI_Allgatherv(mine.data(), count, MPI_CHAR, all.data(), counts.data(), offsets.data(),
                       MPI_CHAR, handle_->comm),
        "Allgatherv");
  std::vector<std::string> out;
  for (int r = 0; r < size_; ++r) out.push_back(all.substr(offsets[r], counts[r]));
  return out;
}

void Communicator::sumInPlace(std::vector<std::int64_t>& values) const {
  if (!handle_ || size_ == 1) return;
  // In chunks below 2^31 elements (MPI counts are int).
  const std::size_t chunk = std::size_t{1} << 28;
  for (std::size_t begin = 0; begin < values.size(); begin += chunk) {
    const int count = static_cast<int>(std::min(chunk, values.size() - begin));
    check(MPI_Allreduce(MPI_IN_PLACE, values.data() + begin, count, MPI_INT64_T, MPI_SUM,
                        handle_->comm),
          "Allreduce");
  }
}

void Communicator::broadcast(std::string& text, int root) const {
  if (!handle_ || size_ == 1) return;
  long long length = static_cast<long long>(text.size());
  check(MPI_Bcast(&length, 1, MPI_LONG_LONG, root, handle_->comm), "Bcast");
  text.resize(static_cast<std::size_t>(length));
  if (length > 0)
    check(MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, root, handle_->comm),
          "Bcast");
}

void Communicator::barrier() const {
  if (handle_ && size_ > 1) check(MPI_Barrier(handle_->comm), "Barrier");
}

std::string Communicator::firstFailure(const std::string& mine) const {
  if (!handle_ || size_ == 1) return mine;
  int failed = mine.empty() ? size_ : rank_;
  int first = size_;
  check(MPI_Allreduce(&failed, &first, 1, MPI_INT, MPI_MIN, handle_->comm), "Allreduce");
  if (first == size_) return {};
  std::string text = first == rank_ ? mine : std::string();
  broadcast(text, first);
  return text;
}

#else  // built without MPI: every communicator is serial

struct Communicator::Handle {};

bool builtWithMpi() { return false; }
bool mpiActive() { return false; }
Communicator Communicator::world() { return serial(); }
Communicator Communicator::split(int color) const {
  if (color < 0) throw std::invalid_argument("Communicator::split: negative color");
  return serial();
}
std::vector<double> Communicator::allgather(const std::vector<double>& mine) const { return mine; }
std::vector<std::string> Communicator::allgatherText(const std::string& mine) const {
  return {mine};
}
void Communicator::sumInPlace(std::vector<std::int64_t>&) const {}
void Communicator::broadcast(std::string&, int) const {}
void Communicator::barrier() const {}
std::string Communicator::firstFailure(const std::string& mine) const { return mine; }

#endif

Communicator Communicator::serial() { return Communicator(nullptr, 0, 1); }

}  // namespace mesochain::parallel
