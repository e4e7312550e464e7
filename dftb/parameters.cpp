// ParameterSet::load: species data and pair tables from DFTB+ .skf files (see parameters.hpp).
#include "dftb/parameters.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "dftb/repulsive.hpp"
#include "dftb/sk_pair.hpp"
#include "dftb/skf_file.hpp"

namespace mesochain::dftb {

namespace {

const char* kShellNames[4] = {"s", "p", "d", "f"};

const std::string& fileFor(const std::map<std::string, std::string>& files, const std::string& a,
                           const std::string& b, const std::string& source) {
  const std::string key = a + "-" + b;
  const auto it = files.find(key);
  if (it == files.end()) {
    throw InputError(source, "Slater-Koster files", "no entry \"" + key + "\" for the pair " +
                                                        key,
                     "a file for every ordered species pair (" + key + ".skf)");
  }
  return it->second;
}

// Highest shell in use: the user's override, else the highest shell with non-zero occupation.
int maxShell(const SkfTable& t, const std::string& name,
             const std::map<std::string, int>& overrides, const std::string& source) {
  int lmax = 0;
  for (int l = 0; l < 4; ++l) {
    if (t.occupation[static_cast<std::size_t>(l)] != 0.0) lmax = l;
  }
  const auto it = overrides.find(name);
  const int l = it != overrides.end() ? it->second : lmax;
  const std::string where = it != overrides.end()
                                ? "maximum angular momentum of " + name
                                : "shell occupations of " + t.path;
  if (l < 0 || l > 3) {
    throw InputError(source, where, std::to_string(l), "s (0) or p (1)");
  }
  if (l >= 2 || lmax >= 2) {
    const int worst = std::max(l, lmax);
    throw InputError(source, where,
                     "species " + name + " with a " + kShellNames[worst] +
                         " shell (occupations s p d f: " + std::to_string(t.occupation[0]) + " " +
                         std::to_string(t.occupation[1]) + " " + std::to_string(t.occupation[2]) +
                         " " + std::to_string(t.occupation[3]) + ")",
                     worst == 2 ? "s and p shells only: d shells not supported yet"
                                : "s and p shells only: f shells (and d shells) not supported yet");
  }
  return l;
}

SpeciesData speciesFrom(const SkfTable& t, const std::string& name, int l) {
  SpeciesData s;
  s.name = name;
  s.maxAngularMomentum = l;
  s.orbitalCount = (l + 1) * (l + 1);
  s.onsiteS = t.onsite[0];
  s.onsiteP = t.onsite[1];
  s.hubbardU = t.hubbard[0];
  // As DFTB+ (parser.F90, readSKFiles): only the occupations of the shells in use count.
  for (int k = 0; k <= l; ++k) s.valenceElectrons += t.occupation[static_cast<std::size_t>(k)];
  s.mass = t.mass;
  return s;
}

bool sameSpline(const SplineRepulsiveData& a, const SplineRepulsiveData& b) {
  // Tolerance of DFTB+ (parser.F90, checkSKCompRepSpline).
  constexpr double tol = 1e-8;
  if (a.start.size() != b.start.size()) return false;
  if (std::abs(a.cutoff() - b.cutoff()) > tol) return false;
  for (std::size_t k = 0; k < 3; ++k) {
    if (std::abs(a.expHead[k] - b.expHead[k]) > tol) return false;
  }
  for (std::size_t i = 0; i < a.start.size(); ++i) {
    if (std::abs(a.start[i] - b.start[i]) > tol) return false;
    for (std::size_t k = 0; k < 6; ++k) {
      if (std::abs(a.coeffs[i][k] - b.coeffs[i][k]) > tol) return false;
    }
  }
  return true;
}

std::shared_ptr<const RadialPotential> repulsiveFrom(const SkfTable& ab, const SkfTable& ba,
                                                     bool polynomial, const std::string& pair) {
  if (polynomial) {
    if (ab.polynomial.c != ba.polynomial.c || ab.polynomial.cutoff != ba.polynomial.cutoff) {
      throw InputError(ab.path, "polynomial repulsive of the pair " + pair,
                       "coefficients different from those of " + ba.path,
                       "the same polynomial in both files");
    }
    return std::make_shared<PolynomialRepulsive>(ab.polynomial);
  }
  if (!ab.spline) {
    throw InputError(ab.path, "end of file", "no line 'Spline' (no spline repulsive)",
                     "a Spline block, or the pair " + pair + " listed as polynomial repulsive");
  }
  if (ba.spline && !sameSpline(*ab.spline, *ba.spline)) {
    throw InputError(ab.path, "line " + std::to_string(ab.splineLine),
                     "a spline repulsive different from that of " + ba.path + " (line " +
                         std::to_string(ba.splineLine) + ")",
                     "the same repulsive for " + pair + " in both files");
  }
  return std::make_shared<SplineRepulsive>(*ab.spline);
}

}  // namespace

ParameterSet ParameterSet::load(const std::vector<std::string>& species,
                                const std::map<std::string, std::string>& files,
                                const std::string& source,
                                const std::map<std::string, int>& maxAngularMomentum,
                                const std::set<std::string>& polynomialRepulsive) {
  if (species.empty()) throw InputError(source, "species", "no species", "at least one species");
  for (std::size_t i = 0; i < species.size(); ++i) {
    if (std::count(species.begin(), species.end(), species[i]) > 1) {
      throw InputError(source, "species", species[i] + " listed twice", "distinct species");
    }
  }
  for (const auto& [name, l] : maxAngularMomentum) {
    if (std::find(species.begin(), species.end(), name) == species.end()) {
      throw InputError(source, "maximum angular momentum",
                       "an entry for " + name + " (value " + std::to_string(l) + ")",
                       "only species in use");
    }
  }
  const int n = static_cast<int>(species.size());
  for (const std::string& pair : polynomialRepulsive) {
    bool known = false;
    for (const auto& a : species) {
      for (const auto& b : species) known = known || pair == a + "-" + b;
    }
    if (!known) {
      throw InputError(source, "polynomial repulsive", "the pair \"" + pair + "\"",
                       "a pair A-B of species in use");
    }
  }

  // tables[a * n + b] = A-B.skf
  std::vector<SkfTable> tables(static_cast<std::size_t>(n * n));
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      const std::string& path = fileFor(files, species[a], species[b], source);
      tables[static_cast<std::size_t>(a * n + b)] = readSkfFile(path, a == b);
    }
  }

  ParameterSet set;
  for (int a = 0; a < n; ++a) {
    const SkfTable& t = tables[static_cast<std::size_t>(a * n + a)];
    const int l = maxShell(t, species[a], maxAngularMomentum, source);
    set.species_.push_back(speciesFrom(t, species[a], l));
  }
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      const SkfTable& ab = tables[static_cast<std::size_t>(a * n + b)];
      const SkfTable& ba = tables[static_cast<std::size_t>(b * n + a)];
      const std::string pair = species[a] + "-" + species[b];
      set.integrals_.push_back(std::make_shared<SkPairIntegrals>(
          ab, ba, set.species_[a].maxAngularMomentum, set.species_[b].maxAngularMomentum));
      const bool poly = polynomialRepulsive.count(pair) > 0 ||
                        polynomialRepulsive.count(species[b] + "-" + species[a]) > 0;
      set.repulsive_.push_back(repulsiveFrom(ab, ba, poly, pair));
    }
  }
  return set;
}

double ParameterSet::integralCutoff() const {
  double c = 0.0;
  for (const auto& p : integrals_) c = std::max(c, p->cutoff());
  return c;
}

double ParameterSet::repulsiveCutoff() const {
  double c = 0.0;
  for (const auto& p : repulsive_) c = std::max(c, p->cutoff());
  return c;
}

}  // namespace mesochain::dftb
