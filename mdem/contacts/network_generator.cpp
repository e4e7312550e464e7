#include "mdem/contacts/network_generator.hpp"

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/contacts/contact_dashpot.hpp"
#include "mdem/contacts/portable_math.hpp"
#include "mdem/contacts/portable_random.hpp"
#include "mdem/contacts/neighbour_list.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

void generateNetwork(Scene& scene, const NetworkSpec& spec) {
  const ElementType& t = scene.elementTypes.at(spec.elementType);
  const double r = t.contactRadius(), l = t.length, reach = 2.0 * r + spec.minimumGap;
  if (spec.tubes < 1 || spec.elementsPerTube < 1)
    throw InputError(scene.source, "key network.tubes", fmt::format("{} tubes of {} elements", spec.tubes, spec.elementsPerTube),
                     "at least one tube of at least one element");
  if (spec.size.x() <= 0.0 || spec.size.y() <= 0.0 || spec.size.z() < 0.0)
    throw InputError(scene.source, "key network.size_nm", fmt::format("[{}, {}, {}]", spec.size.x(), spec.size.y(), spec.size.z()),
                     "positive film extents along x and y, a thickness >= 0");
  // Quick test: tube footprints (length x (2r + gap)) cannot cover more than the film's area per
  // layer times the number of layers that fit in the thickness.
  const double layers = std::floor(spec.size.z() / reach) + 1.0;
  const double footprint = spec.tubes * spec.elementsPerTube * l * reach;
  if (footprint > layers * spec.size.x() * spec.size.y())
    throw InputError(scene.source, "key network.tubes",
                     fmt::format("{} tubes covering {:.4g} nm^2", spec.tubes, footprint),
                     fmt::format("a density that can be packed: at most {:.4g} nm^2 of tube footprint in a "
                                 "{:.4g} x {:.4g} nm film of {:.0f} layer(s)",
                                 layers * spec.size.x() * spec.size.y(), spec.size.x(), spec.size.y(), layers));
  std::mt19937_64 gen(spec.seed);
  // Placed segments on a coarse grid (cell >= element length + reach) for the overlap checks.
  const double cell = l + reach;
  const int nx = std::max(1, static_cast<int>(spec.size.x() / cell)), ny = std::max(1, static_cast<int>(spec.size.y() / cell));
  std::vector<std::vector<Segment>> grid(nx * ny);
  auto cellOf = [&](const Vec3& x, int* cx, int* cy) {
    *cx = std::clamp(static_cast<int>(x.x() / spec.size.x() * nx), 0, nx - 1);
    *cy = std::clamp(static_cast<int>(x.y() / spec.size.y() * ny), 0, ny - 1);
  };
  auto clear = [&](const Segment& s) {
    int cx, cy;
    cellOf(s.centre, &cx, &cy);
    for (int i = std::max(0, cx - 1); i <= std::min(nx - 1, cx + 1); ++i)
      for (int j = std::max(0, cy - 1); j <= std::min(ny - 1, cy + 1); ++j)
        for (const Segment& o : grid[i * ny + j])
          if (wallGap(s, o, r, r) < spec.minimumGap) return false;
    return true;
  };
  for (int tube = 0; tube < spec.tubes; ++tube) {
    std::vector<Segment> segs;
    bool placed = false;
    for (int attempt = 0; attempt < spec.attemptsPerTube && !placed; ++attempt) {
      segs.clear();
      double phi = 2.0 * units::kPi * uniformUnit(gen);
      const double z = spec.size.z() * uniformUnit(gen);
      Vec3 x(spec.size.x() * uniformUnit(gen), spec.size.y() * uniformUnit(gen), z);
      placed = true;
      for (int k = 0; k < spec.elementsPerTube; ++k) {
        if (k > 0) {
          const double turn = spec.waviness * (2.0 * uniformUnit(gen) - 1.0);
          const Vec3 prev(portableCos(phi), portableSin(phi), 0.0);
          phi += turn;
          const Vec3 next(portableCos(phi), portableSin(phi), 0.0);
          x += 0.5 * l * (prev + next);  // ends of consecutive elements meet
        }
        const Segment s{x, Vec3(portableCos(phi), portableSin(phi), 0.0), 0.5 * l};
        if (x.x() < 0.0 || x.x() > spec.size.x() || x.y() < 0.0 || x.y() > spec.size.y() || !clear(s)) {
          placed = false;
          break;
        }
        segs.push_back(s);
      }
    }
    if (!placed)
      throw InputError(scene.source, "key network.tubes",
                       fmt::format("no room for tube {} of {} after {} attempts", tube + 1, spec.tubes, spec.attemptsPerTube),
                       "a lower density (fewer or shorter tubes, a larger or thicker film, a smaller minimum gap)");
    const int first = scene.bodies.size();
    for (std::size_t k = 0; k < segs.size(); ++k) {
      const Vec3 ez = segs[k].axis, ex = Vec3::UnitZ().cross(ez).normalized();
      Mat3 m;
      m.col(0) = ex, m.col(1) = ez.cross(ex), m.col(2) = ez;
      scene.bodies.add(spec.elementType, t, segs[k].centre, fromMatrix(m));
      if (k > 0) addBond(scene, first + static_cast<int>(k) - 1, first + static_cast<int>(k), spec.bondType);
      int cx, cy;
      cellOf(segs[k].centre, &cx, &cy);
      grid[cx * ny + cy].push_back(segs[k]);
    }
  }
}

void checkNoOverlaps(const Scene& scene, double minimumGap) {
  const Bodies& b = scene.bodies;
  const FilamentTopology topo = buildTopology(b.size(), scene.bonds, 0, {});
  auto seg = [&](int i) {
    return Segment{b.position[i], rotate(b.orientation[i], Vec3::UnitZ()), 0.5 * scene.elementTypes[b.type[i]].length};
  };
  for (int i = 0; i < b.size(); ++i)
    for (int j = i + 1; j < b.size(); ++j) {
      if (topo.filament[i] == topo.filament[j]) continue;
      const Segment si = seg(i), sj = seg(j);
      if ((si.centre - sj.centre).norm() > si.halfLength + sj.halfLength + 10.0) continue;
      const double gap = wallGap(si, sj, scene.elementTypes[b.type[i]].contactRadius(), scene.elementTypes[b.type[j]].contactRadius());
      if (gap < minimumGap)
        throw InputError(scene.source, "elements",
                         fmt::format("elements {} and {} of different tubes overlapping (wall gap {:.3g} nm)", i, j, gap),
                         fmt::format("tubes at least {:.3g} nm apart", minimumGap));
    }
}

}  // namespace mesochain::mdem
