#include "benchmarks/bench_network_coarsen.hpp"

#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/scene_file.hpp"

namespace mesochain::app {

mdem::Scene coarsenedFilm(const mdem::Scene& fine, const std::string& modelFile) {
  const mdem::Scene model = mdem::loadScene(modelFile);
  if (model.elementTypes.empty() || model.bondTypes.empty())
    throw InputError(modelFile, "element_types, bond_types", "none", "one element type and one bond type");
  if (fine.elementTypes.size() != 1)
    throw InputError(fine.source, "element_types", fmt::format("{}", fine.elementTypes.size()), "one element type to coarsen");
  const mdem::ElementType& type = model.elementTypes[0];
  const double l = type.length;
  if (std::abs(l - 2.0 * fine.elementTypes[0].length) > 1e-9 * l)
    throw InputError(modelFile, "element_types.length_nm", fmt::format("{} nm", l),
                     fmt::format("twice the scene's element length ({} nm)", 2.0 * fine.elementTypes[0].length));
  // Chains: bond i joins (a, a + 1).
  std::vector<char> bondedToNext(fine.bodies.size(), 0);
  for (const mdem::Bond& b : fine.bonds) {
    if (b.b != b.a + 1) throw InputError(fine.source, "bonds", fmt::format("a bond {} - {}", b.a, b.b), "chains in index order");
    bondedToNext[b.a] = 1;
  }
  mdem::Scene s = fine;
  s.elementTypes = {type};
  s.bondTypes = {model.bondTypes[0]};
  s.bodies = mdem::Bodies{};
  s.bonds.clear();
  s.inputHash = fine.inputHash ^ (model.inputHash * 0x9E3779B97F4A7C15ULL);  // a relaxed-state checkpoint of its own
  mdem::Bodies straight;  // the bond template of a straight tube (deposition.cpp, rest_shape straight)
  straight.add(0, type, mdem::Vec3::Zero(), mdem::Quat{});
  straight.add(0, type, mdem::Vec3(0.0, 0.0, l), mdem::Quat{});
  const mdem::Bond straightBond =
      mdem::makeBond(0, 1, straight, s.bondTypes[0].stiffnessFor(l), mdem::sectionOf(type));
  long dropped = 0;
  for (int start = 0; start < fine.bodies.size();) {
    int end = start;  // the filament is [start, end]
    while (end + 1 < fine.bodies.size() && bondedToNext[end]) ++end;
    int previous = -1;
    for (int k = start; k <= end; k += 2) {
      if (k + 1 > end) {
        ++dropped;
        break;
      }
      const mdem::Vec3 chord = fine.bodies.position[k + 1] - fine.bodies.position[k];
      const mdem::Vec3 axis = mdem::rotate(fine.bodies.orientation[k], mdem::Vec3::UnitZ());
      const mdem::Quat q = mdem::normalized(mdem::minimalRotation(axis, chord.normalized()) * fine.bodies.orientation[k]);
      const int index = s.bodies.size();
      s.bodies.add(0, type, 0.5 * (fine.bodies.position[k] + fine.bodies.position[k + 1]), q);
      if (previous >= 0) {
        mdem::Bond b = straightBond;
        b.a = previous, b.b = index;
        s.bonds.push_back(b);
      }
      previous = index;
    }
    start = end + 1;
  }
  std::cout << fmt::format("coarsened to {}-nm elements ({}): {} -> {} elements, {} -> {} bonds; {} odd last elements dropped ({:.2g} % of the mass)\n",
                           l, modelFile, fine.bodies.size(), s.bodies.size(), fine.bonds.size(), s.bonds.size(), dropped,
                           100.0 * dropped / fine.bodies.size());
  return s;
}

}  // namespace mesochain::app
