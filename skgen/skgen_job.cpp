#include "skgen/skgen_job.hpp"

#include "common/build_info.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <toml.hpp>

#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/toml_file.hpp"
#include "common/toml_table.hpp"
#include "skgen/repulsive_fit.hpp"
#include "skgen/skf_writer.hpp"

namespace mesochain::skgen {

namespace {
constexpr double kMaxSkgenGridRows = 100000;
}  // namespace


namespace {

const char* kShellNames = "spdf";

Confinement readConfinement(const TomlTable& t) {
  const std::string type = t.has("type") ? t.string("type", "\"power\" or \"woods-saxon\"") : "power";
  const double r0 = t.number("r0_bohr", "the confinement radius r0 in bohr (> 0)");
  if (!(r0 > 0.0)) t.fail("r0_bohr", fmt::format("{}", r0), "a radius > 0 bohr");
  if (type == "power") {
    t.allowOnly({"type", "r0_bohr", "power"});
    const double n = t.number("power", "the exponent n of (r/r0)^n (> 0)");
    if (!(n > 0.0)) t.fail("power", fmt::format("{}", n), "an exponent > 0");
    return Confinement::powerLaw(r0, n);
  }
  if (type == "woods-saxon") {
    t.allowOnly({"type", "r0_bohr", "height_hartree", "slope_per_bohr"});
    const double w = t.number("height_hartree", "the Woods-Saxon height W in hartree (> 0)");
    const double a = t.number("slope_per_bohr", "the Woods-Saxon slope a in 1/bohr (> 0)");
    if (!(w > 0.0)) t.fail("height_hartree", fmt::format("{}", w), "a height > 0");
    if (!(a > 0.0)) t.fail("slope_per_bohr", fmt::format("{}", a), "a slope > 0");
    return Confinement::woodsSaxon(r0, w, a);
  }
  t.fail("type", "\"" + type + "\"", "\"power\" or \"woods-saxon\"");
}

ElementSettings readElement(const TomlTable& t, const std::string& symbol, const SkgenJob& job) {
  t.allowOnly({"basis", "exponents_per_bohr", "powers", "density", "wavefunction", "shells"});
  ElementSettings s;
  s.symbol = symbol;
  s.source = job.source;
  s.xc = job.xc;
  s.hubbardXc = job.hubbardXc;
  const Element& e = findElement(symbol, job.source, t.name());
  const std::string basis = t.has("basis") ? t.string("basis", "\"slater\" or \"grid\"") : "slater";
  if (basis == "slater") {
    if (!t.has("exponents_per_bohr"))
      t.missing("exponents_per_bohr", "the Slater exponents α_j in 1/bohr, e.g. [0.5, 1.14, 2.62, 6.0]");
    const char* exponents = "a non-empty array of exponents > 0 in 1/bohr";
    s.slater.exponents = t.numbers("exponents_per_bohr", exponents);
    if (s.slater.exponents.empty()) t.fail("exponents_per_bohr", "an empty array", exponents);
    for (double a : s.slater.exponents)
      if (!(a > 0.0)) t.fail("exponents_per_bohr", fmt::format("an array holding {}", a), exponents);
    std::vector<double> sorted = s.slater.exponents;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i] - sorted[i - 1] < 1e-3 * sorted[i])
        t.fail("exponents_per_bohr", fmt::format("the exponent {} twice", sorted[i]),
               "distinct exponents (equal ones make the basis linearly dependent)");
    // Checked as 64-bit before narrowing (4294967299 would wrap to 3).
    const long powers = t.has("powers") ? t.integer("powers", "an integer 1..6") : 3;
    if (powers < 1 || powers > 6) t.fail("powers", fmt::format("{}", powers), "an integer from 1 to 6");
    s.slater.powers = static_cast<int>(powers);
  } else if (basis == "grid") {
    for (const char* k : {"exponents_per_bohr", "powers"})
      if (t.has(k)) t.fail(k, "a Slater-basis key with basis = \"grid\"", "no exponents or powers for the grid basis");
  } else {
    t.fail("basis", "\"" + basis + "\"", "\"slater\" or \"grid\"");
  }
  if (!t.has("density")) t.missing("density", "the density confinement, e.g. { r0_bohr = 7.0, power = 2 }");
  s.density = readConfinement(t.requireTable("density", "a confinement table { r0_bohr, power }"));
  std::optional<Confinement> all;
  if (t.has("wavefunction"))
    all = readConfinement(t.requireTable("wavefunction", "a confinement table { r0_bohr, power }"));
  std::optional<TomlTable> shells;
  if (t.has("shells")) shells = t.requireTable("shells", "a table of shells, e.g. { 2s = {...}, 2p = {...} }");
  std::vector<std::string> names;
  for (int k : e.valence) names.push_back(fmt::format("{}{}", e.shells[k].n, kShellNames[e.shells[k].l]));
  if (shells) {
    for (const std::string& k : shells->keys())
      if (k.size() >= 2 && (k.back() == 'd' || k.back() == 'f') && std::isdigit(static_cast<unsigned char>(k[0])))
        shells->fail(k, fmt::format("a {} shell", k.back()),
                     fmt::format("the valence shells of {} ({}): skgen computes s and p shells only (d and "
                                 "f atomic shells and two-centre integrals are not supported)",
                                 symbol, fmt::join(names, ", ")));
    shells->allowOnly(names);
  }
  for (const std::string& n : names) {
    if (shells && shells->has(n)) {
      s.shells.push_back(readConfinement(shells->requireTable(n, "a confinement table")));
    } else if (all) {
      s.shells.push_back(*all);
    } else {
      t.missing("wavefunction", fmt::format("a wavefunction confinement for every valence shell ({})",
                                            fmt::join(names, ", ")));
    }
  }
  return s;
}

std::string describeConfinement(const Confinement& c) { return c.describe(); }

}  // namespace

SkgenJob readSkgenJob(const std::string& path) {
  const toml::value root = parseTomlFile(path, "file of elements");
  SkgenJob job;
  job.source = path;
  const TomlTable top(path, root, "");
  top.allowOnly({"functional", "hubbard_functional", "superposition", "output_dir", "pairs", "grid",
                 "elements", "repulsive"});
  job.xc = parseXcKind(top.string("functional", "\"none\", \"lda\", \"lda-vwn\" or \"pbe\""), path);
  job.hubbardXc = top.has("hubbard_functional")
                      ? parseXcKind(top.string("hubbard_functional", "a functional name"), path)
                      : job.xc;
  if (top.has("output_dir")) job.outputDir = top.string("output_dir", "a folder name");

  double atomStep = 0.008;
  if (top.has("grid")) {
    const TomlTable g = top.requireTable("grid", "a table [grid]");
    g.allowOnly({"spacing_bohr", "cutoff_bohr", "quadrature_points", "quadrature_extent_bohr", "atom_log_step"});
    if (g.has("spacing_bohr")) job.grid.spacing = g.number("spacing_bohr", "a spacing in bohr");
    if (!(job.grid.spacing > 0.0)) g.fail("spacing_bohr", fmt::format("{}", job.grid.spacing), "a spacing > 0");
    if (g.has("cutoff_bohr")) job.grid.cutoff = g.number("cutoff_bohr", "a distance in bohr");
    // The rows of every table are cutoff / spacing: at most kMaxSkgenGridRows (each row costs a
    // two-centre quadrature, and DFTB+ tables have 500-1000).
    if (job.grid.cutoff / job.grid.spacing > kMaxSkgenGridRows)
      g.fail("spacing_bohr and cutoff_bohr",
             fmt::format("{} / {} = {:.4g} grid rows", job.grid.cutoff, job.grid.spacing,
                         job.grid.cutoff / job.grid.spacing),
             fmt::format("at most {} rows per table", kMaxSkgenGridRows));
    if (job.grid.cutoff < job.grid.spacing)
      g.fail("cutoff_bohr", fmt::format("{} bohr, shorter than the first grid point ({} bohr)",
                                        job.grid.cutoff, job.grid.spacing),
             "a cutoff at least one grid spacing long");
    if (g.has("quadrature_points")) {
      const long n = g.integer("quadrature_points", "an integer 8..400");
      if (n < 8 || n > 400) g.fail("quadrature_points", fmt::format("{}", n), "an integer 8..400");
      job.grid.quadrature.nXi = job.grid.quadrature.nEta = static_cast<int>(n);
    } else {
      job.grid.quadrature.nXi = job.grid.quadrature.nEta = 48;
    }
    job.grid.quadrature.rMax = 20.0;
    if (g.has("quadrature_extent_bohr")) job.grid.quadrature.rMax = g.number("quadrature_extent_bohr", "bohr");
    if (!(job.grid.quadrature.rMax > 1.0))
      g.fail("quadrature_extent_bohr", fmt::format("{}", job.grid.quadrature.rMax), "an extent > 1 bohr");
    if (g.has("atom_log_step")) atomStep = g.number("atom_log_step", "the step in ln r");
    if (!(atomStep > 0.0 && atomStep <= 0.05))
      g.fail("atom_log_step", fmt::format("{}", atomStep), "a step in ln r between 0 and 0.05");
  } else {
    job.grid.quadrature.nXi = job.grid.quadrature.nEta = 48;
    job.grid.quadrature.rMax = 20.0;
  }

  if (top.has("superposition")) {
    const std::string sup = top.string("superposition", "\"density\" or \"potential\"");
    if (sup == "density") job.grid.quadrature.superposition = Superposition::Density;
    else if (sup == "potential") job.grid.quadrature.superposition = Superposition::Potential;
    else top.fail("superposition", "\"" + sup + "\"", "\"density\" or \"potential\"");
  }

  if (!top.has("elements")) top.missing("elements", "a table [elements.SYMBOL] per element");
  const TomlTable elements = top.requireTable("elements", "tables [elements.SYMBOL]");
  // file order: toml11 keeps insertion order only with ordered tables; sort by line instead
  std::vector<std::pair<int, std::string>> order;
  for (const std::string& k : elements.keys()) order.emplace_back(elements.line(k), k);
  std::sort(order.begin(), order.end());
  for (const auto& [line, symbol] : order) {
    ElementSettings s = readElement(elements.requireTable(symbol, "a table [elements." + symbol + "]"),
                                    symbol, job);
    s.h = atomStep;
    job.elements.push_back(std::move(s));
  }
  if (job.elements.empty()) top.fail("elements", "no element", "at least one [elements.SYMBOL]");

  auto known = [&](const std::string& sym) {
    for (const auto& e : job.elements)
      if (e.symbol == sym) return true;
    return false;
  };
  if (top.has("pairs")) {
    for (const std::string& s : top.strings("pairs", "an array of \"A-B\" strings")) {
      const auto dash = s.find('-');
      if (dash == std::string::npos || dash == 0 || dash + 1 == s.size())
        top.fail("pairs", "\"" + s + "\"", "pairs written \"A-B\", e.g. \"C-H\"");
      const std::string a = s.substr(0, dash), b = s.substr(dash + 1);
      for (const std::string& sym : {a, b}) {
        findElement(sym, path, top.where("pairs"));
        if (!known(sym))
          top.fail("pairs", "\"" + s + "\" names " + sym + ", which has no [elements." + sym + "] table",
                   "pairs of the elements defined in the file");
      }
      job.pairs.emplace_back(a, b);
    }
  } else {
    for (const auto& a : job.elements)
      for (const auto& b : job.elements) job.pairs.emplace_back(a.symbol, b.symbol);
  }
  if (top.has("repulsive")) {
    const TomlTable rep = top.requireTable("repulsive", "tables [repulsive.A-B]");
    for (const std::string& name : rep.keys()) {
      const TomlTable t = rep.requireTable(name, "a table [repulsive." + name + "]");
      t.allowOnly({"curve_csv", "cutoff_bohr", "intervals"});
      const auto dash = name.find('-');
      RepulsiveRequest r;
      r.key = t.name();
      if (dash == std::string::npos || dash == 0 || dash + 1 == name.size())
        rep.fail(name, "a table named '" + name + "'", "[repulsive.A-B], e.g. [repulsive.C-H]");
      r.a = name.substr(0, dash);
      r.b = name.substr(dash + 1);
      for (const std::string& sym : {r.a, r.b})
        if (!known(sym))
          rep.fail(name, "the element " + sym + " without an [elements." + sym + "] table",
                   "pairs of the elements defined in the file");
      for (const auto& other : job.repulsive)
        if ((other.a == r.a && other.b == r.b) || (other.a == r.b && other.b == r.a))
          rep.fail(name, "a second repulsive for the pair", "one [repulsive.A-B] per pair (it serves B-A too)");
      const std::filesystem::path curve(t.string("curve_csv", "a CSV file 'r_bohr,energy_hartree'"));
      r.curve = curve.is_absolute() ? curve.string()
                                    : (std::filesystem::path(path).parent_path() / curve).string();
      r.cutoff = t.number("cutoff_bohr", "the repulsive cutoff in bohr");
      if (!(r.cutoff > 0.0)) t.fail("cutoff_bohr", fmt::format("{}", r.cutoff), "a cutoff > 0");
      // The integral table must reach beyond the repulsion (the .skf reader refuses a table
      // whose grid ends before its repulsive cutoff: dftb/skf_file.cpp).
      if (r.cutoff > job.grid.cutoff)
        t.fail("cutoff_bohr",
               fmt::format("{} bohr, beyond the integral grid ([grid] cutoff_bohr = {} bohr)",
                           r.cutoff, job.grid.cutoff),
               "a repulsive cutoff within the integral grid");
      if (t.has("intervals")) {
        const long n = t.integer("intervals", "an integer 1..200");
        if (n < 1 || n > 200) t.fail("intervals", fmt::format("{}", n), "an integer 1..200");
        r.intervals = static_cast<int>(n);
      }
      job.repulsive.push_back(r);
    }
  }
  return job;
}

std::string skgenDocumentation(const SkgenJob& job, const ElementSettings& a,
                               const ElementSettings& b, const RepulsiveRequest* rep) {
  std::string doc = "<Documentation>\n  <General>\n";
  doc += fmt::format("    <Identifier>{}-{}.skf</Identifier>\n    <Code>mesochain skgen</Code>\n", a.symbol, b.symbol);
  doc += fmt::format("    <Input>{}</Input>\n  </General>\n  <SK_table>\n", job.source);
  doc += fmt::format("    <Functional>{}</Functional>\n    <HubbardFunctional>{}</HubbardFunctional>\n",
                     xcName(job.xc), xcName(job.hubbardXc));
  doc += fmt::format("    <Superposition>{}</Superposition>\n",
                     job.grid.quadrature.superposition == Superposition::Potential ? "potential" : "density");
  doc += fmt::format("    <Grid spacing_bohr=\"{}\" cutoff_bohr=\"{}\" quadrature_points=\"{}\" "
                     "quadrature_extent_bohr=\"{}\"/>\n",
                     job.grid.spacing, job.grid.cutoff, job.grid.quadrature.nXi, job.grid.quadrature.rMax);
  int atom = 1;
  for (const ElementSettings* e : {&a, &b}) {
    if (atom == 2 && a.symbol == b.symbol) break;
    doc += fmt::format("    <Basis atom=\"{}\" element=\"{}\">\n", atom++, e->symbol);
    if (e->slater.empty()) {
      doc += "      <Type>numerical radial grid</Type>\n";
    } else {
      doc += fmt::format("      <Type>Slater</Type>\n      <Exponents>{}</Exponents>\n      <Powers>{}</Powers>\n",
                         fmt::join(e->slater.exponents, " "), e->slater.powers);
    }
    doc += fmt::format("      <Density>{}</Density>\n", describeConfinement(e->density));
    for (const Confinement& c : e->shells) doc += fmt::format("      <Wavefunction>{}</Wavefunction>\n", describeConfinement(c));
    doc += "    </Basis>\n";
  }
  doc += "  </SK_table>\n  <E_rep>\n    <Storage>spline</Storage>\n";
  if (rep) {
    doc += fmt::format("    <Fit curve=\"{}\" cutoff_bohr=\"{}\" intervals=\"{}\"/>\n", rep->curve,
                       rep->cutoff, rep->intervals);
    doc += "    <Notes>Least-squares cubic spline to E_ref - E_el of the dimer (non-SCC), zero "
           "with zero slope and curvature at the cutoff, exponential head.</Notes>\n";
  } else {
    doc += "    <Notes>Explicit zero repulsive: no repulsive potential was fitted; the spline block "
           "evaluates to 0 at every distance. Fit one before using the table for total energies "
           "or forces.</Notes>\n";
  }
  doc += "  </E_rep>\n</Documentation>\n";
  return doc;
}

std::string atomicDataJson(const SkgenJob& job,
                           const std::vector<std::pair<std::string, const ElementBasis*>>& elements) {
  nlohmann::ordered_json root;
  root["code"] = "mesochain skgen";
  root["program"] = buildInfoJson();
  root["input"] = job.source;
  root["functional"] = xcName(job.xc);
  root["hubbard_functional"] = xcName(job.hubbardXc);
  root["notes"] =
      "Free spherical atom. onsite_Ha: Kohn-Sham levels; hubbard_Ha: dε/dn of the highest "
      "occupied shell (hubbard_functional); spin_constants_Ha: W_ll' = ½(∂ε_l↑/∂n_l'↑ − "
      "∂ε_l↑/∂n_l'↓) of the valence shells in shell order (DFTB+ SpinConstants), empty shells "
      "take the values of the highest occupied one; spin_polarisation_energy_Ha: E(Hund's-rule "
      "spin-polarised atom) − E(unpolarised atom), the SPE field of the .skf atomic line "
      "(functional for W and SPE: functional)";
  nlohmann::ordered_json list = nlohmann::ordered_json::object();
  for (const auto& [symbol, b] : elements) {
    const Element& e = *b->element;
    nlohmann::ordered_json el;
    el["z"] = e.z;
    el["mass_amu"] = e.mass;
    std::vector<std::string> shells;
    nlohmann::ordered_json onsite, u, occ;
    for (int k : e.valence) {
      const std::string name = fmt::format("{}{}", e.shells[k].n, kShellNames[e.shells[k].l]);
      shells.push_back(name);
      onsite[name] = b->data.onsite[e.shells[k].l];
      u[name] = b->data.hubbard[e.shells[k].l];
      occ[name] = b->data.occupation[e.shells[k].l];
    }
    el["valence_shells"] = shells;
    el["onsite_Ha"] = onsite;
    el["hubbard_Ha"] = u;
    el["occupation"] = occ;
    el["spin_constants_Ha"] = b->data.spinConstants;
    el["spin_polarisation_energy_Ha"] = b->data.spinPolarisationEnergy;
    list[symbol] = el;
  }
  root["elements"] = list;
  return root.dump(2) + "\n";
}

SkgenOutput runSkgen(const SkgenJob& job,
                     const std::function<void(double, const std::string&)>& progress) {
  // work units: 1 per element, rows per pair (an element costs roughly as much as 40 rows)
  const int rows = static_cast<int>(std::floor(job.grid.cutoff / job.grid.spacing + 1e-9));
  const double perElement = 40.0;
  const double total = perElement * job.elements.size() + static_cast<double>(rows) * job.pairs.size();
  double done = 0.0;
  auto report = [&](const std::string& what) {
    if (progress) progress(std::min(1.0, done / total), what);
  };
  std::map<std::string, ElementBasis> bases;
  std::map<std::string, const ElementSettings*> settings;
  for (const ElementSettings& e : job.elements) {
    report("atom " + e.symbol);
    ElementBasis b = buildElementBasis(e);
    report("spin " + e.symbol);
    addSpinData(e, b);
    bases.emplace(e.symbol, std::move(b));
    settings[e.symbol] = &e;
    done += perElement;
  }
  std::filesystem::create_directories(job.outputDir);
  SkgenOutput output;
  std::vector<std::string>& written = output.tables;
  std::map<std::string, dftb::SplineRepulsiveData> fitted;
  for (const auto& [a, b] : job.pairs) {
    const std::string name = a + "-" + b;
    dftb::SkfTable t = buildSkTable(bases.at(a), bases.at(b), job.xc, job.grid, a == b,
                                    [&](int i, int) {
                                      done += 1.0;
                                      if (i % 10 == 0) report("pair " + name);
                                    });
    const RepulsiveRequest* rep = nullptr;
    for (const auto& r : job.repulsive)
      if ((r.a == a && r.b == b) || (r.a == b && r.b == a)) rep = &r;
    if (rep) {
      const std::string unordered = rep->a + "-" + rep->b;
      if (!fitted.count(unordered)) {
        report("repulsive " + unordered);
        fitted[unordered] = fitRepulsive(bases.at(rep->a), bases.at(rep->b), job.xc, job.grid.quadrature,
                                         readDimerCurve(rep->curve), rep->cutoff, rep->intervals, rep->key);
      }
      t.spline = fitted.at(unordered);
    } else {
      t.spline = zeroRepulsive(1.0, 2.0);
    }
    const std::string path = (std::filesystem::path(job.outputDir) / (name + ".skf")).string();
    writeSkfFile(path, t, skgenDocumentation(job, *settings.at(a), *settings.at(b), rep));
    written.push_back(path);
  }
  std::vector<std::pair<std::string, const ElementBasis*>> elements;
  for (const ElementSettings& e : job.elements) elements.emplace_back(e.symbol, &bases.at(e.symbol));
  output.atomicData = (std::filesystem::path(job.outputDir) / "atomic-data.json").string();
  writeFileAtomically(output.atomicData, atomicDataJson(job, elements));
  done = total;
  report("done");
  return output;
}

}  // namespace mesochain::skgen
