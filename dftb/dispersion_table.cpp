#include "dftb/dispersion_table.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "common/units.hpp"
#include "objective/core/uff_parameters.hpp"

namespace mesochain::dftb {

namespace {

const char* kModels = "\"none\", \"lj\" or \"kc\"";
const std::vector<std::string> kLjOnlyKeys{"epsilon", "r0", "elements", "summation", "ewald_tolerance"};
const std::vector<std::string> kKcOnlyKeys{"taper_start", "bond_cutoff"};

// A positive number in `unit` (the key's fallback when absent).
double positive(const TomlTable& t, const char* key, double fallback, const char* unit) {
  return t.positiveOr(key, fallback, fmt::format("a positive number ({})", unit));
}

// model = "kc" (dftb/dispersion_kc.hpp): the parameter set and, when given, its cutoff and taper
// start (absent: the set's own, resolved in dispersion_kc.cpp), and the bond cutoff.
void readKolmogorovCrespi(const TomlTable& t, KolmogorovCrespiSettings& kc) {
  kc.enabled = true;
  if (t.has("parameters")) {
    kc.parameters = t.string("parameters", "\"kc2005\" or \"ouyang2018\"");
    if (kc.parameters != "kc2005" && kc.parameters != "ouyang2018")
      t.fail("parameters", "\"" + kc.parameters + "\"", "\"kc2005\" or \"ouyang2018\"");
  }
  if (t.has("cutoff") != t.has("taper_start"))
    t.fail(t.has("cutoff") ? "cutoff" : "taper_start",
           t.has("cutoff") ? "a cutoff without taper_start" : "a taper_start without cutoff",
           "cutoff and taper_start together, or neither (the parameter set's own)");
  if (t.has("cutoff")) {
    const double angstrom = positive(t, "cutoff", 0.0, "Å");
    if (angstrom > kMaximumKcCutoffAngstrom || angstrom < 7.0)
      t.fail("cutoff", fmt::format("{} Å", angstrom), fmt::format("a cutoff in [7, {}] Å", kMaximumKcCutoffAngstrom));
    kc.cutoff = angstrom * units::kAngstromInBohr;
    const double x = t.number("taper_start", "a distance >= 0 (Å) below the cutoff");
    if (!(x >= 0.0)) t.fail("taper_start", fmt::format("{} Å", x), "a distance >= 0 (Å)");
    if (!(x < angstrom))
      t.fail("taper_start", fmt::format("{} Å >= cutoff {} Å", x, angstrom), "a taper start below the cutoff");
    kc.taperStart = x * units::kAngstromInBohr;
  }
  const double bond = positive(t, "bond_cutoff", kDefaultKcBondCutoffAngstrom, "Å");
  if (bond >= 2.2)
    t.fail("bond_cutoff", fmt::format("{} Å", bond),
           "a covalent cutoff below 2.2 Å (the second neighbours of graphene are at 2.46 Å)");
  kc.bondCutoff = bond * units::kAngstromInBohr;
}

// elements = { C = { epsilon = ..., r0 = ... }, ... }: every element of the cell.
std::map<std::string, LjElement> readLjElements(const TomlTable& t, const std::vector<std::string>& species) {
  const char* shape = "an inline table of the elements of the cell, such as { C = { epsilon = 0.105, "
                      "r0 = 3.851 }, H = { epsilon = 0.044, r0 = 2.886 } } (kcal/mol, Å)";
  const TomlTable e = t.requireTable("elements", shape);
  std::map<std::string, LjElement> out;
  for (const std::string& el : e.keys()) {
    if (std::find(species.begin(), species.end(), el) == species.end())
      e.fail(el, "element " + el + ", which is not in the cell", "elements of the cell only");
    const TomlTable p = e.requireTable(el, "{ epsilon = KCAL_PER_MOL, r0 = ANGSTROM }");
    p.allowOnly({"epsilon", "r0"});
    const double eps = p.number("epsilon", "a positive well depth (kcal/mol)");
    if (!(eps > 0.0)) p.fail("epsilon", fmt::format("{} kcal/mol", eps), "a positive well depth (kcal/mol)");
    const double r0 = p.number("r0", "a positive distance of the minimum (Å)");
    if (!(r0 > 0.0)) p.fail("r0", fmt::format("{} Å", r0), "a positive distance of the minimum (Å)");
    out[el] = {eps * units::kKcalPerMolInHartree, r0 * units::kAngstromInBohr};
  }
  for (const std::string& el : species)
    if (!out.count(el))
      t.fail("elements", "no entry for element " + el, std::string("an entry for every element of the cell: ") + shape);
  return out;
}

// parameters = "uff": the UFF values of every element of the cell.
std::map<std::string, LjElement> uffElements(const TomlTable& t, const std::vector<std::string>& species) {
  const char* uffName = "\"uff\" (the UFF set of Rappe et al. 1992)";
  const std::string name = t.string("parameters", uffName);
  if (name != "uff") t.fail("parameters", "\"" + name + "\"", uffName);
  std::map<std::string, LjElement> out;
  for (const std::string& el : species) {
    const auto uff = objective::uffParameters(el);
    if (!uff)
      t.fail("parameters",
             "element " + el + ", which has no UFF entry in mesochain's table (" + objective::uffElementRange() + ")",
             "elements = { " + el + " = { epsilon = ..., r0 = ... }, ... } with explicit values");
    out[el] = {uff->energyKcalPerMol * units::kKcalPerMolInHartree, uff->distanceAngstrom * units::kAngstromInBohr};
  }
  return out;
}

// The r^-6 tail: summation = "cutoff" | "ewald", with its tolerance.
void readSummation(const TomlTable& t, DispersionSettings& lj) {
  if (t.has("summation")) {
    const std::string s = t.string("summation", "\"cutoff\" or \"ewald\"");
    if (s != "cutoff" && s != "ewald") t.fail("summation", "\"" + s + "\"", "\"cutoff\" or \"ewald\"");
    lj.ewald = s == "ewald";
  }
  if (t.has("ewald_tolerance")) {
    if (!lj.ewald)
      t.fail("ewald_tolerance", "a tolerance with summation = \"cutoff\"",
             "ewald_tolerance only with summation = \"ewald\"");
    const double x = t.number("ewald_tolerance", "a relative tolerance in [1e-13, 1e-2]");
    if (!(x >= 1e-13 && x <= 1e-2))
      t.fail("ewald_tolerance", fmt::format("{}", x),
             "a relative tolerance in [1e-13, 1e-2] (tighter cannot be met in double precision)");
    lj.ewaldTolerance = x;
  }
}

// model = "lj": one of epsilon and r0 for every pair (defaults), parameters = "uff", or
// elements = {...}; then the cutoff and the summation of the tail.
void readLennardJones(const TomlTable& t, const std::vector<std::string>& species, DispersionTable& d) {
  DispersionSettings& lj = d.lj;
  lj.enabled = true;
  const char* sources = "one of: epsilon and r0 (every pair), parameters = \"uff\", or elements = { ... }";
  if (t.has("parameters") || t.has("elements")) {
    for (const char* k : {"epsilon", "r0"})
      if (t.has(k)) t.fail(k, std::string(k) + " together with per-element parameters", sources);
    if (t.has("parameters") && t.has("elements")) t.fail("elements", "both parameters and elements", sources);
  }
  if (t.has("parameters")) {
    d.ljParameters = "uff";
    setLjElements(lj, uffElements(t, species));
  } else if (t.has("elements")) {
    setLjElements(lj, readLjElements(t, species));
  } else {
    lj.epsilon = positive(t, "epsilon", kDefaultLjEpsilonKcalPerMol, "kcal/mol") * units::kKcalPerMolInHartree;
    lj.r0 = positive(t, "r0", kDefaultLjR0Angstrom, "Å") * units::kAngstromInBohr;
  }
  const double cutoff = positive(t, "cutoff", kDefaultLjCutoffAngstrom, "Å");
  if (cutoff > kMaximumLjCutoffAngstrom)
    t.fail("cutoff", fmt::format("{} Å", cutoff),
           fmt::format("a cutoff of at most {} Å (summation = \"ewald\" for the exact tail)", kMaximumLjCutoffAngstrom));
  lj.cutoff = cutoff * units::kAngstromInBohr;
  double largestR0 = lj.r0;
  for (double r0 : lj.elementR0) largestR0 = std::max(largestR0, r0);
  if (!(lj.cutoff > largestR0))
    t.fail(t.has("cutoff") ? "cutoff" : t.has("r0") ? "r0" : t.has("elements") ? "elements" : "parameters",
           fmt::format("cutoff {:.4g} Å <= r0 {:.4g} Å", cutoff, largestR0 * units::kBohrInAngstrom),
           "a cutoff well beyond r0 (default 30 Å)");
  readSummation(t, lj);
}

// TOML values of the entries.
toml::value real(double x) { return toml::value(x); }
toml::value angstrom(double bohr) { return toml::value(bohr * units::kBohrInAngstrom); }
toml::value kcalPerMol(double hartree) { return toml::value(hartree * units::kHartreeInKcalPerMol); }

}  // namespace

void setLjElements(DispersionSettings& settings, const std::map<std::string, LjElement>& elements) {
  settings.elements.clear();
  settings.elementEpsilon.clear();
  settings.elementR0.clear();
  for (const auto& [el, p] : elements) {
    settings.elements.push_back(el);
    settings.elementEpsilon.push_back(p.epsilon);
    settings.elementR0.push_back(p.r0);
  }
}

std::map<std::string, LjElement> ljElements(const DispersionSettings& settings) {
  std::map<std::string, LjElement> out;
  for (std::size_t k = 0; k < settings.elements.size(); ++k)
    out[settings.elements[k]] = {settings.elementEpsilon.at(k), settings.elementR0.at(k)};
  return out;
}

void readDispersionTable(const TomlTable& t, const std::vector<std::string>& species, DispersionTable& d) {
  d = DispersionTable{};
  // `parameters` and `cutoff` belong to both models: "uff" for lj, "kc2005" | "ouyang2018" for kc.
  t.allowOnly({"model", "epsilon", "r0", "parameters", "elements", "cutoff", "summation", "ewald_tolerance",
               "taper_start", "bond_cutoff"});
  const std::string model = t.string("model", kModels);
  if (model == "none") {
    for (const std::string& k : t.keys())
      if (k != "model") t.fail(k, "a value with model = \"none\"", "no parameters for \"none\"");
    return;
  }
  if (model != "lj" && model != "kc") t.fail("model", "\"" + model + "\"", kModels);
  for (const std::string& k : model == "lj" ? kKcOnlyKeys : kLjOnlyKeys)
    if (t.has(k))
      t.fail(k, fmt::format("a value with model = \"{}\"", model),
             fmt::format("only the keys of model = \"{}\" (docs/cell-file.md)", model));
  if (model == "kc") readKolmogorovCrespi(t, d.kc);
  else readLennardJones(t, species, d);
}

SettingEntries dispersionTableEntries(const DispersionTable& d) {
  // Every member of both settings named: a new one fails to compile here until it has its entry.
  const auto& [ljEnabled, epsilon, r0, ljCutoff, ewald, ewaldTolerance, elements, elementEpsilon, elementR0] = d.lj;
  const auto& [kcEnabled, kcParameters, kcCutoff, taperStart, bondCutoff] = d.kc;
  SettingEntries out{{"model", toml::value(d.model()), ""}};
  if (ljEnabled) {
    if (d.ljParameters == "uff") {
      out.push_back({"parameters", toml::value("uff"), ""});
    } else if (!elements.empty()) {
      for (std::size_t k = 0; k < elements.size(); ++k) {
        out.push_back({"elements." + elements[k] + ".epsilon", kcalPerMol(elementEpsilon.at(k)), "kcal/mol"});
        out.push_back({"elements." + elements[k] + ".r0", angstrom(elementR0.at(k)), "Å"});
      }
    } else {
      out.push_back({"epsilon", kcalPerMol(epsilon), "kcal/mol"});
      out.push_back({"r0", angstrom(r0), "Å"});
    }
    out.push_back({"cutoff", angstrom(ljCutoff), "Å"});
    out.push_back({"summation", toml::value(ewald ? "ewald" : "cutoff"), ""});
    if (ewald) out.push_back({"ewald_tolerance", real(ewaldTolerance), ""});
  } else if (kcEnabled) {
    out.push_back({"parameters", toml::value(kcParameters), ""});
    if (kcCutoff > 0.0) {  // else the parameter set's cutoff and taper start
      out.push_back({"cutoff", angstrom(kcCutoff), "Å"});
      out.push_back({"taper_start", angstrom(taperStart), "Å"});
    }
    out.push_back({"bond_cutoff", angstrom(bondCutoff), "Å"});
  }
  return out;
}

}  // namespace mesochain::dftb
