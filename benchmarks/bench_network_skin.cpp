#include "benchmarks/bench_network_skin.hpp"

#include <cmath>
#include <cstring>
#include <iostream>
#include <memory>

#include <fmt/format.h>
#include <omp.h>

#include "benchmarks/bench_network_mts.hpp"
#include "mdem/contacts/contact_effects.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::app {

namespace {
mdem::Scene withSkin(mdem::Scene s, double skin) {
  s.contacts.skin = skin;
  return s;
}

long listBuilds(const mdem::Simulation& sim) {
  const mdem::ContactNeighbourhood* nb = sim.contactNeighbourhood();
  return nb ? nb->list().builds() : 0;
}

// True when the positions, orientations, velocities and angular momenta of the two simulations are the same bits.
bool sameState(const mdem::Simulation& a, const mdem::Simulation& b) {
  const mdem::Bodies &x = a.state().bodies, &y = b.state().bodies;
  for (int i = 0; i < x.size(); ++i) {
    if (std::memcmp(x.position[i].data(), y.position[i].data(), sizeof(double) * 3) != 0) return false;
    if (std::memcmp(x.velocity[i].data(), y.velocity[i].data(), sizeof(double) * 3) != 0) return false;
    if (std::memcmp(&x.orientation[i], &y.orientation[i], sizeof(x.orientation[i])) != 0) return false;
    if (std::memcmp(x.angularMomentumBody[i].data(), y.angularMomentumBody[i].data(), sizeof(double) * 3) != 0) return false;
  }
  return true;
}
}  // namespace

int printSkinCurve(const mdem::Scene& scene, const std::vector<double>& skins, double seconds, int threads,
                   long checkSteps) {
  omp_set_num_threads(threads);
  std::cout << fmt::format("Verlet skin of the contacts' neighbour list: {} elements, {} thread(s), {:.3g} s per skin; "
                           "trajectories compared after {} steps\n",
                           scene.bodies.size(), threads, seconds, checkSteps);
  std::cout << "skin (nm)  listed pairs/element  builds/1000 steps  element-steps/s  neighbour search  same bits\n";
  int status = 0;
  std::unique_ptr<mdem::Simulation> first;
  for (double skin : skins) {
    const mdem::Scene s = withSkin(scene, skin);
    // Results: `checkSteps` steps from the scene's state, against the first skin's.
    auto check = std::make_unique<mdem::Simulation>(s);
    check->run(checkSteps);
    const bool same = !first || sameState(*first, *check);
    if (!same) status = 1;
    if (!first) first = std::move(check);
    // Time: an unprofiled pass for the rate, then a profiled one for the neighbour search's share
    // (the list's displacement test and its builds, in the contact effects' prepare).
    mdem::Simulation sim(s);
    sim.run(8);
    const long builds0 = listBuilds(sim);
    const auto [steps, elapsed] = timedSteps(sim, seconds, 0, 8);
    const double rate = static_cast<double>(steps) * s.bodies.size() / elapsed;
    const long builds = listBuilds(sim) - builds0;
    mdem::PhaseTimes phases;
    sim.setProfile(&phases);
    const double profiled = timedSteps(sim, seconds, steps / 2, 8).second;
    sim.setProfile(nullptr);
    const double share = (phases["prepare vdw_contact"] + phases["prepare contact_damping"]) / profiled;
    const mdem::ContactNeighbourhood* nb = sim.contactNeighbourhood();
    const double pairs = nb ? static_cast<double>(nb->list().pairs().size()) / s.bodies.size() : 0.0;
    std::cout << fmt::format("{:9.3g}  {:20.3f}  {:17.2f}  {:15.4g}  {:15.1f}%  {}\n", skin, pairs,
                             1000.0 * builds / std::max(1L, steps), rate, 100.0 * share, same ? "yes" : "NO")
              << std::flush;
  }
  if (status != 0) std::cout << "a skin changed the trajectory: the list's reach must not change results\n";
  return status;
}

}  // namespace mesochain::app
