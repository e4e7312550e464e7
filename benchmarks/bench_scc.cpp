// `mesochain-bench scc`: SCC iterations and time per iteration on benchmark cells, Broyden
// against simple mixing, and the objective cell against the same structure written out.
// Cells: a cyclic C_N H_N ring (N = 60, C-C 1.40 Å, C-H 1.09 Å, slightly puckered so that the
// charges are not fixed by symmetry alone) as one CH unit + C_60, and as 120 explicit atoms.
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#include "app/cli/command.hpp"
#include "benchmarks/default_parameters.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "dftb/calculator.hpp"
#include "objective/drivers/relax.hpp"

namespace mesochain::app {

namespace {
using Clock = std::chrono::steady_clock;

objective::ObjectiveCell chRing(int n) {
  const double a = units::kAngstromInBohr;
  const double rc = 1.40 * a / (2 * std::sin(units::kPi / n));
  objective::ObjectiveCell cell;
  cell.symmetry = objective::Symmetry::ring(n);
  cell.addAtom("C", {rc, 0.0, 0.05 * a});
  cell.addAtom("H", {(rc + 1.09 * a) * std::cos(0.03), (rc + 1.09 * a) * std::sin(0.03), -0.1 * a});
  return cell;
}

objective::ObjectiveCell explicitRing(const objective::ObjectiveCell& unit) {
  objective::ObjectiveCell out;
  for (int c = 0; c < unit.symmetry.rotationOrder(); ++c)
    for (int i = 0; i < unit.atomCount(); ++i)
      out.addAtom(unit.speciesOf(i),
                  unit.symmetry.apply(objective::GroupElement{0, c}, unit.positions.col(i)));
  return out;
}

int benchScc(const std::string& params, int repeats) {
  const std::string dir = params + "/";
  auto p = std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      {"C", "H"},
      {{"C-C", dir + "C-C.skf"}, {"C-H", dir + "C-H.skf"}, {"H-C", dir + "H-C.skf"},
       {"H-H", dir + "H-H.skf"}},
      "<bench>"));
  std::cout << fmt::format("mesochain-bench scc: {} OpenMP threads, {} repeats, tables {}\n",
                           omp_get_max_threads(), repeats, params);
  std::cout << fmt::format("{:<34} {:<8} {:>6} {:>11} {:>12} {:>11} {:>9} {:>16}\n", "cell",
                           "mixer", "iter", "s/iter", "s/eval", "non-SCC s", "ratio",
                           "F per atom (Ha)");
  const auto unit = chRing(60);
  const auto molecule = explicitRing(unit);
  for (const auto* cell : {&unit, &molecule}) {
    const std::string name = cell == &unit ? "C60H60 ring: CH + C_60 (2 atoms)"
                                           : "C60H60 ring: explicit (120 atoms)";
    dftb::CalculatorSettings s;
    s.band.electronicTemperature = 300 * units::kBoltzmannHartreePerKelvin;
    const dftb::Calculator plain(p, s);
    double tPlain = 0;
    for (int r = 0; r < repeats; ++r) {
      const auto a = Clock::now();
      plain.evaluate(*cell, {true, false});
      tPlain += std::chrono::duration<double>(Clock::now() - a).count() / repeats;
    }
    for (const char* mixer : {"broyden", "simple"}) {
      s.scc.enabled = true;
      s.scc.mixer = mixer;
      s.scc.mixing = 0.2;
      s.scc.chargeTolerance = 1e-8;
      s.scc.maxIterations = 500;
      const dftb::Calculator calc(p, s);
      double t = 0, perIteration = 0;
      dftb::Result res;
      try {
        for (int r = 0; r < repeats; ++r) {
          calc.chargeCache().clear();  // every repeat starts from neutral atoms
          const auto a = Clock::now();
          res = calc.evaluate(*cell, {true, false});
          t += std::chrono::duration<double>(Clock::now() - a).count() / repeats;
          perIteration += res.extras.at("time_per_scc_iteration") / repeats;
        }
      } catch (const NumericalError& e) {
        const std::string m = e.what();
        std::cout << fmt::format("{:<34} {:<8} FAILED: {}\n", name, mixer, m.substr(0, m.find('(')));
        continue;
      }
      std::cout << fmt::format("{:<34} {:<8} {:>6} {:>11.5f} {:>12.5f} {:>11.5f} {:>9.1f} {:>16.10f}\n",
                               name, mixer, static_cast<int>(res.extras.at("scc_iterations")),
                               perIteration, t, tPlain, t / tPlain,
                               res.freeEnergy / cell->atomCount());
    }
  }
  std::cout << "s/iter: one band solve with Mulliken charges; ratio: SCC evaluation (energy and "
               "forces) over the non-SCC one\n";

  // Warm start across the evaluations of a relaxation (L-BFGS, forces < 1e-4 Ha/Bohr) of the
  // puckered C60H60 ring unit (2 atoms + C_60): every loop from neutral atoms, or from the
  // charges of the previous evaluation.
  std::cout << fmt::format("\n{:<34} {:>6} {:>11} {:>10} {:>8} {:>18}\n", "relaxation, C60H60 ring unit",
                           "evals", "SCC iter", "iter/eval", "time s", "F per atom (Ha)");
  for (bool warm : {false, true}) {
    dftb::CalculatorSettings s;
    s.band.electronicTemperature = 300 * units::kBoltzmannHartreePerKelvin;
    s.scc.enabled = true;
    s.scc.chargeTolerance = 1e-8;
    s.scc.warmStart = warm;
    const dftb::Calculator calc(p, s);
    objective::RelaxSettings rs;
    rs.forceTolerance = 1e-4;
    const auto a = Clock::now();
    const auto out = objective::relax(calc, unit, rs);
    const double t = std::chrono::duration<double>(Clock::now() - a).count();
    const long it = calc.chargeCache().iterations();
    std::cout << fmt::format("{:<34} {:>6} {:>11} {:>10.2f} {:>8.3f} {:>18.12f}\n",
                             warm ? "warm start" : "from neutral atoms", out.evaluations, it,
                             static_cast<double>(it) / out.evaluations, t,
                             out.result.freeEnergy / unit.atomCount());
  }
  return 0;
}
}  // namespace

Command makeBenchSccCommand() {
  struct Opts {
    std::string params = defaultParameterSetFolder();
    int repeats = 2;
  };
  auto o = std::make_shared<Opts>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [o, sub](CLI::App& bench) {
    auto* s = bench.add_subcommand("scc", "SCC iterations and time per iteration");
    s->add_option("--params", o->params, "folder with C-C, C-H, H-C, H-H tables");
    s->add_option("--repeats", o->repeats, "evaluations to average");
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [o] { return benchScc(o->params, o->repeats); };
  return c;
}

}  // namespace mesochain::app
