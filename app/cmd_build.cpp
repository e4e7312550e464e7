// `mesochain build cnt N M | multiwall N,M N,M ... | graphene-ring LAYERS [options]`: writes an
// objective-cell file (docs/cell-file.md) of an (n,m) nanotube (its minimal helical cell or its
// translational cell), of concentric walls sharing one translational period, or of a bent
// AB-stacked graphene stack (one sector of a ring); atoms inline, symmetry, k-points, task.
#include <algorithm>
#include <charconv>
#include <optional>
#include <utility>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/build_tube_sector.hpp"
#include "app/cli_checks.hpp"
#include "app/commands.hpp"
#include "common/electronic_temperature.hpp"
#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/cell_file.hpp"
#include "objective/core/graphene_builder.hpp"
#include "objective/core/nanotube_builder.hpp"

namespace mesochain::app {

namespace {
// Options every structure shares.
struct CommonOptions {
  double bond = objective::kDefaultBondLengthAngstrom;
  int kpoints = 0;  // 0: chosen from the cell length
  double kelvin = 300.0;
  std::string set = "pbc-0-3";
  std::string task = "relax";
  std::string output;
};

struct CntOptions {
  int n = 0, m = 0;
  std::string cell = "helical";
};

struct MultiWallOptions {
  std::vector<std::string> walls;  // "n,m"
};

struct RingOptions {
  int layers = 0;
  std::string direction;
  std::string chiral;  // "n,m" with direction = chiral
  int rotationOrder = 0;
  int cellsAlongArc = 1;
  double interlayer = 3.35;  // Å
};

void addCommonOptions(CLI::App* s, CommonOptions& o, const std::string& defaultName) {
  s->add_option("--bond", o.bond, "C-C bond length of the flat sheet, Å")->check(finiteNumber(false));
  s->add_option("--kpoints", o.kpoints, "helical k-points (default: from the cell length)")
      ->check(integerIn(1, 1000000, "the limit of [kpoints] helical"));
  s->add_option("--temperature", o.kelvin, "electronic temperature, K")->check(finiteNumber(false));
  s->add_option("--parameter-set", o.set, "parameter set: a folder under params/ (docs/cell-file.md, [parameters] set)");
  s->add_option("--task", o.task, "energy | forces | relax")
      ->check(CLI::IsMember({"energy", "forces", "relax"}));
  s->add_option("-o,--output", o.output, "cell file to write (default " + defaultName + "; - for the standard output)")
      ->check(nonEmptyPath());
}

// "n,m" -> (n, m) with 1 <= n <= 10000 and 0 <= m <= 10000 (the limits of the cell file's
// builder); nullopt when the text is not two integers in range (read as 64-bit, no wrapping).
std::optional<std::pair<int, int>> chiralPair(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  long long n = 0, m = 0;
  const char* end = text.data() + text.size();
  const auto a = std::from_chars(text.data(), text.data() + comma, n);
  const auto b = std::from_chars(text.data() + comma + 1, end, m);
  if (a.ec != std::errc() || a.ptr != text.data() + comma || b.ec != std::errc() || b.ptr != end)
    return std::nullopt;
  if (n < 1 || n > 10000 || m < 0 || m > 10000) return std::nullopt;
  return std::make_pair(static_cast<int>(n), static_cast<int>(m));
}

// Completes the cell input around `cell` and writes it; `what` describes the structure.
int writeBuilt(objective::ObjectiveCell cell, const CommonOptions& o, const std::string& defaultPath,
               const std::string& what) {
  objective::CellInput in;
  in.cell = std::move(cell);
  const std::string path = o.output.empty() ? defaultPath : o.output;
  in.source = path;
  const std::string cl = "<command line>";
  requireElectronicTemperature(o.kelvin * units::kBoltzmannHartreePerKelvin, cl,
                               "option --temperature");
  // A built structure passes the check of a read one (--bond too short, walls too close).
  in.cell.validate(cl + " (the structure built from the options)",
                   objective::kMinimumAtomDistanceAngstrom * units::kAngstromInBohr);
  requireWritableOutput(path, cl, "option --output");
  // Unless asked otherwise: kappa points that sample a 300 Å length of tube (N T = 300 Å),
  // which converges metallic tubes at 300 K to about 1e-8 Ha/atom (mesochain bench kpoints).
  const double t = in.cell.symmetry.translation();
  in.band.helicalKPoints = o.kpoints > 0 ? o.kpoints
                      : t > 0 ? std::max(8, static_cast<int>(std::ceil(300.0 * units::kAngstromInBohr / t)))
                              : 1;
  in.band.electronicTemperature = o.kelvin * units::kBoltzmannHartreePerKelvin;
  in.parameterSet = o.set;
  in.parameterFiles = objective::parameterSetFiles(o.set, in.cell.speciesNames, "<command line>", "--parameter-set");
  in.task.type = o.task;
  in.task.relaxTranslation = o.task == "relax" && !in.cell.symmetry.isRing();
  objective::writeCellFile(path, in);
  // With -o - the cell file is the standard output and this line goes to stderr.
  (isStandardOutput(path) ? std::cerr : std::cout) << fmt::format("wrote {}: {}, {} atoms, T = {:.6f} Å, twist = {:.6f}°, "
                           "rotation order {}, {} kappa points\n",
                           path, what, in.cell.atomCount(), t * units::kBohrInAngstrom,
                           in.cell.symmetry.twist() / units::kDegree,
                           in.cell.symmetry.rotationOrder(), in.band.helicalKPoints);
  return 0;
}

int buildCnt(const CntOptions& c, const CommonOptions& o) {
  const double bond = o.bond * units::kAngstromInBohr;
  return writeBuilt(c.cell == "helical" ? objective::buildNanotubeHelical(c.n, c.m, bond)
                                        : objective::buildNanotubeTranslational(c.n, c.m, bond, false),
                    o, fmt::format("cnt{}{}.toml", c.n, c.m), fmt::format("({},{}) {} cell", c.n, c.m, c.cell));
}

std::vector<std::pair<int, int>> parseWalls(const std::vector<std::string>& texts, const std::string& command) {
  std::vector<std::pair<int, int>> walls;
  for (const std::string& s : texts) {
    const auto nm = chiralPair(s);
    if (!nm)
      throw InputError("<command line>", "build " + command + ", wall '" + s + "'", "'" + s + "'",
                       "chiral indices written n,m (e.g. 5,5) with 1 <= n <= 10000, 0 <= m <= 10000");
    walls.push_back(*nm);
  }
  return walls;
}

int buildMultiWall(const MultiWallOptions& w, const CommonOptions& o) {
  std::vector<std::pair<int, int>> walls;
  std::string name = "mw", what;
  for (const auto& [n, m] : parseWalls(w.walls, "multiwall")) {
    walls.emplace_back(n, m);
    name += fmt::format("{}{}-{}", walls.size() > 1 ? "_" : "", n, m);
    what += fmt::format("{}({},{})", walls.size() > 1 ? "@" : "", n, m);
  }
  return writeBuilt(objective::buildMultiWallTranslational(walls, o.bond * units::kAngstromInBohr), o,
                    name + ".toml", what + " translational cell");
}

int buildRing(const RingOptions& r, const CommonOptions& o) {
  objective::ChiralIndices dir = objective::chiralIndices(
      r.direction == "armchair" ? objective::Direction::Armchair : objective::Direction::Zigzag);
  std::string name = r.direction;
  if (r.direction == "chiral") {
    if (r.chiral.empty())
      throw InputError("<command line>", "build graphene-ring --chiral", "nothing",
                       "--chiral n,m with --direction chiral (e.g. 2,1)");
    const auto nm = chiralPair(r.chiral);
    if (!nm)
      throw InputError("<command line>", "build graphene-ring --chiral", "'" + r.chiral + "'",
                       "chiral indices written n,m (e.g. 2,1) with 1 <= n <= 10000, 0 <= m <= 10000");
    dir.n = nm->first;
    dir.m = nm->second;
    name = fmt::format("{}-{}", dir.n, dir.m);
  } else if (!r.chiral.empty()) {
    throw InputError("<command line>", "build graphene-ring --chiral", "'" + r.chiral + "'",
                     "--chiral only with --direction chiral");
  }
  return writeBuilt(objective::buildGrapheneRingSector(r.layers, dir, r.rotationOrder, r.cellsAlongArc,
                                                       r.interlayer * units::kAngstromInBohr,
                                                       o.bond * units::kAngstromInBohr),
                    o, fmt::format("ring{}L-{}-{}.toml", r.layers, name, r.rotationOrder),
                    fmt::format("{}-layer graphene ring sector ({} along the arc, 1/{} of the ring)",
                                r.layers, name, r.rotationOrder));
}
int buildSector(const TubeSectorOptions& t, const CommonOptions& o) {
  const double bond = o.bond * units::kAngstromInBohr;
  BuiltTubeSector b = buildTubeSector(t, parseWalls(t.walls, "tube-sector"), bond);
  return writeBuilt(std::move(b.cell), o, b.fileName, b.what);
}
}  // namespace

Command makeBuildCommand() {
  auto common = std::make_shared<CommonOptions>();
  auto cnt = std::make_shared<CntOptions>();
  auto mw = std::make_shared<MultiWallOptions>();
  auto ring = std::make_shared<RingOptions>();
  auto sector = std::make_shared<TubeSectorOptions>();
  struct Subs {
    CLI::App *cnt = nullptr, *mw = nullptr, *ring = nullptr, *sector = nullptr;
  };
  auto subs = std::make_shared<Subs>();
  Command c;
  c.attach = [=](CLI::App& app) {
    auto* b = app.add_subcommand("build", "write an objective-cell file of a structure");
    b->require_subcommand(1);
    auto* s = b->add_subcommand("cnt", "an (n,m) carbon nanotube");
    s->add_option("n", cnt->n, "chiral index n")->required()->check(integerIn(1, 10000));
    s->add_option("m", cnt->m, "chiral index m")->required()->check(integerIn(0, 10000));
    s->add_option("--cell", cnt->cell, "helical (2 atoms + symmetry) or translational")
        ->check(CLI::IsMember({"helical", "translational"}));
    addCommonOptions(s, *common, "cntNM.toml");
    subs->cnt = s;

    auto* w = b->add_subcommand("multiwall", "concentric nanotube walls sharing one period (translational cell)");
    w->add_option("walls", mw->walls, "chiral indices of the walls, inner first, as n,m (e.g. 5,5 10,10)")
        ->required();
    addCommonOptions(w, *common, "mwN-M_N-M.toml");
    subs->mw = w;

    auto* g = b->add_subcommand("graphene-ring", "AB-stacked graphene layers bent into a ring (one sector)");
    g->add_option("layers", ring->layers, "number of graphene layers")->required()->check(integerIn(1, 1000));
    g->add_option("--direction", ring->direction, "sheet direction along the arc")
        ->required()
        ->check(CLI::IsMember({"armchair", "zigzag", "chiral"}));
    g->add_option("--chiral", ring->chiral, "with --direction chiral: indices n,m of the arc direction (0 <= m <= n)");
    g->add_option("--rotation-order", ring->rotationOrder, "N_a, sectors of the full ring (>= 3)")
        ->required()
        ->check(integerIn(3, 10000000, "as rotation_order of the cell file"));
    g->add_option("--cells-along-arc", ring->cellsAlongArc, "sheet cells (C x T parallelograms) per sector")
        ->check(integerIn(1, 1000));
    g->add_option("--interlayer", ring->interlayer, "layer spacing, Å")->check(finiteNumber(false));
    addCommonOptions(g, *common, "ringLL-DIRECTION-NA.toml");
    subs->ring = g;

    auto* ts = b->add_subcommand(
        "tube-sector", "an angular sector of concentric walls, each an exact sector with its own atom count");
    addTubeSectorOptions(*ts, *sector);
    addCommonOptions(ts, *common, "sector_N-M_..-CD.toml");
    subs->sector = ts;
  };
  c.selected = [subs] {
    for (CLI::App* s : {subs->cnt, subs->mw, subs->ring, subs->sector})
      if (s && s->parsed()) return true;
    return false;
  };
  c.run = [=] {
    if (subs->mw->parsed()) return buildMultiWall(*mw, *common);
    if (subs->ring->parsed()) return buildRing(*ring, *common);
    if (subs->sector->parsed()) return buildSector(*sector, *common);
    return buildCnt(*cnt, *common);
  };
  return c;
}

}  // namespace mesochain::app
