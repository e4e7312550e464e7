#include "mdem/contacts/deposition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/contacts/contact_dashpot.hpp"
#include "mdem/contacts/portable_math.hpp"
#include "mdem/contacts/portable_random.hpp"
#include "mdem/contacts/drape_geometry.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

namespace {
// Standard normal by Box-Muller from two portable uniforms (portable_math.hpp: the same bits on
// every platform).
double normal(std::mt19937_64& g) {
  const double u1 = uniformUnit(g), u2 = uniformUnit(g);
  return std::sqrt(-2.0 * portableLog(1.0 - u1)) * portableCos(2.0 * units::kPi * u2);
}

constexpr int kSelfExclude = 3;    // elements along one tube closer than this are not checked
constexpr int kSettleRounds = 30;
constexpr double kHeightSlack = 1e-9;  // nm added to supports against rounding
constexpr double kRestTolerance = 0.02;  // nm: a laid tube lies at most this above its lowest clear profile

// The periodic generation domain [0, px) x [0, py) with a grid of columns for the supports.
class Domain {
 public:
  Domain(double px, double py, double reach) : px_(px), py_(py) {
    nx_ = std::max(1, static_cast<int>(px / reach)), ny_ = std::max(1, static_cast<int>(py / reach));
    cells_.resize(static_cast<std::size_t>(nx_) * ny_);
    // Neighbour columns per axis: offsets -1, 0, 1, or every column once when fewer than 3.
    auto around = [](int n) {
      std::vector<int> d;
      if (n >= 3) return std::vector<int>{-1, 0, 1};
      for (int k = 0; k < n; ++k) d.push_back(k);
      return d;
    };
    offX_ = around(nx_), offY_ = around(ny_);
  }
  Vec3 wrap(Vec3 x) const {
    x.x() -= px_ * std::floor(x.x() / px_), x.y() -= py_ * std::floor(x.y() / py_);
    return x;
  }
  Vec3 minimumImage(Vec3 d) const {
    d.x() -= px_ * std::nearbyint(d.x() / px_), d.y() -= py_ * std::nearbyint(d.y() / py_);
    return d;
  }
  int cellOf(const Vec3& wrapped) const {
    const int cx = std::clamp(static_cast<int>(wrapped.x() / px_ * nx_), 0, nx_ - 1);
    const int cy = std::clamp(static_cast<int>(wrapped.y() / py_ * ny_), 0, ny_ - 1);
    return cx * ny_ + cy;
  }
  // Calls f(index) for every stored element in the 3 x 3 columns around `wrapped`.
  template <class F>
  void forNear(const Vec3& wrapped, F&& f) const {
    const int c = cellOf(wrapped), cx = c / ny_, cy = c % ny_;
    for (int dx : offX_)
      for (int dy : offY_) {
        const int x = nx_ >= 3 ? (cx + dx + nx_) % nx_ : dx, y = ny_ >= 3 ? (cy + dy + ny_) % ny_ : dy;
        for (int j : cells_[x * ny_ + y]) f(j);
      }
  }
  void insert(int index, const Vec3& wrapped) { cells_[cellOf(wrapped)].push_back(index); }
  void removeLast(const Vec3& wrapped) { cells_[cellOf(wrapped)].pop_back(); }

 private:
  double px_, py_;
  int nx_, ny_;
  std::vector<std::vector<int>> cells_;
  std::vector<int> offX_, offY_;
};

struct LaidElement {
  Vec3 centre;  // wrapped into the domain (z as laid)
  Vec3 axis;
};

struct TubePath {
  Vec3 start;                    // first end, in-plane, unwrapped
  std::vector<double> heading;   // per element, rad
};

// Element centres (unwrapped) and axes of a tube with end heights zeta.
void placeTube(const TubePath& path, const std::vector<double>& zeta, double l, std::vector<Vec3>& centre,
               std::vector<Vec3>& axis) {
  const int n = static_cast<int>(path.heading.size());
  centre.resize(n), axis.resize(n);
  Vec3 end = path.start;
  end.z() = zeta[0];
  for (int k = 0; k < n; ++k) {
    const double dz = zeta[k + 1] - zeta[k], h = std::sqrt(std::max(0.0, l * l - dz * dz));
    const Vec3 step(h * portableCos(path.heading[k]), h * portableSin(path.heading[k]), dz);
    centre[k] = end + 0.5 * step;
    axis[k] = step / l;
    end += step;
  }
}

Quat frameAlong(const Vec3& axis) {
  Vec3 ex = Vec3::UnitZ().cross(axis);
  if (ex.norm() < 1e-9) ex = axis.unitOrthogonal();
  ex.normalize();
  Mat3 m;
  m.col(0) = ex, m.col(1) = axis.cross(ex), m.col(2) = axis;
  return fromMatrix(m);
}
}  // namespace


DepositionResult depositFilm(Scene& scene, const DepositionSpec& spec) {
  const ElementType& type = scene.elementTypes.at(spec.elementType);
  const double r = type.contactRadius(), l = type.length, hl = 0.5 * l;
  const double clearance = 2.0 * r + spec.minimumGap;
  const double tubeLength = spec.elementsPerTube * l;
  const bool cut = spec.boundary == FilmBoundary::Cut;
  const double px = cut ? spec.sheetX : spec.sizeX, py = cut ? spec.sheetY : spec.sizeY;
  const std::string& src = scene.source;
  if (spec.elementsPerTube < 1)
    throw InputError(src, "key network.tube_length_nm", fmt::format("{} elements per tube", spec.elementsPerTube), "at least one");
  if (!(spec.sizeX > 0.0 && spec.sizeY > 0.0))
    throw InputError(src, "key network.size_nm", fmt::format("[{}, {}]", spec.sizeX, spec.sizeY), "positive film extents along x and y");
  if (cut && !(spec.sheetX >= spec.sizeX + tubeLength && spec.sheetY >= spec.sizeY + tubeLength))
    throw InputError(src, "key network.sheet_size_nm", fmt::format("[{:.6g}, {:.6g}] nm", spec.sheetX, spec.sheetY),
                     fmt::format("a sheet at least the film plus one tube length ({:.6g} nm) along x and y, so that a tube "
                                 "enters the cut-out specimen through one image only: >= [{:.6g}, {:.6g}]",
                                 tubeLength, spec.sizeX + tubeLength, spec.sizeY + tubeLength));
  if (tubeLength + clearance > std::min(px, py))
    throw InputError(src, "key network.tube_length_nm",
                     fmt::format("{:.6g} nm tubes in a periodic {} of {:.6g} x {:.6g} nm", tubeLength, cut ? "sheet" : "film", px, py),
                     fmt::format("tubes that cannot meet their own periodic image: length + 2R + minimum gap = {:.6g} nm at most "
                                 "the shorter side ({:.6g} nm){}",
                                 tubeLength + clearance, std::min(px, py), cut ? "; enlarge sheet_size_nm" : "; enlarge size_nm"));
  if (spec.tubes < 1 && !(spec.thickness > 0.0))
    throw InputError(src, spec.countKey, "no number of tubes and no thickness_nm", "a number of tubes, a density or a thickness target");
  if (spec.tubes < 1 && spec.thickness < 2.0 * r)
    throw InputError(src, "key network.thickness_nm", fmt::format("{:.6g} nm", spec.thickness),
                     fmt::format("a thickness that can be reached: at least one tube diameter ({:.6g} nm)", 2.0 * r));
  if (!(spec.maxSlope > 0.0 && spec.maxSlope < units::kPi / 2))
    throw InputError(src, "key network.drape_slope_deg", fmt::format("{:.6g} deg", spec.maxSlope * 180.0 / units::kPi), "an angle in (0, 90) degrees");
  if (!(spec.bendPerElement > 0.0 && spec.bendPerElement <= units::kPi / 2))
    throw InputError(src, "key network.drape_bend_deg", fmt::format("{:.6g} deg", spec.bendPerElement * 180.0 / units::kPi), "an angle in (0, 90] degrees");

  const DrapeProfile profile{l, spec.maxSlope, spec.bendPerElement};
  // Columns wide enough that any element within the clearance of another lies in the 3 x 3 around it.
  Domain domain(px, py, l + clearance);
  std::vector<LaidElement> laid;
  std::vector<int> tubeStart{0};  // laid elements of tube t: [tubeStart[t], tubeStart[t+1])
  std::vector<Vec3> anchor;       // per tube: unwrapped centre of its first element
  const bool checkSelf = spec.waviness > 0.0;
  std::mt19937_64 gen(spec.seed);
  const int n = spec.elementsPerTube;
  double zLow = std::numeric_limits<double>::infinity(), zHigh = -zLow;
  auto thicknessNow = [&] { return laid.empty() ? 0.0 : zHigh - zLow + 2.0 * r; };

  long hovering = 0;
  TubePath path;
  std::vector<double> zeta(n + 1), required(n + 1), need(n + 1), settledZeta, support(n);
  std::vector<Vec3> centre, axis;
  for (int tube = 0;; ++tube) {
    if (spec.tubes > 0 && tube == spec.tubes) break;
    if (spec.tubes < 1 && thicknessNow() >= spec.thickness) break;
    if (spec.tubes < 1 && static_cast<long>(laid.size()) + n > spec.maximumElements)
      throw InputError(src, "key network.thickness_nm", fmt::format("{:.6g} nm, not reached after {} elements ({:.6g} nm)", spec.thickness, laid.size(), thicknessNow()),
                       "a thickness the film reaches within the element budget (a smaller thickness_nm, or a smaller film)");
    bool placed = false;
    for (int attempt = 0; attempt < spec.attemptsPerTube && !placed; ++attempt) {
      path.start = Vec3(px * uniformUnit(gen), py * uniformUnit(gen), 0.0);
      double phi = uniformUnit(gen) < spec.alignedFraction ? spec.alignmentAngle + spec.alignmentSpread * normal(gen)
                                                        : 2.0 * units::kPi * uniformUnit(gen);
      if (uniformUnit(gen) < 0.5) phi += units::kPi;
      path.heading.resize(n);
      for (int k = 0; k < n; ++k) {
        if (k > 0) phi += spec.waviness * (2.0 * uniformUnit(gen) - 1.0);
        path.heading[k] = phi;
      }
      std::fill(zeta.begin(), zeta.end(), 0.0);
      std::fill(required.begin(), required.end(), 0.0);
      bool haveSettled = false, hovered = false;
      for (int round = 0; round < kSettleRounds && !placed; ++round) {
        placeTube(path, zeta, l, centre, axis);
        for (int k = 0; k < n; ++k) {
          const Vec3 here = domain.wrap(centre[k]);
          const double h = std::sqrt(axis[k].x() * axis[k].x() + axis[k].y() * axis[k].y());  // (not libm's hypot)
          const Vec3 a(axis[k].x() / h, axis[k].y() / h, 0.0);
          double best = 0.0;  // the floor
          domain.forNear(here, [&](int j) {
            const LaidElement& o = laid[j];
            Vec3 d = domain.minimumImage(o.centre - here);
            if (d.x() * d.x() + d.y() * d.y() > (l + clearance) * (l + clearance)) return;
            if (o.centre.z() + std::abs(o.axis.z()) * hl + clearance <= best) return;
            d.z() = o.centre.z();
            best = std::max(best, supportHeight(a, hl, d, o.axis, hl, clearance) + kHeightSlack);
          });
          support[k] = best;
        }
        bool settled = true;
        for (int e = 0; e <= n; ++e) {
          need[e] = std::max(e > 0 ? support[e - 1] : 0.0, e < n ? support[e] : 0.0);
          settled &= zeta[e] >= need[e];
        }
        if (settled) {
          // Clear of everything: laid if it also rests (no lower profile clears it here);
          // otherwise remember it and try the lower profile.
          haveSettled = true, settledZeta = zeta;
          const std::vector<double> lower = drapeEnvelope(need, profile);
          double hover = 0.0;
          for (int e = 0; e <= n; ++e) hover = std::max(hover, zeta[e] - lower[e]);
          if (hover <= kRestTolerance) placed = true;
          else zeta = lower, required = need;
          continue;
        }
        // Raise: monotone from round 1 on (round 0 saw the tube flat on the floor, away from
        // where it lies), which makes the loop settle.
        for (int e = 0; e <= n; ++e) required[e] = round == 1 ? need[e] : std::max(required[e], need[e]);
        zeta = drapeEnvelope(required, profile);
      }
      if (!placed && haveSettled) {  // the last profile that cleared everything
        zeta = settledZeta;
        placeTube(path, zeta, l, centre, axis);
        placed = hovered = true;
      }
      if (!placed) continue;
      // Lay it; a wavy tube must also clear itself beyond kSelfExclude elements along it.
      const int first = static_cast<int>(laid.size());
      for (int k = 0; k < n; ++k) {
        laid.push_back({domain.wrap(centre[k]), axis[k]});
        domain.insert(first + k, laid.back().centre);
      }
      if (checkSelf) {
        bool clear = true;
        for (int k = 0; k < n && clear; ++k) {
          const Segment sk{laid[first + k].centre, laid[first + k].axis, hl};
          domain.forNear(sk.centre, [&](int j) {
            if (j < first || std::abs(j - first - k) <= kSelfExclude || !clear) return;
            const Segment sj{sk.centre + domain.minimumImage(laid[j].centre - sk.centre), laid[j].axis, hl};
            if (wallGap(sk, sj, r, r) < spec.minimumGap) clear = false;
          });
        }
        if (!clear) {
          for (int k = n - 1; k >= 0; --k) domain.removeLast(laid[first + k].centre);
          laid.resize(first);
          placed = false;
          continue;
        }
      }
      for (int k = 0; k < n; ++k) zLow = std::min(zLow, centre[k].z()), zHigh = std::max(zHigh, centre[k].z());
      tubeStart.push_back(static_cast<int>(laid.size()));
      anchor.push_back(centre[0]);
      hovering += hovered;
    }
    if (!placed)
      throw InputError(src, spec.countKey,
                       fmt::format("tube {} could not be laid in {} attempts", tube + 1, spec.attemptsPerTube),
                       "a tube shape that can be laid (a smaller waviness_deg for tubes curling onto themselves)");
    if (spec.tubes > 0 && spec.thickness > 0.0 && thicknessNow() > spec.thickness)
      throw InputError(src, spec.countKey,
                       fmt::format("{} tubes: the film reached {:.6g} nm, above thickness_nm = {:.6g}, after {} tubes", spec.tubes,
                                   thicknessNow(), spec.thickness, tube + 1),
                       "a density that can be reached within thickness_nm (fewer tubes or a larger thickness_nm; the "
                       "draped film's thickness depends on drape_slope_deg / drape_bend_deg)");
  }
  DepositionResult result;
  result.tubesLaid = static_cast<int>(anchor.size());
  result.elementsLaid = static_cast<long>(laid.size());
  result.domainThickness = thicknessNow();
  result.hoveringTubes = hovering;

  // The scene: unwrapped positions along each tube, orientations carried along it.
  Bodies straight;  // two elements of the straight tube, for the bond template
  straight.add(spec.elementType, type, Vec3::Zero(), Quat{});
  straight.add(spec.elementType, type, Vec3(0.0, 0.0, l), Quat{});
  const Bond straightBond = makeBond(0, 1, straight, scene.bondTypes.at(spec.bondType).stiffnessFor(l), sectionOf(type));
  const double ox = 0.5 * (px - spec.sizeX), oy = 0.5 * (py - spec.sizeY);
  std::vector<Vec3> position(n);
  std::vector<Quat> orientation(n);
  std::vector<char> keep(n);
  double zMin = std::numeric_limits<double>::infinity(), zMax = -zMin;
  for (std::size_t t = 0; t < anchor.size(); ++t) {
    const LaidElement* e = &laid[tubeStart[t]];
    for (int k = 0; k < n; ++k) {
      position[k] = k == 0 ? anchor[t] : position[k - 1] + domain.minimumImage(e[k].centre - e[k - 1].centre);
      orientation[k] = k == 0 ? frameAlong(e[0].axis) : normalized(minimalRotation(e[k - 1].axis, e[k].axis) * orientation[k - 1]);
      keep[k] = 1;
      if (cut) {
        position[k] = e[k].centre - Vec3(ox, oy, 0.0);  // wrapped in the sheet, specimen at [0, x] x [0, y]
        keep[k] = position[k].x() >= 0.0 && position[k].x() <= spec.sizeX && position[k].y() >= 0.0 && position[k].y() <= spec.sizeY;
      }
    }
    int previous = -1;  // scene index of the previous kept element of this tube
    for (int k = 0; k < n; ++k) {
      if (!keep[k]) {
        previous = -1;
        continue;
      }
      const int index = scene.bodies.size();
      scene.bodies.add(spec.elementType, type, position[k], orientation[k]);
      zMin = std::min(zMin, position[k].z()), zMax = std::max(zMax, position[k].z());
      // Consecutive kept elements are bonded unless the cut separates them (a jump across the sheet).
      const bool bonded = previous >= 0 && (position[k] - scene.bodies.position[previous]).norm() < 1.5 * l;
      if (!bonded) ++result.filaments;
      if (bonded && spec.restShape == RestShape::AsLaid) addBond(scene, previous, index, spec.bondType);
      if (bonded && spec.restShape == RestShape::Straight) {
        Bond b = straightBond;
        b.a = previous, b.b = index;
        scene.bonds.push_back(b);
      }
      previous = index;
    }
  }
  scene.filmSize = Vec3(spec.sizeX, spec.sizeY, zMax >= zMin ? zMax - zMin : 0.0);
  return result;
}

}  // namespace mesochain::mdem
