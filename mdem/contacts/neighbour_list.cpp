#include "mdem/contacts/neighbour_list.hpp"

#include "mdem/binary_io.hpp"
#include "mdem/contacts/contact_dashpot.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numeric>

#include <omp.h>

namespace mesochain::mdem {

namespace {
std::atomic<int> liveLists{0};

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}
}  // namespace

bool FilamentTopology::excluded(int i, int j) const {
  const int f = filament[i];
  if (f != filament[j]) return false;
  int gap = std::abs(place[i] - place[j]);
  if (closed[f]) gap = std::min(gap, filamentSize[f] - gap);
  return gap <= excludeWithin;
}

FilamentTopology buildTopology(int n, const std::vector<Bond>& bonds, int excludeWithin,
                               const std::vector<ClosedFilament>& closedFilaments) {
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto join = [&](int a, int b) {
    a = findRoot(parent, a), b = findRoot(parent, b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  for (const Bond& b : bonds) join(b.a, b.b);
  for (const ClosedFilament& c : closedFilaments)
    for (int k = 1; k < c.count; ++k) join(c.first, c.first + k);
  FilamentTopology t;
  t.excludeWithin = excludeWithin;
  t.filament.assign(n, -1), t.place.assign(n, 0);
  std::vector<int> idOfRoot(n, -1);
  for (int i = 0; i < n; ++i) {  // increasing index: ids ordered by first element, places by index
    const int r = findRoot(parent, i);
    if (idOfRoot[r] < 0) {
      idOfRoot[r] = static_cast<int>(t.filamentSize.size());
      t.filamentSize.push_back(0);
    }
    const int f = idOfRoot[r];
    t.filament[i] = f;
    t.place[i] = t.filamentSize[f]++;
  }
  t.closed.assign(t.filamentSize.size(), 0);
  for (const ClosedFilament& c : closedFilaments)
    if (c.count > 0) t.closed[t.filament[c.first]] = 1;
  return t;
}

NeighbourList::NeighbourList(double interactionRange, double skin, const Periodicity& periodicity, double axisRange)
    : range_(interactionRange), skin_(skin), axisRange_(axisRange), periodicity_(periodicity) {
  ++liveLists;
}

NeighbourList::~NeighbourList() { --liveLists; }

int NeighbourList::live() { return liveLists.load(); }

bool NeighbourList::update(const Bodies& b, const std::vector<double>& halfLength,
                           const FilamentTopology& topology) {
  bool rebuild = builds_ == 0 || static_cast<int>(builtPosition_.size()) != b.size();
  if (!rebuild) {
    // The larger squared displacement of the two ends x +- l t since the build,
    // |dx|^2 + l^2 |dt|^2 + 2 l |dx . dt|; every point of the segment moved by at most that.
    double moved2 = 0.0;
#pragma omp parallel for reduction(max : moved2) schedule(static) if (b.size() > 4096)
    for (int i = 0; i < b.size(); ++i) {
      const Vec3 dt = rotate(b.orientation[i], Vec3::UnitZ()) - builtAxis_[i];
      const Vec3 dx = b.position[i] - builtPosition_[i];
      const double l = halfLength[b.type[i]];
      moved2 = std::max(moved2, dx.squaredNorm() + l * l * dt.squaredNorm() + 2.0 * l * std::abs(dx.dot(dt)));
    }
    rebuild = moved2 > 0.25 * skin_ * skin_;
  }
  if (!rebuild) return false;
  builtPosition_ = b.position;
  builtAxis_.resize(b.size());
  for (int i = 0; i < b.size(); ++i) builtAxis_[i] = rotate(b.orientation[i], Vec3::UnitZ());
  build(b, halfLength, topology);
  return true;
}

void NeighbourList::build(const Bodies& b, const std::vector<double>& halfLength, const FilamentTopology& topology) {
  const int n = b.size();
  const double rl = range_ + skin_, rl2 = rl * rl;
  const bool bySegments = std::isfinite(axisRange_);
  const double ra2 = bySegments ? (axisRange_ + skin_) * (axisRange_ + skin_) : 0.0;
  // Grid: periodic axes span the box (positions wrapped into it); others the bounding box.
  Vec3 lo, extent;
  std::array<int, 3> nc{};
  wrapped_.assign(b.position.begin(), b.position.end());
  for (int k = 0; k < 3; ++k) {
    if (periodicity_.periodic[k]) {
      const double l = periodicity_.length[k];
      for (Vec3& x : wrapped_) x[k] -= l * std::floor(x[k] / l);
      lo[k] = 0.0, extent[k] = l;
    } else {
      double mn = 0.0, mx = 0.0;
      if (n > 0) {
        mn = mx = wrapped_[0][k];
        for (const Vec3& x : wrapped_) mn = std::min(mn, x[k]), mx = std::max(mx, x[k]);
      }
      lo[k] = mn, extent[k] = std::max(mx - mn, 1e-9);
    }
    nc[k] = std::max(1, static_cast<int>(extent[k] / rl));
  }
  // Keep the grid at most ~4 cells per element (sparse scenes).
  while (static_cast<double>(nc[0]) * nc[1] * nc[2] > 4.0 * n + 27) {
    const int k = static_cast<int>(std::max_element(nc.begin(), nc.end()) - nc.begin());
    nc[k] = std::max(1, nc[k] / 2);
  }
  auto cellCoord = [&](const Vec3& x, int k) {
    return std::clamp(static_cast<int>((x[k] - lo[k]) / extent[k] * nc[k]), 0, nc[k] - 1);
  };
  const int cells = nc[0] * nc[1] * nc[2];
  head_.assign(cells + 1, 0), members_.resize(n), cellOf_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Vec3& x = wrapped_[i];
    cellOf_[i] = (cellCoord(x, 0) * nc[1] + cellCoord(x, 1)) * nc[2] + cellCoord(x, 2);
    ++head_[cellOf_[i] + 1];
  }
  for (int c = 0; c < cells; ++c) head_[c + 1] += head_[c];
  fill_.assign(head_.begin(), head_.end() - 1);
  for (int i = 0; i < n; ++i) members_[fill_[cellOf_[i]]++] = i;
  // Neighbour cells of c along axis k, without duplicates (fewer than 3 cells on a periodic axis).
  auto around = [&](int c, int k, std::array<int, 3>& out) {
    int count = 0;
    for (int d = -1; d <= 1; ++d) {
      int m = c + d;
      if (periodicity_.periodic[k]) {
        m = (m % nc[k] + nc[k]) % nc[k];
      } else if (m < 0 || m >= nc[k]) {
        continue;
      }
      if (std::find(out.begin(), out.begin() + count, m) == out.begin() + count) out[count++] = m;
    }
    return count;
  };
  // Distance of the closest points of i's and j's axis segments at the build (j at the image next
  // to i): the pair can only interact later if it is below axisRange + skin now (each end moves
  // by at most skin/2 before the next build, so the distance changes by at most skin).
  auto segmentsNear = [&](int i, int j, const Vec3& d) {
    const Segment si{b.position[i], builtAxis_[i], halfLength[b.type[i]]};
    const Segment sj{b.position[i] + d, builtAxis_[j], halfLength[b.type[j]]};
    double s, u;
    closestPoints(si, sj, &s, &u);
    return (si.centre + s * si.axis - sj.centre - u * sj.axis).squaredNorm() < ra2;
  };
  // Each thread lists the pairs of its contiguous range of i (static schedule), each i's partners
  // sorted; the ranges are joined in thread order, so the list is sorted on any thread count.
  const bool parallel = n > 2048;
  threadPairs_.resize(parallel ? std::max(1, omp_get_max_threads()) : 1);
  for (auto& t : threadPairs_) t.clear();
#pragma omp parallel if (parallel) num_threads(static_cast<int>(threadPairs_.size()))
  {
    std::vector<std::pair<int, int>>& mine = threadPairs_[omp_get_thread_num()];
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      const int c = cellOf_[i];
      const int cz = c % nc[2], cy = (c / nc[2]) % nc[1], cx = c / (nc[1] * nc[2]);
      const std::size_t first = mine.size();
      std::array<int, 3> xs{}, ys{}, zs{};
      const int nx = around(cx, 0, xs), ny = around(cy, 1, ys), nz = around(cz, 2, zs);
      for (int a = 0; a < nx; ++a)
        for (int bb = 0; bb < ny; ++bb)
          for (int z = 0; z < nz; ++z) {
            const int cell = (xs[a] * nc[1] + ys[bb]) * nc[2] + zs[z];
            for (int e = head_[cell]; e < head_[cell + 1]; ++e) {
              const int j = members_[e];
              if (j <= i || topology.excluded(i, j)) continue;
              const Vec3 d = periodicity_.minimumImage(b.position[j] - b.position[i]);
              if (d.squaredNorm() < rl2 && (!bySegments || segmentsNear(i, j, d))) mine.emplace_back(i, j);
            }
          }
      std::sort(mine.begin() + static_cast<std::ptrdiff_t>(first), mine.end());
    }
  }
  pairs_.clear();
  for (const auto& t : threadPairs_) pairs_.insert(pairs_.end(), t.begin(), t.end());
  buildIncidence(n);
  ++builds_;
}

void NeighbourList::buildIncidence(int n) {
  start_.assign(n + 1, 0);
  for (const auto& [i, j] : pairs_) ++start_[i + 1], ++start_[j + 1];
  for (int i = 0; i < n; ++i) start_[i + 1] += start_[i];
  incident_.resize(start_.back());
  fill_.assign(start_.begin(), start_.end() - 1);
  for (int p = 0; p < static_cast<int>(pairs_.size()); ++p) {
    incident_[fill_[pairs_[p].first]++] = 2 * p;
    incident_[fill_[pairs_[p].second]++] = 2 * p + 1;
  }
}

void NeighbourList::save(BinaryWriter& out) const {
  out.write<std::int64_t>(builds_);
  out.writeVector(builtPosition_);
  out.writeVector(builtAxis_);
  out.write<std::uint64_t>(pairs_.size());
  for (const auto& [i, j] : pairs_) out.write<std::int32_t>(i), out.write<std::int32_t>(j);
}

void NeighbourList::load(BinaryReader& in, int n) {
  builds_ = in.read<std::int64_t>();
  builtPosition_ = in.readVector<Vec3>("neighbour list positions");
  builtAxis_ = in.readVector<Vec3>("neighbour list axes");
  if (static_cast<int>(builtPosition_.size()) != n || builtAxis_.size() != builtPosition_.size())
    in.fail("neighbour list of " + std::to_string(builtPosition_.size()) + " elements for a scene of " + std::to_string(n));
  const std::uint64_t np = in.read<std::uint64_t>();
  if (np > in.remaining() / 8) in.fail("neighbour list pair count beyond the end of the data");
  pairs_.resize(np);
  for (auto& [i, j] : pairs_) {
    i = in.read<std::int32_t>(), j = in.read<std::int32_t>();
    if (i < 0 || j <= i || j >= n) in.fail("a neighbour pair (" + std::to_string(i) + ", " + std::to_string(j) + ") outside the scene");
  }
  buildIncidence(n);
}

}  // namespace mesochain::mdem
