#include "mdem/contacts/pore_size.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mesochain::mdem {

namespace {

// Elements binned by centre into columns of the film's area (all heights in one column).
struct Columns {
  int nx = 1, ny = 1;
  double cx = 1.0, cy = 1.0;  // nm
  std::vector<int> start, items;
  int index(double v, double c, int n) const { return std::clamp(static_cast<int>(std::floor(v / c)), 0, n - 1); }
};

double positiveModulo(double v, double l) {
  const double m = std::fmod(v, l);
  return m < 0.0 ? m + l : m;
}

}  // namespace

PoreSizeDistribution poreSizeDistribution(const Scene& scene, const PoreSizeOptions& o) {
  PoreSizeDistribution out;
  out.binWidth = o.binWidth;
  const Bodies& b = scene.bodies;
  const double lx = scene.filmSize.x(), ly = scene.filmSize.y();
  if (b.size() == 0 || !(lx > 0.0) || !(ly > 0.0)) return out;
  const Periodicity& per = scene.periodic;
  double rMax = 0.0, hMax = 0.0, zMin = std::numeric_limits<double>::infinity(), zMax = -zMin;
  for (int i = 0; i < b.size(); ++i) {
    const ElementType& t = scene.elementTypes[b.type[i]];
    rMax = std::max(rMax, t.contactRadius()), hMax = std::max(hMax, 0.5 * t.length);
    zMin = std::min(zMin, b.position[i].z()), zMax = std::max(zMax, b.position[i].z());
  }
  out.zLow = o.zHigh > o.zLow ? o.zLow : zMin - rMax;
  out.zHigh = o.zHigh > o.zLow ? o.zHigh : zMax + rMax;
  const double lz = out.zHigh - out.zLow;
  const double h = o.gridSpacing > 0.0 ? o.gridSpacing : std::max(0.5, std::cbrt(lx * ly * lz / o.maxPoints));
  const long n[3] = {std::max(1L, std::lround(lx / h)), std::max(1L, std::lround(ly / h)), std::max(1L, std::lround(lz / h))};
  const double len[3] = {lx, ly, lz};
  for (int k = 0; k < 3; ++k) out.spacing[k] = len[k] / n[k];
  out.points = n[0] * n[1] * n[2];

  // Columns of at least one element length (and 3 nm), wrapped on periodic axes.
  Columns col;
  const double size = std::max(3.0, 2.0 * hMax);
  col.nx = std::max(1, static_cast<int>(lx / size)), col.ny = std::max(1, static_cast<int>(ly / size));
  col.cx = lx / col.nx, col.cy = ly / col.ny;
  std::vector<int> home(b.size());
  col.start.assign(col.nx * col.ny + 1, 0);
  for (int i = 0; i < b.size(); ++i) {
    const double x = per.periodic[0] ? positiveModulo(b.position[i].x(), lx) : b.position[i].x();
    const double y = per.periodic[1] ? positiveModulo(b.position[i].y(), ly) : b.position[i].y();
    home[i] = col.index(x, col.cx, col.nx) * col.ny + col.index(y, col.cy, col.ny);
    ++col.start[home[i] + 1];
  }
  for (std::size_t c = 1; c < col.start.size(); ++c) col.start[c] += col.start[c - 1];
  col.items.resize(b.size());
  {
    std::vector<int> fill(col.start.begin(), col.start.end() - 1);
    for (int i = 0; i < b.size(); ++i) col.items[fill[home[i]]++] = i;
  }
  std::vector<Vec3> axis(b.size());
  std::vector<double> half(b.size()), radius(b.size());
  for (int i = 0; i < b.size(); ++i) {
    const ElementType& t = scene.elementTypes[b.type[i]];
    axis[i] = rotate(b.orientation[i], Vec3::UnitZ()), half[i] = 0.5 * t.length, radius[i] = t.contactRadius() + o.shell;
  }
  const int ringsAll = std::max(col.nx, col.ny);  // beyond: every column has been seen

  // d(p) per grid point (negative inside the solid).
  std::vector<double> d(out.points);
#pragma omp parallel
  {
  // Columns already searched for the current point (a ring wider than a periodic axis wraps onto
  // columns seen before).
  std::vector<long> seen(col.nx * col.ny, -1);
  long stamp = 0;
#pragma omp for schedule(dynamic, 64)
  for (long q = 0; q < n[0] * n[1]; ++q) {
    const long ix = q / n[1], iy = q % n[1];
    const double px = (ix + 0.5) * out.spacing[0], py = (iy + 0.5) * out.spacing[1];
    const int cx = col.index(px, col.cx, col.nx), cy = col.index(py, col.cy, col.ny);
    for (long iz = 0; iz < n[2]; ++iz) {
      const Vec3 p(px, py, out.zLow + (iz + 0.5) * out.spacing[2]);
      double best = std::numeric_limits<double>::infinity();
      ++stamp;
      for (int ring = 0; ring <= ringsAll; ++ring) {
        // Elements of columns at Chebyshev ring k have their axis at least (k - 1) c - half away.
        const double bound = (ring - 1) * std::min(col.cx, col.cy) - hMax - rMax - o.shell;
        if (bound >= best) break;
        for (int ax = -ring; ax <= ring; ++ax)
          for (int ay = -ring; ay <= ring; ++ay) {
            if (std::max(std::abs(ax), std::abs(ay)) != ring) continue;
            int gx = cx + ax, gy = cy + ay;
            if (per.periodic[0]) gx = ((gx % col.nx) + col.nx) % col.nx;
            else if (gx < 0 || gx >= col.nx) continue;
            if (per.periodic[1]) gy = ((gy % col.ny) + col.ny) % col.ny;
            else if (gy < 0 || gy >= col.ny) continue;
            const int c = gx * col.ny + gy;
            if (seen[c] == stamp) continue;
            seen[c] = stamp;
            for (int e = col.start[c]; e < col.start[c + 1]; ++e) {
              const int i = col.items[e];
              const Vec3 r = per.minimumImage(p - b.position[i]);
              const double s = std::clamp(r.dot(axis[i]), -half[i], half[i]);
              best = std::min(best, (r - s * axis[i]).norm() - radius[i]);
            }
          }
      }
      d[q * n[2] + iz] = best;
    }
  }
  }

  // Serial statistics (independent of the threads).
  std::vector<double> diameters;
  diameters.reserve(out.points);
  for (double v : d)
    if (v > 0.0) diameters.push_back(2.0 * v);
  out.voidPoints = static_cast<long>(diameters.size());
  out.voidFraction = static_cast<double>(out.voidPoints) / out.points;
  if (diameters.empty()) return out;
  double sum = 0.0;
  for (double v : diameters) sum += v, out.largestDiameter = std::max(out.largestDiameter, v);
  out.meanDiameter = sum / diameters.size();
  const int bins = static_cast<int>(std::floor(out.largestDiameter / o.binWidth)) + 1;
  std::vector<long> count(bins, 0);
  for (double v : diameters) ++count[std::min(bins - 1, static_cast<int>(std::floor(v / o.binWidth)))];
  out.fraction.resize(bins), out.cumulative.resize(bins);
  long above = out.voidPoints;
  for (int k = 0; k < bins; ++k) {
    out.fraction[k] = static_cast<double>(count[k]) / out.voidPoints;
    out.cumulative[k] = static_cast<double>(above) / out.voidPoints;
    above -= count[k];
  }
  const std::size_t mid = diameters.size() / 2;
  std::nth_element(diameters.begin(), diameters.begin() + mid, diameters.end());
  out.medianDiameter = diameters[mid];
  return out;
}

}  // namespace mesochain::mdem
