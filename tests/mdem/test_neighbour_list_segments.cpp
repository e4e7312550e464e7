// The contacts' neighbour list by axis segments (NeighbourList's axisRange): against brute force
// (periodic, exclusions, moves within the skin, rebuilds), and the pairs it leaves out of the
// centre-distance list contribute exactly zero to the van der Waals contact and the dashpots, so
// the trajectories do not depend on which of the two lists is used.
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "contact_fixture.hpp"
#include "mdem/contacts/contact_effects.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

// Distance of the closest points of the axis segments of i and j (j at the minimum image).
double segmentDistance(const Scene& s, const Bodies& b, int i, int j) {
  const double l = 0.5 * s.elementTypes[0].length;
  const Segment si{b.position[i], rotate(b.orientation[i], Vec3::UnitZ()), l};
  const Segment sj{b.position[i] + s.periodic.minimumImage(b.position[j] - b.position[i]),
                   rotate(b.orientation[j], Vec3::UnitZ()), l};
  double a, u;
  closestPoints(si, sj, &a, &u);
  return (si.centre + a * si.axis - sj.centre - u * sj.axis).norm();
}

// Random short filaments of 3 elements in a box periodic along x and z.
Scene randomSegments(int filaments, unsigned seed) {
  Scene s = tubeScene({"vdw_contact", "contact_damping"});
  s.periodic.periodic = {true, false, true};
  s.periodic.length = Vec3(14.0, 0.0, 11.0);
  s.contacts.excludeWithin = 1;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int f = 0; f < filaments; ++f) {
    const Vec3 start(14.0 * u(gen), 20.0 * u(gen), 11.0 * u(gen));
    addTube(s, 3, start, Vec3(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5));
  }
  return s;
}

TEST(MdemNeighbourListSegments, HoldsEveryPairWithinTheAxisRange) {
  Scene s = randomSegments(40, 11);
  const double centre = VdwContactEffect::interactionRange(s);
  const double axis = std::max(VdwContactEffect::axisRange(s), ContactDampingEffect::axisRange(s));
  ASSERT_TRUE(std::isfinite(axis));
  EXPECT_NEAR(axis, 2 * kTubeRadius + 1.2 + 3 * TubePairPotential::kDefaultGridStep, 1e-12);
  ContactNeighbourhood bySegments(s, centre, axis), byCentres(s, centre);
  const double skin = s.contacts.skin;
  auto check = [&](const Bodies& b, double slack) {
    const auto& listed = bySegments.list().pairs();
    const std::set<std::pair<int, int>> in(listed.begin(), listed.end());
    int expected = 0;
    for (int i = 0; i < b.size(); ++i)
      for (int j = i + 1; j < b.size(); ++j) {
        const bool excluded = i / 3 == j / 3 && std::abs(i - j) <= 1;
        if (excluded) {
          EXPECT_FALSE(in.count({i, j}));
          continue;
        }
        const double d = segmentDistance(s, b, i, j);
        if (d < axis) {
          ++expected;
          EXPECT_TRUE(in.count({i, j})) << i << " " << j << " segment distance " << d;
        }
      }
    for (const auto& [i, j] : listed) EXPECT_LT(segmentDistance(s, b, i, j), axis + skin + slack);
    return expected;
  };
  EXPECT_GT(check(s.bodies, 1e-9), 20);
  // The segment list is the centre list less pairs whose axes are far apart: a strict subset here.
  const std::set<std::pair<int, int>> centres(byCentres.list().pairs().begin(), byCentres.list().pairs().end());
  for (const auto& p : bySegments.list().pairs()) EXPECT_TRUE(centres.count(p));
  EXPECT_LT(bySegments.list().pairs().size(), centres.size());

  // Turn and move every element so that each end moves by less than skin/2: no rebuild, and the
  // list still holds every pair now within the axis range.
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Bodies moved = s.bodies;
  for (int i = 0; i < moved.size(); ++i) {
    const Vec3 axisOfTurn = Vec3(u(gen), u(gen), u(gen)).normalized();
    const double angle = 0.06;  // rad: the ends move by about 0.06 nm from the turn
    moved.orientation[i] = normalized(axisAngle(axisOfTurn, angle) * moved.orientation[i]);
    moved.position[i] += 0.07 * Vec3(u(gen), u(gen), u(gen)).normalized();
  }
  const long builds = bySegments.list().builds();
  bySegments.update(moved);
  EXPECT_EQ(bySegments.list().builds(), builds);
  check(moved, 0.3);
  // A larger move rebuilds.
  for (int i = 0; i < moved.size(); ++i) moved.position[i] += Vec3(0.5, 0.0, -0.4);
  bySegments.update(moved);
  EXPECT_EQ(bySegments.list().builds(), builds + 1);
  check(moved, 1e-9);
}

TEST(MdemNeighbourListSegments, PairsLeftOutContributeExactlyZero) {
  // A damped random network after some steps (moving, with contacts at every distance); every
  // pair of the centre-distance list that the segment list leaves out has zero vdW energy, force
  // and torque and a zero dashpot, exactly.
  Scene scene = dampedNetworkScene();
  Simulation sim(scene);
  sim.run(300);
  const Bodies& b = sim.state().bodies;
  const auto* vdw = dynamic_cast<const VdwContactEffect*>(sim.effect("vdw_contact"));
  ASSERT_NE(vdw, nullptr);
  const ContactNeighbourhood& used = vdw->neighbourhood();
  EXPECT_TRUE(std::isfinite(used.list().axisRange()));
  Scene now = scene;
  now.bodies = b;
  ContactNeighbourhood byCentres(now, VdwContactEffect::interactionRange(now));
  const std::set<std::pair<int, int>> listed(used.list().pairs().begin(), used.list().pairs().end());
  int left = 0, zeroVdw = 0, zeroDashpot = 0, nonzeroListed = 0;
  for (const auto& [i, j] : byCentres.list().pairs()) {
    if (listed.count({i, j})) {
      nonzeroListed += vdw->evaluatePair(b, i, j).energy != 0.0;
      continue;
    }
    ++left;
    const ContactPairResult r = vdw->evaluatePair(b, i, j);
    zeroVdw += r.energy == 0.0 && r.forceA.isZero(0.0) && r.forceB.isZero(0.0) && r.torqueA.isZero(0.0) &&
               r.torqueB.isZero(0.0);
    const Segment si = used.segment(b, i), sj = used.imageNear(b, j, si.centre);
    const ContactPairResult d = contactDashpot(now.contacts.damping, si, sj, used.radius(b.type[i]), used.radius(b.type[j]),
                                               b.velocity[i] + Vec3(1, 2, 3), b.angularVelocityWorld(i) + Vec3(3, 1, 2),
                                               b.velocity[j], b.angularVelocityWorld(j));
    zeroDashpot += d.forceA.isZero(0.0) && d.torqueA.isZero(0.0) && d.torqueB.isZero(0.0);
  }
  EXPECT_GT(left, static_cast<int>(byCentres.list().pairs().size()) / 3);  // the list is much shorter
  EXPECT_GT(nonzeroListed, 50);                                              // and there are contacts
  EXPECT_EQ(zeroVdw, left);
  EXPECT_EQ(zeroDashpot, left);
}

}  // namespace
}  // namespace mesochain::mdem
