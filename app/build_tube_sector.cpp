#include "app/build_tube_sector.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_checks.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "objective/core/tube_sector_builder.hpp"

namespace mesochain::app {

void addTubeSectorOptions(CLI::App& s, TubeSectorOptions& o) {
  s.add_option("walls", o.walls, "chiral indices of the walls, inner first, as n,m (or give --family)");
  s.add_option("--family", o.family, "armchair (n,n) or zigzag (n,0) walls, with --inner and --walls")
      ->check(CLI::IsMember({"armchair", "zigzag"}));
  s.add_option("--inner", o.inner, "index n of the inner wall (with --family)")->check(integerIn(1, 10000));
  s.add_option("--walls", o.count, "number of walls (with --family)")->check(integerIn(1, 100));
  s.add_option("--step", o.step, "index step between walls (default: the one nearest --spacing)")
      ->check(integerIn(1, 10000));
  s.add_option("--spacing", o.spacing, "wall spacing for the default step, Å (default 3.4)")->check(finiteNumber(false));
  s.add_option("--rotation-order", o.rotationOrder,
               "sectors of the full tube, a divisor of gcd(n, m) of every wall (default: that gcd)")
      ->check(integerIn(1, 10000));
}

BuiltTubeSector buildTubeSector(const TubeSectorOptions& o, std::vector<std::pair<int, int>> walls, double bond) {
  const std::string cl = "<command line>";
  if (!o.family.empty()) {
    if (!walls.empty())
      throw InputError(cl, "build tube-sector", "walls and --family", "either n,m walls or --family with --inner, --walls");
    if (o.inner < 1 || o.count < 1)
      throw InputError(cl, "build tube-sector --family", "no --inner or --walls", "--inner N and --walls COUNT");
    const objective::TubeFamily f = objective::tubeFamily(o.family, cl, "--family");
    const int step = o.step > 0 ? o.step : objective::nearestIndexStep(f, o.spacing * units::kAngstromInBohr, bond);
    walls = objective::familyWalls(f, o.inner, o.count, step);
  } else if (walls.empty()) {
    throw InputError(cl, "build tube-sector", "no walls", "n,m walls (e.g. 35,35 40,40) or --family with --inner, --walls");
  } else if (o.inner > 0 || o.count > 0 || o.step > 0) {
    throw InputError(cl, "build tube-sector", "--inner, --walls or --step without --family", "--family armchair|zigzag");
  }
  const int largest = objective::largestSectorOrder(walls);
  const int order = o.rotationOrder > 0 ? o.rotationOrder : largest;
  BuiltTubeSector b;
  b.cell = objective::buildMultiWallSector(walls, bond, order);
  std::string name = "sector", what;
  for (const auto& [n, m] : walls) {
    name += fmt::format("_{}-{}", n, m);
    what += fmt::format("{}({},{})", what.empty() ? "" : "@", n, m);
  }
  std::string counts;
  for (const auto& [n, m] : walls)
    counts += fmt::format("{}{}", counts.empty() ? "" : " + ",
                          objective::NanotubeRollUp(n, m, bond).translationalAtomCount() / order);
  b.fileName = fmt::format("{}-C{}.toml", name, order);
  b.what = fmt::format("C{} sector of {} ({} atoms per wall; largest exact sector C{})", order, what, counts, largest);
  return b;
}

}  // namespace mesochain::app
