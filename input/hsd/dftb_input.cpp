#include "input/hsd/dftb_input.hpp"

#include <sstream>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/hsd/dftbplus_units.hpp"
#include "input/hsd/hsd_values.hpp"

namespace mesochain::input::hsd {

namespace {

// The newest DFTB+ parser version whose keywords this reader follows (DFTB+ 25.1).
constexpr long kParserVersion = 14;
// DFTB+'s defaults of the geometry drivers (MaxForceComponent in Ha/Bohr, MaxSteps).
constexpr double kDftbPlusMaxForceComponent = 1e-4;
constexpr long kDftbPlusMaxSteps = 200;

[[noreturn]] void missing(const std::string& path, const std::string& key, const std::string& expected) {
  throw InputError(path, "the file", "no " + key, expected);
}

// Geometry = GenFormat { ... }: the .gen lines (inline or <<< "file"), read by the project's
// .gen reader with the line numbers of their file, then scaled from CODATA's Bohr to DFTB+'s.
objective::GenGeometry readGeometry(const Node& root, const std::string& path) {
  const char* expected = "Geometry = GenFormat { <<< \"geo.gen\" } (or the .gen lines inline)";
  const Node* g = root.child("Geometry");
  if (!g) missing(path, "Geometry", expected);
  const Node& m = method(*g, expected);
  if (!m.is("GenFormat")) m.fail("the geometry format '" + m.name + "'", expected);
  requireNoAttribute(m);
  if (!m.children.empty()) m.children.front().fail("the keyword '" + m.children.front().name + "'",
                                                   "the lines of a .gen geometry");
  if (m.data.empty()) m.fail("no geometry lines", expected);
  const std::string file = m.data.front().file;
  std::string text;
  int line = 1;  // blank lines keep the reader's line numbers those of `file`
  for (const DataLine& d : m.data) {
    if (d.file != file)
      throw InputError(d.file, fmt::format("line {}", d.line), "geometry lines from a second file",
                       "the whole .gen geometry inline or in one <<< file");
    for (; line < d.line; ++line) text += '\n';
    text += d.text + '\n';
    ++line;
  }
  std::istringstream in(text);
  objective::GenGeometry gen = objective::readGen(in, file);
  // The .gen reader converts Å with CODATA 2018; DFTB+ uses 0.529177249 Å per Bohr.
  const double scale = kDftbPlusAngstromInBohr / units::kAngstromInBohr;
  gen.cell.positions *= scale;
  const objective::Symmetry& s = gen.cell.symmetry;
  if (!s.isRing())
    gen.cell.symmetry = objective::Symmetry::screw(s.translation() * scale, s.twist(), s.rotationOrder());
  return gen;
}

// Driver and Analysis: the task.
void readTask(const Node& root, objective::CellInput& in) {
  objective::TaskInput& task = in.task;
  bool forces = false;
  if (const Node* a = root.child("Analysis")) {
    requireNoAttribute(*a);
    if (const Node* old = a->child("CalculateForces"))
      old->fail("CalculateForces, the name of DFTB+ before parser version 14", "PrintForces = Yes");
    allowOnly(*a, {"PrintForces"});
    if (const Node* p = a->child("PrintForces")) forces = yesNo(*p);
  }
  task.type = forces ? "forces" : "energy";
  const Node* d = root.child("Driver");
  const char* drivers = "Driver = {} (none), Driver = LBFGS { ... } or Driver = ConjugateGradient { ... }";
  if (!d || (d->children.empty() && d->data.empty())) return;  // no driver: a single point
  const Node& m = method(*d, drivers);
  if (!m.is("LBFGS") && !m.is("ConjugateGradient"))
    m.fail("the driver '" + m.name + "'", drivers);
  allowOnly(m, {"MaxForceComponent", "MaxSteps", "LatticeOpt"});
  task.type = "relax";
  task.forceTolerance = kDftbPlusMaxForceComponent;
  task.maxSteps = static_cast<int>(kDftbPlusMaxSteps);
  if (const Node* f = m.child("MaxForceComponent")) {
    task.forceTolerance = withUnit(*f, UnitKind::Force, "au", "a positive force (Ha/Bohr by default)");
    if (!(task.forceTolerance > 0.0))
      f->fail(fmt::format("{} Ha/Bohr", task.forceTolerance), "a positive force");
  }
  if (const Node* n = m.child("MaxSteps")) {
    const long steps = integer(*n, "an integer from 1 to 100000000");
    if (steps < 1 || steps > 100000000L) n->fail(std::to_string(steps), "an integer from 1 to 100000000");
    task.maxSteps = static_cast<int>(steps);
  }
  if (const Node* l = m.child("LatticeOpt"))
    if (yesNo(*l))
      l->fail("LatticeOpt = Yes", "LatticeOpt = No (the lattice is kept; relax_translation of a cell "
                                  "file optimises the screw translation)");
}

// Options, ParserOptions, Parallel: accepted only with the values whose meaning mesochain keeps.
void readRunOptions(const Node& root) {
  if (const Node* o = root.child("Options")) {
    requireNoAttribute(*o);
    allowOnly(*o, {"WriteDetailedOut", "WriteResultsTag"});
    for (const Node& c : o->children) yesNo(c);  // output files of DFTB+; mesochain writes --json
  }
  if (const Node* p = root.child("ParserOptions")) {
    requireNoAttribute(*p);
    allowOnly(*p, {"ParserVersion"});
    if (const Node* v = p->child("ParserVersion")) {
      const long n = integer(*v, fmt::format("a parser version from 1 to {}", kParserVersion));
      if (n < 1 || n > kParserVersion)
        v->fail(std::to_string(n), fmt::format("a parser version from 1 to {} (DFTB+ 25.1's)", kParserVersion));
    }
  }
  if (const Node* p = root.child("Parallel")) {
    requireNoAttribute(*p);
    allowOnly(*p, {"UseOmpThreads"});
    if (const Node* u = p->child("UseOmpThreads"))
      if (!yesNo(*u))
        u->fail("UseOmpThreads = No", "UseOmpThreads = Yes (mesochain always runs OpenMP threads; "
                                      "OMP_NUM_THREADS=1 runs one)");
  }
}

}  // namespace

objective::CellInput readDftbInput(const std::string& path) { return readDftbInput(parseHsdFile(path), path); }

objective::CellInput readDftbInput(const Node& root, const std::string& path) {
  allowOnly(root, {"Geometry", "Hamiltonian", "Driver", "Analysis", "Options", "ParserOptions", "Parallel"});
  objective::CellInput in;
  in.source = path;
  readRunOptions(root);
  objective::GenGeometry gen = readGeometry(root, path);
  in.cell = std::move(gen.cell);
  detail::readHamiltonian(root, gen.type, in);
  readTask(root, in);
  in.cell.validate(path, objective::kMinimumAtomDistanceAngstrom * units::kAngstromInBohr);
  return in;
}

}  // namespace mesochain::input::hsd
