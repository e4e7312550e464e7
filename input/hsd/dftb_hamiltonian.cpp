// Hamiltonian = DFTB { ... } of a dftb_in.hsd into the cell-file settings (input/hsd/dftb_input.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "common/electronic_temperature.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/hsd/dftb_input.hpp"
#include "input/hsd/dftbplus_units.hpp"
#include "input/hsd/hsd_values.hpp"
#include "objective/core/uff_parameters.hpp"

namespace mesochain::input::hsd::detail {

namespace fs = std::filesystem;
using objective::CellInput;
using objective::GenType;

namespace {

// DFTB+'s defaults (manual, Hamiltonian = DFTB).
constexpr double kDftbPlusSccTolerance = 1e-5;
constexpr long kDftbPlusMaxSccIterations = 100;

bool isSpecies(const CellInput& in, const std::string& el) {
  return std::find(in.cell.speciesNames.begin(), in.cell.speciesNames.end(), el) != in.cell.speciesNames.end();
}

bool integral(double x) { return std::abs(x - std::round(x)) < 1e-9; }

void readScc(const Node& h, CellInput& in) {
  in.scc.enabled = false;
  if (const Node* s = h.child("SCC")) in.scc.enabled = yesNo(*s);
  for (const char* key : {"SCCTolerance", "MaxSCCIterations", "EwaldTolerance", "EwaldParameter"})
    if (const Node* n = h.child(key); n && !in.scc.enabled)
      n->fail(std::string(key) + " with SCC = No", "SCC = Yes, or no SCC keywords");
  if (!in.scc.enabled) return;
  in.scc.chargeTolerance = kDftbPlusSccTolerance;
  if (const Node* t = h.child("SCCTolerance")) {
    in.scc.chargeTolerance = real(*t, "a charge tolerance in [1e-13, 1] (electrons)");
    if (!(in.scc.chargeTolerance >= 1e-13 && in.scc.chargeTolerance <= 1.0))
      t->fail(fmt::format("{}", in.scc.chargeTolerance),
              "a charge tolerance in [1e-13, 1] (electrons; tighter cannot be resolved in double precision)");
  }
  // DFTB+ stops on the charges alone: mesochain's energy criterion is left wide open (1 Ha).
  in.scc.energyTolerance = 1.0;
  in.scc.maxIterations = static_cast<int>(kDftbPlusMaxSccIterations);
  if (const Node* n = h.child("MaxSCCIterations")) {
    const long k = integer(*n, "1 .. 100000");
    if (k < 1 || k > 100000) n->fail(std::to_string(k), "1 .. 100000");
    in.scc.maxIterations = static_cast<int>(k);
  }
  // DFTB+'s EwaldTolerance bounds the terms its 3-D Ewald sum leaves out; mesochain's
  // [scc] ewald_tolerance bounds the error of its helical Ewald sum of the same 1/r interaction
  // (docs/ewald.md): the same number, within mesochain's range.
  if (const Node* t = h.child("EwaldTolerance")) {
    in.scc.ewaldTolerance = real(*t, "an Ewald tolerance in [1e-13, 1e-2]");
    if (!(in.scc.ewaldTolerance >= 1e-13 && in.scc.ewaldTolerance <= 1e-2))
      t->fail(fmt::format("{}", in.scc.ewaldTolerance), "an Ewald tolerance in [1e-13, 1e-2]");
  }
  // EwaldParameter only splits DFTB+'s sum between real and reciprocal space (0: DFTB+ chooses);
  // the converged sum does not depend on it, and mesochain's helical Ewald sum chooses its own
  // split, so it is checked and has no other effect.
  if (const Node* a = h.child("EwaldParameter")) {
    const double alpha = real(*a, "a splitting parameter >= 0 (1/Bohr; 0: automatic)");
    if (!(alpha >= 0.0)) a->fail(fmt::format("{}", alpha), "a splitting parameter >= 0 (1/Bohr; 0: automatic)");
  }
}

std::string existingTable(const Node& at, const std::string& file, const std::string& hsdPath,
                          const std::string& pair) {
  const fs::path p(file);
  const fs::path resolved = (p.is_absolute() ? p : fs::path(hsdPath).parent_path() / p).lexically_normal();
  std::error_code ec;
  if (file.empty() || !fs::is_regular_file(resolved, ec))
    at.fail(fmt::format("the table of {}: \"{}\", which does not exist", pair, resolved.string()),
            "an existing .skf file for every ordered pair of elements (paths relative to the folder of the "
            "input)");
  return resolved.string();
}

void readTables(const Node& h, CellInput& in) {
  const char* expected =
      "SlaterKosterFiles = Type2FileNames { Prefix = \"...\" Separator = \"-\" Suffix = \".skf\" } or "
      "SlaterKosterFiles { C-C = \"C-C.skf\" ... }";
  const Node* sk = h.child("SlaterKosterFiles");
  if (!sk) h.fail("no SlaterKosterFiles", expected);
  requireNoAttribute(*sk);
  const auto& species = in.cell.speciesNames;
  if (sk->children.size() == 1 && sk->children.front().is("Type2FileNames") && sk->children.front().block) {
    const Node& t = sk->children.front();
    allowOnly(t, {"Prefix", "Separator", "Suffix", "LowerCaseTypeName"});
    auto text = [&](const char* key) { return t.child(key) ? word(*t.child(key), "a string") : std::string(); };
    const std::string prefix = text("Prefix"), separator = text("Separator"), suffix = text("Suffix");
    const bool lower = t.child("LowerCaseTypeName") && yesNo(*t.child("LowerCaseTypeName"));
    for (const auto& a : species)
      for (const auto& b : species) {
        const std::string file = prefix + (lower ? lowerCase(a) : a) + separator + (lower ? lowerCase(b) : b) + suffix;
        in.parameterFiles[a + "-" + b] = existingTable(t, file, in.source, a + "-" + b);
      }
    return;
  }
  if (!sk->block || !sk->data.empty()) sk->fail("a value", expected);
  for (const Node& c : sk->children) {
    const auto dash = c.name.find('-');
    const std::string a = dash == std::string::npos ? "" : c.name.substr(0, dash);
    const std::string b = dash == std::string::npos ? "" : c.name.substr(dash + 1);
    if (!isSpecies(in, a) || !isSpecies(in, b))
      c.fail("the keyword '" + c.name + "'", "A-B = \"file.skf\" for ordered pairs of the elements of the geometry");
    if (in.parameterFiles.count(a + "-" + b)) c.fail("the pair " + c.name + " a second time", "each pair once");
    in.parameterFiles[a + "-" + b] =
        existingTable(c, word(c, "one .skf file (a quoted path)"), in.source, c.name);
  }
  for (const auto& a : species)
    for (const auto& b : species)
      if (!in.parameterFiles.count(a + "-" + b))
        sk->fail("no table for the pair " + a + "-" + b, "an entry for every ordered pair of the elements");
}

void readAngularMomenta(const Node& h, CellInput& in) {
  const Node* m = h.child("MaxAngularMomentum");
  if (!m) h.fail("no MaxAngularMomentum", "MaxAngularMomentum { C = \"p\" H = \"s\" } for every element");
  requireNoAttribute(*m);
  if (!m->data.empty() || !m->block) m->fail("a value", "MaxAngularMomentum { C = \"p\" ... }");
  for (const Node& c : m->children) {
    if (!isSpecies(in, c.name))
      c.fail("element '" + c.name + "', which is not in the geometry", "the elements of the geometry");
    if (in.maxAngularMomentum.count(c.name)) c.fail(c.name + " a second time", "each element once");
    const std::string shell = lowerCase(word(c, "\"s\", \"p\", \"d\" or \"f\""));
    const std::string shells = "spdf";
    if (shell.size() != 1 || shells.find(shell[0]) == std::string::npos)
      c.fail("'" + shell + "'", "\"s\", \"p\", \"d\" or \"f\"");
    in.maxAngularMomentum[c.name] = static_cast<int>(shells.find(shell[0]));
  }
  for (const auto& el : in.cell.speciesNames)
    if (!in.maxAngularMomentum.count(el)) m->fail("no entry for " + el, "an entry for every element");
}

// KPointsAndWeights onto mesochain's helical midpoint grid (objective/core/kgrid.hpp) and its
// angular samples; a set of points that grid does not contain is an error saying why.
void readKPoints(const Node& h, GenType type, CellInput& in) {
  const Node* k = h.child("KPointsAndWeights");
  const objective::Symmetry& sym = in.cell.symmetry;
  in.band.helicalKPoints = 1;
  in.band.angular.samples = 0;
  if (type == GenType::Cluster || sym.isRing()) {
    if (k) k->fail("k-points for a molecule or closed ring", "no KPointsAndWeights (.gen type C)");
    return;
  }
  if (type == GenType::Helical) {
    const char* expected = "KPointsAndWeights = HelicalUniform { N 0.5 } or HelicalSampled { N1 N2 0.5 S2 }";
    if (!k) h.fail("no KPointsAndWeights for a helical geometry", expected);
    const Node& m = method(*k, expected);
    const int cn = sym.rotationOrder();
    if (m.is("HelicalUniform")) {
      // k1 = (i + s)/(2N), i < N, every k2 = j/C_n (DFTB+ parser_kpoints.F90): with s = 1/2 the
      // half of the midpoint grid of 2N points that time reversal keeps, i.e. helical = 2N.
      const auto v = reals(m, 2, "two numbers: N (an integer >= 1) and the shift 0.5");
      if (!integral(v[0]) || v[0] < 1 || v[0] > 500000) m.fail(fmt::format("N = {}", v[0]), "an integer 1 .. 500000");
      if (std::abs(v[1] - 0.5) > 1e-12)
        m.fail(fmt::format("the shift {}", v[1]),
               "the shift 0.5: DFTB+ puts k1 = (i + s)/(2N), which is mesochain's midpoint grid of 2N "
               "helical points only for s = 1/2");
      in.band.helicalKPoints = 2 * static_cast<int>(std::lround(v[0]));
      return;
    }
    if (m.is("HelicalSampled")) {
      // k1 = (i + s1)/(2 N1), k2 = j/N2 + s2 (mod 1), N2 | C_n: mesochain's angular samples are
      // mu_m = floor((m + 1/2) C_n / N2) = m L + floor(L/2), L = C_n / N2.
      const auto v = reals(m, 4, "four numbers: N1 N2 (integers) and the shifts 0.5 S2");
      if (!integral(v[0]) || v[0] < 1 || v[0] > 500000) m.fail(fmt::format("N1 = {}", v[0]), "an integer 1 .. 500000");
      if (!integral(v[1]) || v[1] < 1 || v[1] > cn || cn % static_cast<int>(std::lround(v[1])) != 0)
        m.fail(fmt::format("N2 = {}", v[1]), fmt::format("a divisor of the rotation order C_{}", cn));
      if (std::abs(v[2] - 0.5) > 1e-12)
        m.fail(fmt::format("the shift {}", v[2]), "the helical shift 0.5 (mesochain's midpoint grid)");
      const int n2 = static_cast<int>(std::lround(v[1]));
      const int l = cn / n2;
      const double muShift = v[3] * cn;
      if (!integral(muShift))
        m.fail(fmt::format("the shift {}", v[3]), fmt::format("a multiple of 1/{} (DFTB+'s rule)", cn));
      const long shift = ((std::lround(muShift) % l) + l) % l;
      if (n2 < cn && shift != l / 2)
        m.fail(fmt::format("the angular shift {}", v[3]),
               fmt::format("a shift of {}/{} (mod {}/{}): mesochain samples mu = m {} + {}", l / 2, cn, l, cn, l, l / 2));
      in.band.helicalKPoints = 2 * static_cast<int>(std::lround(v[0]));
      in.band.angular.samples = n2 < cn ? n2 : 0;
      return;
    }
    m.fail("the k-point scheme '" + m.name + "'", expected);
  }
  // .gen S/F: a and b only set vacuum (input/gen_file.hpp), c is the period.
  const char* expected = "KPointsAndWeights = SupercellFolding { 1 0 0  0 1 0  0 0 N  0.0 0.0 S }";
  if (!k) h.fail("no KPointsAndWeights for a periodic geometry", expected);
  const Node& m = method(*k, expected);
  if (!m.is("SupercellFolding")) m.fail("the k-point scheme '" + m.name + "'", expected);
  const auto v = reals(m, 12, "a 3 x 3 folding matrix and a shift (12 numbers)");
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if ((i != j && v[3 * i + j] != 0.0) || (i == j && i < 2 && v[3 * i + j] != 1.0))
        m.fail(fmt::format("the folding matrix entry ({}, {}) = {}", i + 1, j + 1, v[3 * i + j]),
               "diag(1, 1, N): one point along a and b (vacuum), N along the period c");
  const double n = v[8];
  if (!integral(n) || n < 1 || n > 1000000) m.fail(fmt::format("N = {}", n), "an integer 1 .. 1000000");
  if (v[9] != 0.0 || v[10] != 0.0)
    m.fail(fmt::format("the shift ({}, {}) along a and b", v[9], v[10]), "0 0 (a and b are vacuum)");
  // DFTB+: k = (m + S)/N, m < N, reduced by k -> -k; mesochain: (m + 1/2)/N - 1/2. The same set
  // for S = 1/2 (N even) or S = 0 (N odd).
  const int ni = static_cast<int>(std::lround(n));
  const double want = ni % 2 == 0 ? 0.5 : 0.0;
  const double s = v[11] - std::floor(v[11]);
  if (std::abs(s - want) > 1e-12)
    m.fail(fmt::format("the shift {} along c with N = {}", v[11], ni),
           fmt::format("{} for N {}: mesochain's midpoint grid of N points along the period", want,
                       ni % 2 == 0 ? "even" : "odd"));
  in.band.helicalKPoints = ni;
}

void readFilling(const Node& h, CellInput& in) {
  const char* expected = "Filling = Fermi { Temperature [Kelvin] = T } with T >= 0.01 K (DFTB+'s default is 0)";
  const Node* f = h.child("Filling");
  if (!f) h.fail("no Filling", expected);
  const Node& m = method(*f, expected);
  if (!m.is("Fermi")) m.fail("the filling '" + m.name + "'", expected);
  allowOnly(m, {"Temperature"});
  const Node* t = m.child("Temperature");
  if (!t) m.fail("no Temperature", expected);
  in.band.electronicTemperature = withUnit(*t, UnitKind::Energy, "au", "a temperature (Hartree by default, [Kelvin], [eV], ...)");
  if (!electronicTemperatureInRange(in.band.electronicTemperature))
    t->fail(describeElectronicTemperature(in.band.electronicTemperature), electronicTemperatureRange());
}

void readDispersion(const Node& h, CellInput& in) {
  const Node* d = h.child("Dispersion");
  if (!d) return;
  const char* expected = "Dispersion = LennardJones { Parameters = UFFParameters {} } or per element "
                         "Parameters { C { Distance [AA] = ... Energy [kcal/mol] = ... } }";
  const Node& m = method(*d, expected);
  if (!m.is("LennardJones")) m.fail("the dispersion model '" + m.name + "'", expected);
  allowOnly(m, {"Parameters"});
  const Node* p = m.child("Parameters");
  if (!p) m.fail("no Parameters", expected);
  requireNoAttribute(*p);
  dftb::DispersionTable& disp = in.dispersion;
  disp = dftb::DispersionTable{};
  disp.lj.enabled = true;
  std::map<std::string, dftb::LjElement> elements;
  if (p->children.size() == 1 && p->children.front().is("UFFParameters") && p->children.front().block) {
    allowOnly(p->children.front(), {});
    for (const auto& el : in.cell.speciesNames) {
      const auto uff = objective::uffParameters(el);
      if (!uff)
        p->fail("element " + el + ", which has no UFF entry in mesochain's table (" + objective::uffElementRange() + ")",
                "explicit Parameters { " + el + " { Distance [AA] = ... Energy [kcal/mol] = ... } }");
      // As DFTB+ (dispuffdata.F90): Å and kcal/mol with DFTB+'s constants.
      elements[el] = {uff->energyKcalPerMol * kDftbPlusKcalPerMolInHartree,
                           uff->distanceAngstrom * kDftbPlusAngstromInBohr};
    }
  } else {
    if (!p->block || !p->data.empty()) p->fail("a value", expected);
    for (const Node& c : p->children) {
      if (!isSpecies(in, c.name))
        c.fail("element '" + c.name + "', which is not in the geometry", "the elements of the geometry");
      requireNoAttribute(c);
      allowOnly(c, {"Distance", "Energy"});
      if (!c.child("Distance") || !c.child("Energy"))
        c.fail("no Distance or no Energy", "Distance [AA] = ... and Energy [kcal/mol] = ... (Bohr and Hartree by default)");
      const double r0 = withUnit(*c.child("Distance"), UnitKind::Length, "bohr", "a positive distance");
      const double eps = withUnit(*c.child("Energy"), UnitKind::Energy, "au", "a positive well depth");
      if (!(r0 > 0.0)) c.child("Distance")->fail(fmt::format("{} Bohr", r0), "a positive distance");
      if (!(eps > 0.0)) c.child("Energy")->fail(fmt::format("{} Ha", eps), "a positive well depth");
      if (elements.count(c.name)) c.fail(c.name + " a second time", "each element once");
      elements[c.name] = {eps, r0};
    }
    for (const auto& el : in.cell.speciesNames)
      if (!elements.count(el)) p->fail("no parameters for " + el, "Distance and Energy for every element");
  }
  // The full r^-6 sum (helical Ewald; DFTB+ sums all pairs of a molecule and Ewald-sums the
  // r^-6 part of a periodic one): short-range part to the cell file's default cutoff.
  dftb::setLjElements(disp.lj, elements);
  disp.lj.cutoff = dftb::kDefaultLjCutoffAngstrom * units::kAngstromInBohr;
  disp.lj.ewald = true;
}

}  // namespace

void readHamiltonian(const Node& root, GenType type, CellInput& in) {
  const char* expected = "Hamiltonian = DFTB { ... }";
  const Node* h = root.child("Hamiltonian");
  if (!h) throw InputError(in.source, "the file", "no Hamiltonian", expected);
  const Node& m = method(*h, expected);
  if (!m.is("DFTB")) m.fail("the Hamiltonian '" + m.name + "'", expected);
  allowOnly(m, {"SCC", "SCCTolerance", "MaxSCCIterations", "EwaldTolerance", "EwaldParameter", "MaxAngularMomentum",
                "SlaterKosterFiles", "KPointsAndWeights", "Filling", "Dispersion"});
  readScc(m, in);
  readTables(m, in);
  readAngularMomenta(m, in);
  readKPoints(m, type, in);
  readFilling(m, in);
  readDispersion(m, in);
}

}  // namespace mesochain::input::hsd::detail
