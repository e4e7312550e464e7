// `mesochain build cnt N M [options]`: writes an objective-cell file of an (n,m) nanotube, as its
// minimal helical cell (2 atoms + screw + C_gcd(n,m)) or its translational cell.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/commands.hpp"
#include "common/units.hpp"
#include "objective/core/cell_file.hpp"
#include "objective/core/nanotube_builder.hpp"

namespace mesochain::app {

namespace {
struct BuildOptions {
  int n = 0, m = 0;
  std::string cell = "helical";
  double bond = objective::kDefaultBondLengthAngstrom;
  int kpoints = 0;  // 0: chosen from the cell length
  double kelvin = 300.0;
  std::string set = "pbc-0-3";
  std::string task = "relax";
  std::string output;
};

int build(const BuildOptions& o) {
  objective::CellInput in;
  const double bond = o.bond * units::kAngstromInBohr;
  in.cell = o.cell == "helical" ? objective::buildNanotubeHelical(o.n, o.m, bond)
                                : objective::buildNanotubeTranslational(o.n, o.m, bond, false);
  in.source = o.output;
  // Unless asked otherwise: kappa points that sample a 300 Å length of tube (N T = 300 Å),
  // which converges metallic tubes at 300 K to about 1e-8 Ha/atom (mesochain bench kpoints).
  in.helicalKPoints =
      o.kpoints > 0 ? o.kpoints
                    : std::max(8, static_cast<int>(std::ceil(300.0 * units::kAngstromInBohr /
                                                             in.cell.symmetry.translation())));
  in.electronicTemperature = o.kelvin * units::kBoltzmannHartreePerKelvin;
  in.parameterSet = o.set;
  in.parameterFiles = objective::parameterSetFiles(o.set, in.cell.speciesNames, "<command line>", "--set");
  in.task.type = o.task;
  in.task.relaxTranslation = o.task == "relax";
  const std::string path = o.output.empty() ? fmt::format("cnt{}{}.toml", o.n, o.m) : o.output;
  objective::writeCellFile(path, in);
  std::cout << fmt::format("wrote {}: ({},{}) {} cell, {} atoms, T = {:.6f} Å, twist = {:.6f}°, "
                           "rotation order {}, {} kappa points\n",
                           path, o.n, o.m, o.cell, in.cell.atomCount(),
                           in.cell.symmetry.translation() * units::kBohrInAngstrom,
                           in.cell.symmetry.twist() / units::kDegree,
                           in.cell.symmetry.rotationOrder(), in.helicalKPoints);
  return 0;
}
}  // namespace

Command makeBuildCommand() {
  auto o = std::make_shared<BuildOptions>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [o, sub](CLI::App& app) {
    auto* b = app.add_subcommand("build", "write an objective-cell file of a structure");
    b->require_subcommand(1);
    auto* s = b->add_subcommand("cnt", "an (n,m) carbon nanotube");
    s->add_option("n", o->n, "chiral index n")->required();
    s->add_option("m", o->m, "chiral index m")->required();
    s->add_option("--cell", o->cell, "helical (2 atoms + symmetry) or translational")
        ->check(CLI::IsMember({"helical", "translational"}));
    s->add_option("--bond", o->bond, "C-C bond length of the roll-up, Å");
    s->add_option("--kpoints", o->kpoints, "helical k-points (default: from the cell length)");
    s->add_option("--temperature", o->kelvin, "electronic temperature, K");
    s->add_option("--set", o->set, "parameter set folder under params/");
    s->add_option("--task", o->task, "energy | forces | relax")
        ->check(CLI::IsMember({"energy", "forces", "relax"}));
    s->add_option("-o,--output", o->output, "cell file to write (default cntNM.toml)");
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [o] { return build(*o); };
  return c;
}

}  // namespace mesochain::app
