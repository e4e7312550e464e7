// Deposition generator of buckypaper films (mdem/contacts/deposition.hpp): the support height is
// the upper contact height, the draped envelope is the brute-force max of its definition, films
// have no overlaps (also of a tube with its periodic image), every tube rests on something,
// the film report matches an independent recount, seeds reproduce bit for bit, orientation
// distributions give the expected order parameter, cut mode keeps the inside and splits tubes,
// the straight rest state stores exactly the bending energy of the drape, bad requests name
// their key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "common/errors.hpp"
#include "contact_fixture.hpp"
#include "mdem/contacts/contact_dashpot.hpp"
#include "mdem/contacts/deposition.hpp"
#include "mdem/contacts/drape_geometry.hpp"
#include "mdem/contacts/element_pairs.hpp"
#include "mdem/contacts/film_statistics.hpp"
#include "mdem/contacts/neighbour_list.hpp"
#include "mdem/contacts/network_generator.hpp"
#include "mdem/scene_file.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;
constexpr double kDeg = units::kPi / 180.0;
constexpr double kGap = 0.3;

double segmentDistance(const Segment& a, const Segment& b) {
  double sa, sb;
  closestPoints(a, b, &sa, &sb);
  return (a.centre + sa * a.axis - b.centre - sb * b.axis).norm();
}

TEST(MdemDeposition, SupportHeightIsTheUpperContactHeight) {
  std::mt19937_64 g(5);
  auto u = [&] { return static_cast<double>(g() >> 11) * 0x1.0p-53; };
  const double d = 2.0 * kTubeRadius + kGap;
  int touching = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double phi = 2.0 * units::kPi * u();
    const Vec3 a(std::cos(phi), std::sin(phi), 0.0);
    const Vec3 c(6.0 * u() - 3.0, 6.0 * u() - 3.0, 4.0 * u() - 2.0);
    Vec3 b(2.0 * u() - 1.0, 2.0 * u() - 1.0, trial % 5 == 0 ? 0.0 : 2.0 * u() - 1.0);
    if (trial % 7 == 0) b = a;  // parallel
    b.normalize();
    const double z = supportHeight(a, 1.0, c, b, 1.0, d);
    const Segment sb{c, b, 1.0};
    auto distanceAt = [&](double h) { return segmentDistance(Segment{Vec3(0.0, 0.0, h), a, 1.0}, sb); };
    if (std::isinf(z)) {
      for (double h = -6.0; h <= 6.0; h += 0.01) ASSERT_GE(distanceAt(h), d - 1e-9) << trial;
      continue;
    }
    ++touching;
    EXPECT_NEAR(distanceAt(z), d, 1e-7) << trial;  // in contact at z_hi
    for (double dh : {1e-6, 1e-3, 0.1, 1.0, 3.0}) EXPECT_GE(distanceAt(z + dh), d - 1e-9) << trial;  // clear above
  }
  EXPECT_GT(touching, 500);
}

TEST(MdemDeposition, DrapeEnvelopeIsTheMaximumOfItsDefinition) {
  std::mt19937_64 g(11);
  auto u = [&] { return static_cast<double>(g() >> 11) * 0x1.0p-53; };
  const DrapeProfile p{2.0, 10.0 * kDeg, 2.0 * kDeg};
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 5 + static_cast<int>(60 * u());
    std::vector<double> req(n, 0.0);
    for (double& r : req)
      if (u() < 0.2) r = 3.0 * u();
    const std::vector<double> z = drapeEnvelope(req, p);
    for (int e = 0; e < n; ++e) {
      double expected = -1e300;
      for (int j = 0; j < n; ++j) {
        double f = 0.0;  // f(d) = sum_{i=1..d} L sin(min(alpha, (i - 1/2) beta))
        for (int i = 1; i <= std::abs(e - j); ++i) f += 2.0 * std::sin(std::min(10.0 * kDeg, (i - 0.5) * 2.0 * kDeg));
        expected = std::max(expected, req[j] - f);
      }
      EXPECT_NEAR(z[e], expected, 1e-12) << trial << " " << e;
      EXPECT_GE(z[e], req[e]);
      if (e > 0) {
        EXPECT_LE(std::abs(z[e] - z[e - 1]), 2.0 * std::sin(10.0 * kDeg) + 1e-12);
      }
    }
  }
}

DepositionSpec film(int tubes, int elements, double size, std::uint64_t seed) {
  DepositionSpec d;
  d.tubes = tubes, d.elementsPerTube = elements;
  d.sizeX = d.sizeY = size;
  d.seed = seed;
  return d;
}

Scene deposit(const DepositionSpec& d, DepositionResult* result = nullptr) {
  Scene s = tubeScene({"bonds"});
  const DepositionResult r = depositFilm(s, d);
  if (result) *result = r;
  if (d.boundary == FilmBoundary::Periodic) s.periodic.periodic = {true, true, false}, s.periodic.length = Vec3(d.sizeX, d.sizeY, 0.0);
  return s;
}

Vec3 axisOf(const Scene& s, int i) { return rotate(s.bodies.orientation[i], Vec3::UnitZ()); }

// Consecutive ends of each bonded pair meet; every tube rests on the floor or on another tube
// (some element within 0.02 nm of the floor or of the contact gap), except the tubes the
// generator reports as hovering (laid on a clear profile that did not settle).
void expectConnectedAndResting(const Scene& s, double gap, long hovering) {
  for (const Bond& b : s.bonds) {
    const Vec3 ea = s.bodies.position[b.a] + 0.5 * kSegmentLength * axisOf(s, b.a);
    const Vec3 eb = s.bodies.position[b.b] - 0.5 * kSegmentLength * axisOf(s, b.b);
    ASSERT_LT((ea - eb).norm(), 1e-9) << b.a << " " << b.b;
  }
  const FilamentTopology topo = buildTopology(s.bodies.size(), s.bonds, 0, {});
  std::vector<double> lowest(topo.filamentSize.size(), 1e300);  // min over elements of z or |gap - minimum gap|
  for (int i = 0; i < s.bodies.size(); ++i) lowest[topo.filament[i]] = std::min(lowest[topo.filament[i]], s.bodies.position[i].z());
  for (const ClosePair& p : closePairs(s, gap + 0.03, 3))
    for (int e : {p.i, p.j}) lowest[topo.filament[e]] = std::min(lowest[topo.filament[e]], std::abs(p.gap - gap));
  long floating = 0;
  for (double v : lowest) floating += v > 0.02 + 1e-9;
  EXPECT_LE(floating, hovering);
}

TEST(MdemDeposition, SmallAndMediumFilmsHaveNoOverlapsAndRestOnWhatLiesBelow) {
  DepositionResult small, medium;
  const Scene a = deposit(film(40, 20, 100.0, 3), &small);
  EXPECT_EQ(a.bodies.size(), 800);
  EXPECT_EQ(a.bonds.size(), 40u * 19u);
  EXPECT_NO_THROW(checkNoOverlapsCellList(a, kGap - 1e-9, 3));
  EXPECT_NO_THROW(checkNoOverlaps(a, kGap - 1e-9));  // the O(n^2) check agrees (different tubes)
  EXPECT_THROW(checkNoOverlapsCellList(a, kGap + 1e-3, 3), InputError);  // tubes do touch at the gap
  expectConnectedAndResting(a, kGap, small.hoveringTubes);
  EXPECT_LT(small.hoveringTubes, 4);
  EXPECT_GT(small.domainThickness, 2.0 * kTubeRadius + 0.5);  // crossings lift tubes

  DepositionSpec m = film(120, 40, 150.0, 4);
  m.waviness = 6.0 * kDeg;
  const Scene b = deposit(m, &medium);
  EXPECT_EQ(b.bodies.size(), 4800);
  EXPECT_NO_THROW(checkNoOverlapsCellList(b, kGap - 1e-9, 3));  // includes a tube with its images
  expectConnectedAndResting(b, kGap, medium.hoveringTubes);
  EXPECT_LT(medium.hoveringTubes, 12);
  // Tubes continue across the periodic edges with unwrapped positions.
  bool outside = false;
  for (const Vec3& x : b.bodies.position) outside |= x.x() < 0.0 || x.x() > 150.0 || x.y() < 0.0 || x.y() > 150.0;
  EXPECT_TRUE(outside);
}

TEST(MdemDeposition, FilmReportMatchesAnIndependentRecount) {
  const Scene s = deposit(film(40, 20, 100.0, 3));
  const FilmStatistics f = filmStatistics(s);
  double mass = 0.0, zMin = 1e300, zMax = -1e300;
  for (int i = 0; i < s.bodies.size(); ++i)
    mass += s.bodies.mass[i], zMin = std::min(zMin, s.bodies.position[i].z()), zMax = std::max(zMax, s.bodies.position[i].z());
  const double t = zMax - zMin + 2.0 * kTubeRadius, area = 100.0 * 100.0;
  EXPECT_NEAR(f.thickness, t, 1e-12);
  EXPECT_NEAR(f.density, mass / (area * t) * 1e3, 1e-12 * f.density);  // 1 ag/nm^3 = 1000 g/cm^3
  const double vdw = units::kPi * std::pow(kTubeRadius + 0.17, 2) * kSegmentLength * s.bodies.size();
  EXPECT_NEAR(f.porosity, 1.0 - vdw / (area * t), 1e-12);
  EXPECT_NEAR(f.arealDensity, mass / area * 100.0, 1e-12 * f.arealDensity);
  // Bodies that carry scaled masses ([run] mass_scale, as a stage's end state does) report the
  // same, true, densities.
  Scene heavy = s;
  scaleInertia(heavy.bodies, heavy.elementTypes, 9.0, 1.0);
  ASSERT_EQ(heavy.bodies.mass[0], 9.0 * s.bodies.mass[0]);
  EXPECT_EQ(filmStatistics(heavy).density, f.density);
  EXPECT_EQ(filmStatistics(heavy).arealDensity, f.arealDensity);
  // Contacts by brute force over all pairs (minimum image, same tube within 3 excluded), and
  // the aligned ones (axes within 10 degrees) as an adjacency list for the bundles.
  const FilamentTopology topo = buildTopology(s.bodies.size(), s.bonds, 3, {});
  long pairs = 0;
  std::vector<std::vector<int>> alignedWith(s.bodies.size());
  for (int i = 0; i < s.bodies.size(); ++i)
    for (int j = i + 1; j < s.bodies.size(); ++j) {
      if (topo.excluded(i, j)) continue;
      const Segment si{s.bodies.position[i], axisOf(s, i), 1.0};
      const Segment sj{si.centre + s.periodic.minimumImage(s.bodies.position[j] - si.centre), axisOf(s, j), 1.0};
      const bool contact = segmentDistance(si, sj) - 2.0 * kTubeRadius < 0.5;
      pairs += contact;
      if (contact && std::abs(si.axis.dot(sj.axis)) >= std::cos(10.0 * kDeg))
        alignedWith[i].push_back(j), alignedWith[j].push_back(i);
    }
  // Bundles by flood fill: the connected components of the aligned contacts.
  std::vector<int> seen(s.bodies.size(), 0), sizes;
  for (int i = 0; i < s.bodies.size(); ++i) {
    if (seen[i] || alignedWith[i].empty()) continue;
    std::vector<int> stack{i};
    seen[i] = 1;
    int size = 0;
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back(), ++size;
      for (int m : alignedWith[k])
        if (!seen[m]) seen[m] = 1, stack.push_back(m);
    }
    sizes.push_back(size);
  }
  ASSERT_FALSE(sizes.empty());
  EXPECT_EQ(f.bundles.bundles, static_cast<int>(sizes.size()));
  EXPECT_EQ(f.bundles.largest, *std::max_element(sizes.begin(), sizes.end()));
  std::vector<int> perClass(f.bundles.bundlesInClass.size(), 0);
  for (int size : sizes) {
    int c = 0;
    while ((4 << c) <= size) ++c;  // [2^(c+1), 2^(c+2))
    ASSERT_LT(c, static_cast<int>(perClass.size()));
    ++perClass[c];
  }
  EXPECT_EQ(perClass, f.bundles.bundlesInClass);
  EXPECT_EQ(f.contactPairs, pairs);
  EXPECT_GT(pairs, 0);
  EXPECT_NEAR(f.contactsPerElement, 2.0 * pairs / s.bodies.size(), 1e-12);
  EXPECT_NEAR(f.lambda1 + f.lambda2, 1.0, 1e-12);
  // The JSON report is written (atomically: no temporary left behind).
  const std::string path = (std::filesystem::temp_directory_path() / "mdem-film-report.json").string();
  writeFilmStatisticsJson(f, path);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"density_g_per_cm3\""), std::string::npos);
  EXPECT_NE(text.find("\"bundle_size_distribution\""), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(MdemDeposition, SameSeedGivesTheSameFilmBitForBit) {
  DepositionSpec d = film(30, 15, 80.0, 21);
  d.waviness = 5.0 * kDeg;
  const Scene a = deposit(d), b = deposit(d);
  d.seed = 22;
  const Scene c = deposit(d);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  bool differs = false;
  for (int i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies.position[i], b.bodies.position[i]);
    EXPECT_EQ(a.bodies.orientation[i].w, b.bodies.orientation[i].w);
    EXPECT_EQ(a.bodies.orientation[i].z, b.bodies.orientation[i].z);
    differs |= (a.bodies.position[i] - c.bodies.position[i]).norm() > 1e-6;
  }
  EXPECT_TRUE(differs);
}

TEST(MdemDeposition, OrientationTensorOfAlignedAndIsotropicFilms) {
  DepositionSpec iso = film(200, 10, 150.0, 8);
  const FilmStatistics fi = filmStatistics(deposit(iso));
  EXPECT_LT(fi.orderParameter, 0.3);  // 200 random directions: S ~ 0.06 (Rayleigh), 0.3 is far out
  DepositionSpec al = iso;
  al.alignedFraction = 1.0, al.alignmentAngle = 0.5 * units::kPi, al.alignmentSpread = 10.0 * kDeg;
  const FilmStatistics fa = filmStatistics(deposit(al));
  // Headings normal about y with sigma: S = <cos 2 delta> = exp(-2 sigma^2) = 0.941 (draping
  // tilts elements out of the plane but keeps their in-plane direction).
  EXPECT_NEAR(fa.orderParameter, std::exp(-2.0 * std::pow(10.0 * kDeg, 2)), 0.03);
  EXPECT_NEAR(fa.directorAngleDeg, 90.0, 3.0);
  al.alignmentSpread = 0.0, al.alignmentAngle = 0.0;
  const FilmStatistics fx = filmStatistics(deposit(al));
  EXPECT_GT(fx.orderParameter, 1.0 - 1e-9);
  EXPECT_LT(std::min(fx.directorAngleDeg, 180.0 - fx.directorAngleDeg), 1e-3);
  // Half aligned: S = 1/2 (aligned) + 1/2 x 0 (isotropic), within the isotropic half's noise.
  al.alignedFraction = 0.5;
  EXPECT_NEAR(filmStatistics(deposit(al)).orderParameter, 0.5, 0.12);
}

TEST(MdemDeposition, CutModeKeepsTheInsideAndSplitsTubes) {
  DepositionSpec d = film(0, 30, 0.0, 5);
  d.sizeX = 120.0, d.sizeY = 40.0;
  d.boundary = FilmBoundary::Cut;
  d.sheetX = 200.0, d.sheetY = 110.0;
  d.tubes = 150;
  DepositionResult r;
  const Scene s = deposit(d, &r);
  EXPECT_EQ(r.elementsLaid, 150 * 30);
  EXPECT_LT(s.bodies.size(), r.elementsLaid);
  for (const Vec3& x : s.bodies.position) {
    EXPECT_GE(x.x(), 0.0);
    EXPECT_LE(x.x(), 120.0);
    EXPECT_GE(x.y(), 0.0);
    EXPECT_LE(x.y(), 40.0);
  }
  EXPECT_NO_THROW(checkNoOverlapsCellList(s, kGap - 1e-9, 3));
  // (Pieces may hang off supports that were cut away: no resting check here.)
  // Pieces shorter than a tube end at the specimen's edge (within one element of it).
  const FilamentTopology topo = buildTopology(s.bodies.size(), s.bonds, 0, {});
  int shorter = 0;
  std::vector<int> firstOf(topo.filamentSize.size(), -1), lastOf(topo.filamentSize.size(), -1);
  for (int i = 0; i < s.bodies.size(); ++i) {
    if (firstOf[topo.filament[i]] < 0) firstOf[topo.filament[i]] = i;
    lastOf[topo.filament[i]] = i;
  }
  auto nearEdge = [&](int i) {
    const Vec3& x = s.bodies.position[i];
    return std::min({x.x(), 120.0 - x.x(), x.y(), 40.0 - x.y()}) < kSegmentLength;
  };
  for (std::size_t f = 0; f < topo.filamentSize.size(); ++f) {
    if (topo.filamentSize[f] == 30) continue;
    ++shorter;
    EXPECT_TRUE(nearEdge(firstOf[f]) || nearEdge(lastOf[f])) << "piece " << f;
  }
  EXPECT_GT(shorter, 10);
  EXPECT_EQ(r.filaments, static_cast<int>(topo.filamentSize.size()));
}

BondEnergy bondEnergy(const Scene& s) {
  BondEnergy e;
  for (const Bond& b : s.bonds)
    e += evaluateBond(b, s.bodies.position[b.a], s.bodies.orientation[b.a], s.bodies.position[b.b], s.bodies.orientation[b.b]).energy;
  return e;
}

TEST(MdemDeposition, StraightRestStateStoresTheBendingOfTheDrape) {
  // One tube on an empty film: straight and flat, no energy.
  const BondEnergy single = bondEnergy(deposit(film(1, 25, 100.0, 2)));
  EXPECT_LT(std::abs(single.total()), 1e-12);
  // A crowded film: draped tubes store bending only, 1/2 k_n I theta^2 per bond with theta the
  // angle between consecutive axes (k_n = Y / L, I = pi R^4 / 4).
  const Scene s = deposit(film(60, 25, 60.0, 2));
  const BondEnergy e = bondEnergy(s);
  double expected = 0.0;
  for (const Bond& b : s.bonds) {
    const double theta = std::acos(std::clamp(axisOf(s, b.a).dot(axisOf(s, b.b)), -1.0, 1.0));
    expected += 0.5 * (1e6 / kSegmentLength) * (units::kPi * std::pow(kTubeRadius, 4) / 4.0) * theta * theta;
  }
  EXPECT_GT(e.bending, 1.0);
  EXPECT_NEAR(e.bending, expected, 1e-6 * expected);
  EXPECT_LT(std::abs(e.stretching) + std::abs(e.shearing) + std::abs(e.twisting), 1e-9 * e.bending);
  // As laid: the same film at rest.
  DepositionSpec laid = film(60, 25, 60.0, 2);
  laid.restShape = RestShape::AsLaid;
  const Scene l = deposit(laid);
  EXPECT_EQ(l.bodies.position, s.bodies.position);
  EXPECT_LT(std::abs(bondEnergy(l).total()), 1e-9);
}

TEST(MdemDeposition, ThicknessTargetStopsTheDeposition) {
  DepositionSpec d = film(0, 20, 80.0, 6);
  d.thickness = 6.0;
  DepositionResult r;
  const Scene s = deposit(d, &r);
  const FilmStatistics f = filmStatistics(s);
  EXPECT_GE(f.thickness, 6.0);
  EXPECT_NEAR(f.thickness, r.domainThickness, 1e-12);
  // One tube less would not have reached it: the same seed with tubesLaid - 1 tubes.
  DepositionSpec fewer = film(r.tubesLaid - 1, 20, 80.0, 6);
  EXPECT_LT(filmStatistics(deposit(fewer)).thickness, 6.0);
}

TEST(MdemDeposition, CellListCheckFindsATubeMeetingItsOwnImage) {
  Scene s = tubeScene({"bonds"});
  addTube(s, 10, Vec3(1.0, 5.0, 0.0), Vec3::UnitX());  // centres 1..19, ends at 0 and 20
  s.periodic.periodic = {true, false, false};
  s.periodic.length = Vec3(21.0, 0.0, 0.0);  // the last end is 1 nm from the first one's image
  EXPECT_NO_THROW(checkNoOverlaps(s, kGap));  // the O(n^2) check sees different tubes only
  try {
    checkNoOverlapsCellList(s, kGap, 3);
    ADD_FAILURE() << "no overlap found";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("elements 0 and 9"), std::string::npos) << e.what();
  }
  s.periodic.length.x() = 23.0;  // 3 nm of box between the ends: gap 3 - 2R > 0.3
  EXPECT_NO_THROW(checkNoOverlapsCellList(s, kGap, 3));
}

std::string writeScene(const std::string& name, const std::string& networkKeys, const std::string& extra = "") {
  const std::string path = (std::filesystem::temp_directory_path() / ("mdem-deposition-" + name + ".toml")).string();
  std::ofstream(path) << R"(format = 1
effects = ["bonds"]
)" + std::string(testing::kTubeModelToml) + R"([network]
method = "deposition"
element_type = "cnt1010"
bond_type = "cnt"
tube_length_nm = 20.0
)" + networkKeys + R"(
[run]
time_step_fraction = 0.5
steps = 1
)" + extra;
  return path;
}

TEST(MdemDeposition, SceneTableGeneratesTheFilmAndSetsThePeriodicBox) {
  const Scene s = loadScene(writeScene("same", "size_nm = [80.0, 80.0]\ntubes = 30\nseed = 21\nshape = \"wavy\"\nwaviness_deg = 5.0"));
  DepositionSpec d = film(30, 10, 80.0, 21);
  d.waviness = 5.0 * kDeg;
  const Scene direct = deposit(d);
  ASSERT_EQ(s.bodies.size(), direct.bodies.size());
  for (int i = 0; i < s.bodies.size(); ++i) EXPECT_EQ(s.bodies.position[i], direct.bodies.position[i]);
  EXPECT_TRUE(s.periodic.periodic[0] && s.periodic.periodic[1] && !s.periodic.periodic[2]);
  EXPECT_EQ(s.periodic.length.x(), 80.0);
  // 0.1 g/cm^3 over 80 x 80 x 50 nm = 3.2e5 nm^3 x 1e-4 ag/nm^3 = 32 ag = 493.6 tubes of
  // 10 x 0.0064823 ag -> 494 (thickness_nm is then a limit the film stays below).
  const Scene dense = loadScene(writeScene("density", "size_nm = [80.0, 80.0]\ndensity_g_per_cm3 = 0.1\nthickness_nm = 50.0"));
  EXPECT_EQ(dense.bodies.size(), 494 * 10);
  // The same [periodic] box is accepted.
  EXPECT_NO_THROW(loadScene(writeScene("box", "size_nm = [80.0, 80.0]\ntubes = 3", "[periodic]\nlength_nm = [80.0, 80.0, 0.0]\n")));
}

TEST(MdemDeposition, BadRequestsAreClearErrorsNamingTheKey) {
  auto expectError = [](const std::string& keys, const char* key, const std::string& extra = "") {
    try {
      loadScene(writeScene("bad", keys, extra));
      ADD_FAILURE() << "no error for " << keys;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  expectError("size_nm = [21.0, 80.0]\ntubes = 3", "tube_length_nm");   // longer than the box allows
  expectError("size_nm = [40.0, 40.0]\ntubes = 400\nthickness_nm = 3.0", "network.tubes");  // not within 3 nm
  expectError("size_nm = [40.0, 40.0]\ndensity_g_per_cm3 = 0.5\nthickness_nm = 3.0", "density_g_per_cm3");
  expectError("size_nm = [40.0, 40.0]\ndensity_g_per_cm3 = 0.5", "density_g_per_cm3");  // no thickness
  expectError("size_nm = [40.0, 40.0]\nthickness_nm = 1.0", "thickness_nm");  // below one tube diameter
  expectError("size_nm = [40.0, 40.0, 3.0]\ntubes = 3", "size_nm");
  expectError("size_nm = [40.0, 40.0]", "tubes");  // no stop
  expectError("size_nm = [40.0, 40.0]\ntubes = 3\nmethod = \"spray\"", "method");
  expectError("size_nm = [40.0, 40.0]\ntubes = 3\nboundary = \"cut\"\nsheet_size_nm = [50.0, 50.0]", "sheet_size_nm");
  expectError("size_nm = [40.0, 40.0]\ntubes = 3", "periodic.length_nm", "[periodic]\nlength_nm = [50.0, 40.0, 0.0]\n");
  expectError("size_nm = [40.0, 40.0]\ntubes = 3\nalignment_axis = \"y\"", "alignment_axis");  // no aligned fraction
  expectError("size_nm = [40.0, 40.0]\ntubes = 3\nrest_shape = \"bent\"", "rest_shape");
  expectError("size_nm = [40.0, 40.0]\ntubes = 3\nwaviness_deg = 4.0", "waviness_deg");
}

}  // namespace
}  // namespace mesochain::mdem
