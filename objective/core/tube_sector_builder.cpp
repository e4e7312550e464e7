#include "objective/core/tube_sector_builder.hpp"

#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain::objective {

TubeFamily tubeFamily(const std::string& name, const std::string& source, const std::string& key) {
  if (name == "armchair") return TubeFamily::Armchair;
  if (name == "zigzag") return TubeFamily::Zigzag;
  throw InputError(source, key, "\"" + name + "\"", "armchair or zigzag");
}

std::vector<std::pair<int, int>> familyWalls(TubeFamily family, int inner, int walls, int step) {
  const char* src = "<builder>";
  if (inner < 1) throw InputError(src, "inner wall index", std::to_string(inner), "an integer >= 1");
  if (walls < 1 || walls > 100) throw InputError(src, "walls", std::to_string(walls), "1 to 100 walls");
  if (step < 1) throw InputError(src, "index step", std::to_string(step), "an integer >= 1");
  if (static_cast<long>(inner) + static_cast<long>(walls - 1) * step > 10000)
    throw InputError(src, "walls", fmt::format("an outer index of {}", static_cast<long>(inner) + (walls - 1L) * step),
                     "indices up to 10000");
  std::vector<std::pair<int, int>> out;
  for (int k = 0; k < walls; ++k) {
    const int n = inner + k * step;
    out.emplace_back(n, family == TubeFamily::Armchair ? n : 0);
  }
  return out;
}

int nearestIndexStep(TubeFamily family, double spacing, double bondLength) {
  // Radius per unit of the index: |C_h| / 2 pi with |C_h| = sqrt3 a n (armchair), a n (zigzag).
  const double a = std::sqrt(3.0) * bondLength;
  const double perIndex = (family == TubeFamily::Armchair ? std::sqrt(3.0) * a : a) / (2.0 * units::kPi);
  return std::max(1, static_cast<int>(std::lround(spacing / perIndex)));
}

int largestSectorOrder(const std::vector<std::pair<int, int>>& walls) {
  int g = 0;
  for (const auto& [n, m] : walls) g = std::gcd(g, std::gcd(n, m));
  return g;
}

}  // namespace mesochain::objective
