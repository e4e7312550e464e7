#include "objective/core/graphene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/nanotube_builder.hpp"

namespace mesochain::objective {

using units::kPi;

namespace {

// The lattice data of one primitive direction in integer form. Sheet positions are written
// in thirds of the lattice vectors, P = (P1, P2): r = (P1 a1 + P2 a2) / 3.
struct SheetLattice {
  long n, m, t1, t2;
  long det;  // |n t2 - m t1| = 2 (n^2 + nm + m^2) / d_R: hexagons per cell
  // Numerators of the fractional coordinates along C and T (denominator 3 det), by Cramer's
  // rule for P/3 = f_C (n, m) + f_T (t1, t2); n t2 - m t1 < 0, hence the signs.
  long numC(long p1, long p2) const { return -(p1 * t2 - p2 * t1); }
  long numT(long p1, long p2) const { return -(n * p2 - m * p1); }
};

SheetLattice sheetLattice(ChiralIndices dir) {
  if (dir.n < 1 || dir.m < 0 || dir.m > dir.n)
    throw InputError(kBuilderSource, "chiral", fmt::format("[{}, {}]", dir.n, dir.m),
                     "chiral indices 0 <= m <= n, not both 0 (m > n is the mirror image of "
                     "(m, n))");
  if (dir.n > 10000)
    throw InputError(kBuilderSource, "chiral", fmt::format("[{}, {}]", dir.n, dir.m), "n <= 10000");
  const long g = std::gcd(dir.n, dir.m);
  SheetLattice l{};
  l.n = dir.n / g;
  l.m = dir.m / g;
  const long dr = std::gcd(2 * l.n + l.m, 2 * l.m + l.n);
  l.t1 = (2 * l.m + l.n) / dr;
  l.t2 = -(2 * l.n + l.m) / dr;
  l.det = -(l.n * l.t2 - l.m * l.t1);
  return l;
}

// Fractional coordinates (f_C, f_T) in [0, 1)^2 of the atoms of one sheet cell, the whole
// sheet shifted by `shift` thirds of a1 + a2. Sublattices at 0 and 2 (a1 + a2)/3.
std::vector<std::pair<double, double>> sheetCellAtoms(const SheetLattice& l, int shift) {
  const long den = 3 * l.det;
  const long iMin = std::min({0L, l.n, l.t1, l.n + l.t1}) - 1;
  const long iMax = std::max({0L, l.n, l.t1, l.n + l.t1}) + 1;
  const long jMin = std::min({0L, l.m, l.t2, l.m + l.t2}) - 1;
  const long jMax = std::max({0L, l.m, l.t2, l.m + l.t2}) + 1;
  std::vector<std::pair<long, long>> found;
  for (long i = iMin; i <= iMax; ++i)
    for (long j = jMin; j <= jMax; ++j)
      for (int sub : {0, 2}) {
        const long p1 = 3 * i + sub + shift, p2 = 3 * j + sub + shift;
        const long c = l.numC(p1, p2), t = l.numT(p1, p2);
        if (c >= 0 && c < den && t >= 0 && t < den) found.emplace_back(c, t);
      }
  if (static_cast<long>(found.size()) != 2 * l.det)
    throw std::logic_error(fmt::format("graphene sheet cell ({}, {}): {} atoms, expected {}", l.n,
                                       l.m, found.size(), 2 * l.det));
  std::sort(found.begin(), found.end());
  std::vector<std::pair<double, double>> f;
  for (const auto& [c, t] : found)
    f.emplace_back(static_cast<double>(c) / den, static_cast<double>(t) / den);
  return f;
}

}  // namespace

ChiralIndices chiralIndices(Direction dir) {
  return dir == Direction::Armchair ? ChiralIndices{1, 1} : ChiralIndices{1, 0};
}

GrapheneSheetCell grapheneSheetCell(ChiralIndices dir, double bondLength) {
  const SheetLattice l = sheetLattice(dir);
  const double a = std::sqrt(3.0) * bondLength;
  // |n a1 + m a2|^2 = a^2 (n^2 + nm + m^2); likewise for T.
  GrapheneSheetCell s;
  s.primitive = {static_cast<int>(l.n), static_cast<int>(l.m)};
  s.arcPeriod = a * std::sqrt(static_cast<double>(l.n * l.n + l.n * l.m + l.m * l.m));
  s.axialPeriod = a * std::sqrt(static_cast<double>(l.t1 * l.t1 + l.t1 * l.t2 + l.t2 * l.t2));
  s.atomsPerLayer = static_cast<int>(2 * l.det);
  return s;
}

ObjectiveCell buildGrapheneRingSector(int layers, ChiralIndices dir, int rotationOrder,
                                      int cellsAlongArc, double interlayer, double bondLength) {
  if (layers < 1) throw InputError(kBuilderSource, "layers", std::to_string(layers), "at least one layer");
  if (rotationOrder < 1)
    throw InputError(kBuilderSource, "rotation_order", std::to_string(rotationOrder), "an integer >= 1");
  if (cellsAlongArc < 1)
    throw InputError(kBuilderSource, "cells_along_arc", std::to_string(cellsAlongArc),
                     "at least one cell per sector");
  if (!std::isfinite(bondLength) || !(bondLength > 0.0))
    throw InputError(kBuilderSource, "bond_length", fmt::format("{}", bondLength),
                     "a positive, finite bond length");
  if (layers > 1 && (!std::isfinite(interlayer) || !(interlayer > 0.0)))
    throw InputError(kBuilderSource, "interlayer", fmt::format("{}", interlayer),
                     "a positive, finite interlayer distance");
  {
    // Atoms of the sector, counted before any is placed: 4 L / d_R per C x T parallelogram
    // (L = n^2 + nm + m^2, d_R = gcd(2n + m, 2m + n)), per cell along the arc and layer.
    const long long l = 1LL * dir.n * dir.n + 1LL * dir.n * dir.m + 1LL * dir.m * dir.m;
    const long long dr = std::gcd(2LL * dir.n + dir.m, 2LL * dir.m + dir.n);
    const long long atoms = 4 * l / std::max(1LL, dr) * cellsAlongArc * layers;
    if (atoms > kMaxBuiltAtoms)
      throw InputError(kBuilderSource, "layers, chiral and cells_along_arc",
                       fmt::format("{} layers x {} cells of direction ({}, {}): {} atoms", layers,
                                   cellsAlongArc, dir.n, dir.m, atoms),
                       fmt::format("at most {} atoms per cell", kMaxBuiltAtoms));
  }
  const SheetLattice lattice = sheetLattice(dir);
  const GrapheneSheetCell sheet = grapheneSheetCell(dir, bondLength);
  const double rMid = rotationOrder * cellsAlongArc * sheet.arcPeriod / (2.0 * kPi);
  const double rInner = rMid - 0.5 * (layers - 1) * interlayer;
  if (!(rInner > 0.0))
    throw InputError(
        kBuilderSource, "rotation_order and cells_along_arc",
        fmt::format("a middle radius of {:.4f} Å for {} layers {:.4f} Å apart",
                    rMid * units::kBohrInAngstrom, layers, interlayer * units::kBohrInAngstrom),
        "an innermost layer at positive radius (more cells per sector)");
  const auto layerA = sheetCellAtoms(lattice, 0);
  const auto layerB = sheetCellAtoms(lattice, 1);  // Bernal: shifted by (a1 + a2)/3
  ObjectiveCell cell;
  cell.symmetry = Symmetry::screw(sheet.axialPeriod, 0.0, rotationOrder);
  for (int k = 0; k < layers; ++k) {
    const double radius = rMid + (k - 0.5 * (layers - 1)) * interlayer;
    for (int c = 0; c < cellsAlongArc; ++c)
      for (const auto& [fc, ft] : (k % 2 == 1) ? layerB : layerA) {
        const double phi = (c + fc) * sheet.arcPeriod / rMid;
        cell.addAtom("C", {radius * std::cos(phi), radius * std::sin(phi), ft * sheet.axialPeriod});
      }
  }
  return cell;
}

ObjectiveCell buildGrapheneRingSector(int layers, Direction dir, int rotationOrder,
                                      int cellsAlongArc, double interlayer, double bondLength) {
  return buildGrapheneRingSector(layers, chiralIndices(dir), rotationOrder, cellsAlongArc,
                                 interlayer, bondLength);
}

}  // namespace mesochain::objective
