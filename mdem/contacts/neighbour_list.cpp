#include "mdem/contacts/neighbour_list.hpp"

#include "mdem/binary_io.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>

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

NeighbourList::NeighbourList(double interactionRange, double skin, const Periodicity& periodicity)
    : range_(interactionRange), skin_(skin), periodicity_(periodicity) {
  ++liveLists;
}

NeighbourList::~NeighbourList() { --liveLists; }

int NeighbourList::live() { return liveLists.load(); }

bool NeighbourList::update(const Bodies& b, const std::vector<double>& halfLength,
                           const FilamentTopology& topology) {
  bool rebuild = builds_ == 0 || static_cast<int>(builtPosition_.size()) != b.size();
  if (!rebuild) {
    double moved = 0.0;
#pragma omp parallel for reduction(max : moved) schedule(static) if (b.size() > 4096)
    for (int i = 0; i < b.size(); ++i) {
      const Vec3 t = rotate(b.orientation[i], Vec3::UnitZ());
      moved = std::max(moved, (b.position[i] - builtPosition_[i]).norm() +
                                  halfLength[b.type[i]] * (t - builtAxis_[i]).norm());
    }
    rebuild = moved > 0.5 * skin_;
  }
  if (!rebuild) return false;
  builtPosition_ = b.position;
  builtAxis_.resize(b.size());
  for (int i = 0; i < b.size(); ++i) builtAxis_[i] = rotate(b.orientation[i], Vec3::UnitZ());
  build(b, topology);
  return true;
}

void NeighbourList::build(const Bodies& b, const FilamentTopology& topology) {
  const int n = b.size();
  const double rl = range_ + skin_, rl2 = rl * rl;
  // Grid: periodic axes span the box (positions wrapped into it); others the bounding box.
  Vec3 lo, extent;
  std::array<int, 3> nc{};
  std::vector<Vec3> wrapped(b.position);
  for (int k = 0; k < 3; ++k) {
    if (periodicity_.periodic[k]) {
      const double l = periodicity_.length[k];
      for (Vec3& x : wrapped) x[k] -= l * std::floor(x[k] / l);
      lo[k] = 0.0, extent[k] = l;
    } else {
      double mn = 0.0, mx = 0.0;
      if (n > 0) {
        mn = mx = wrapped[0][k];
        for (const Vec3& x : wrapped) mn = std::min(mn, x[k]), mx = std::max(mx, x[k]);
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
  std::vector<int> head(cells + 1, 0), members(n);
  std::vector<int> cellOf(n);
  for (int i = 0; i < n; ++i) {
    const Vec3& x = wrapped[i];
    cellOf[i] = (cellCoord(x, 0) * nc[1] + cellCoord(x, 1)) * nc[2] + cellCoord(x, 2);
    ++head[cellOf[i] + 1];
  }
  for (int c = 0; c < cells; ++c) head[c + 1] += head[c];
  {
    std::vector<int> fill(head.begin(), head.end() - 1);
    for (int i = 0; i < n; ++i) members[fill[cellOf[i]]++] = i;
  }
  // Neighbour cells per axis, without duplicates (fewer than 3 cells on a periodic axis).
  auto around = [&](int c, int k) {
    std::vector<int> out;
    for (int d = -1; d <= 1; ++d) {
      int m = c + d;
      if (periodicity_.periodic[k]) {
        m = (m % nc[k] + nc[k]) % nc[k];
      } else if (m < 0 || m >= nc[k]) {
        continue;
      }
      if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
    }
    return out;
  };
  std::vector<std::vector<int>> partners(n);
#pragma omp parallel for schedule(dynamic, 64) if (n > 2048)
  for (int i = 0; i < n; ++i) {
    const int c = cellOf[i];
    const int cz = c % nc[2], cy = (c / nc[2]) % nc[1], cx = c / (nc[1] * nc[2]);
    std::vector<int>& mine = partners[i];
    for (int x : around(cx, 0))
      for (int y : around(cy, 1))
        for (int z : around(cz, 2)) {
          const int cell = (x * nc[1] + y) * nc[2] + z;
          for (int e = head[cell]; e < head[cell + 1]; ++e) {
            const int j = members[e];
            if (j <= i || topology.excluded(i, j)) continue;
            if (periodicity_.minimumImage(b.position[j] - b.position[i]).squaredNorm() < rl2) mine.push_back(j);
          }
        }
    std::sort(mine.begin(), mine.end());
  }
  pairs_.clear();
  for (int i = 0; i < n; ++i)
    for (int j : partners[i]) pairs_.emplace_back(i, j);
  buildIncidence(n);
  ++builds_;
}

void NeighbourList::buildIncidence(int n) {
  start_.assign(n + 1, 0);
  for (const auto& [i, j] : pairs_) ++start_[i + 1], ++start_[j + 1];
  for (int i = 0; i < n; ++i) start_[i + 1] += start_[i];
  incident_.resize(start_.back());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int p = 0; p < static_cast<int>(pairs_.size()); ++p) {
    incident_[fill[pairs_[p].first]++] = 2 * p;
    incident_[fill[pairs_[p].second]++] = 2 * p + 1;
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
