// Inputs of the knobs' table (workflows/knobs.hpp): the finished scan with its relaxed
// structures, and the knob settings parsed from the command line or a chain file.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>

#include <fmt/format.h>

#include "workflows/knobs.hpp"

#include "common/errors.hpp"
#include "common/units.hpp"
#include "input/xyz_file.hpp"

namespace mesochain::workflows {

namespace fs = std::filesystem;

namespace {

// The deformation a relaxed structure stands for, from its symmetry alone (scan.hpp: stretch
// T = T0 (1 + eps); twist gamma = gamma0 + dgamma; bend 1/R = 2 pi / (N_a T0), T0 the arc per
// cell for a sector).
double deformationOf(const objective::ObjectiveCell& c, const std::string& kind, double t0,
                     double twist0) {
  const objective::Symmetry& s = c.symmetry;
  if (kind == "stretch") return s.translation() / t0 - 1.0;
  if (kind == "twist") return s.twist() - twist0;
  if (s.isRing() || s.rotationOrder() >= 2) return 2 * units::kPi / (s.rotationOrder() * t0);
  return 0.0;
}

std::string structureName(const std::string& prefix, std::size_t k) {
  return fmt::format("{}-{:03d}.xyz", prefix, k);
}

// A positive integer (or "all" when allowed: returned as 0).
int countValue(const KnobSource& where, const std::string& knob, const std::string& text,
               bool allowAll, const std::string& expected) {
  if (allowAll && text == "all") return 0;
  int n = 0;
  const char* end = text.data() + text.size();
  const auto [p, ec] = std::from_chars(text.data(), end, n);
  if (text.empty() || ec != std::errc() || p != end || n < 1)
    throw InputError(where.source, where.option(knob), "'" + text + "'", expected);
  return n;
}

double numberValue(const KnobSource& where, const std::string& knob, const std::string& text,
                   const std::string& expected) {
  double x = 0;
  const char* end = text.data() + text.size();
  const auto [p, ec] = std::from_chars(text.data(), end, x);
  if (text.empty() || ec != std::errc() || p != end || !std::isfinite(x) || !(x > 0))
    throw InputError(where.source, where.option(knob), "'" + text + "'", expected);
  return x;
}

// Sorts by accuracy, merges a listed setting equal to the scan's own one into it.
std::vector<KnobSetting> finish(std::vector<KnobSetting> listed, KnobSetting own) {
  own.own = true;
  std::vector<KnobSetting> out{own};
  for (KnobSetting& s : listed) {
    const bool seen = std::any_of(out.begin(), out.end(), [&](const KnobSetting& o) {
      return o.label == s.label;
    });
    if (!seen) out.push_back(std::move(s));
  }
  std::stable_sort(out.begin(), out.end(), [](const KnobSetting& a, const KnobSetting& b) {
    return a.accuracy < b.accuracy;
  });
  return out;
}

}  // namespace

FinishedScan readFinishedScan(const std::string& scanFile, const std::string& scanOutputDir) {
  FinishedScan f;
  f.input = objective::readScanFile(scanFile, scanOutputDir);
  const std::string& prefix = f.input.structurePrefix;
  if (prefix.empty())
    throw InputError(scanFile, "[output] structures", "no structures key",
                     "structures = \"PREFIX\" in [output], and the scan run with it, so that the "
                     "relaxed cells PREFIX-NNN.xyz exist (bench knobs re-evaluates them)");
  f.curve = beam::readScanTable(f.input.jsonPath);
  const std::size_t n = f.curve.points.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::string file = structureName(prefix, k);
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
      throw InputError(scanFile, "[output] structures = \"" + prefix + "\"",
                       fmt::format("no {} (point {} of the {} points of {})", file, k + 1, n,
                                   f.input.jsonPath),
                       "the relaxed cell of every curve point: run the scan with this "
                       "structures prefix");
    const objective::XyzFrame frame = objective::readXyzFile(file);
    if (!frame.hasSymmetry)
      throw InputError(file, "comment line", "no mesochain: symmetry keys",
                       "a relaxed cell written by mesochain scan");
    f.cells.push_back(frame.cell);
    f.structureFiles.push_back(file);
    if (k > 0 && frame.cell.atomCount() != f.cells[0].atomCount())
      throw InputError(file, "atom count", std::to_string(frame.cell.atomCount()),
                       fmt::format("{} as in {}", f.cells[0].atomCount(), f.structureFiles[0]));
  }
  std::error_code ec;
  if (fs::exists(structureName(prefix, n), ec))
    throw InputError(scanFile, "[output] structures = \"" + prefix + "\"",
                     fmt::format("{} beyond the {} points of {}", structureName(prefix, n), n,
                                 f.input.jsonPath),
                     "as many structures as curve points (the curve and the structures of one "
                     "run)");
  if (n == 0) throw InputError(f.input.jsonPath, "points", "no points", "a finished curve");

  const int atoms = f.cells[0].atomCount();
  if (f.curve.atomsPerCell % atoms != 0)
    throw InputError(f.input.jsonPath, "key atoms_per_cell", std::to_string(f.curve.atomsPerCell),
                     fmt::format("a multiple of the {} atoms of {}", atoms, f.structureFiles[0]));
  f.cellsPerSlice = f.curve.atomsPerCell / atoms;

  const std::string& kind = f.curve.kind;
  double twist0 = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < n; ++k)
    if (f.curve.points[k].deformation == 0.0) twist0 = f.cells[k].symmetry.twist();
  if (kind == "twist" && std::isnan(twist0))
    throw InputError(f.input.jsonPath, "points", "no point at deformation 0",
                     "the reference point of the twist scan");
  const double t0 = f.curve.cellLength;
  for (std::size_t k = 0; k < n; ++k) {
    const double want = f.curve.points[k].deformation;
    const double got = deformationOf(f.cells[k], kind, t0, twist0);
    if (!(std::abs(got - want) <= 1e-9 * std::max(1.0, std::abs(want))))
      throw InputError(f.structureFiles[k], "symmetry",
                       fmt::format("deformation {:.10g} {}", got, f.curve.deformationUnit),
                       fmt::format("{:.10g} as point {} of {} (structures of another run?)", want,
                                   k + 1, f.input.jsonPath));
    if (kind == "twist" && std::abs(f.cells[k].symmetry.translation() - t0) > 1e-9 * t0)
      throw InputError(f.structureFiles[k], "symmetry",
                       fmt::format("T = {:.10g} Bohr", f.cells[k].symmetry.translation()),
                       fmt::format("T0 = {:.10g} Bohr of {}", t0, f.input.jsonPath));
  }
  return f;
}

std::vector<KnobSetting> kpointSettings(const std::vector<std::string>& values, int own,
                                        const KnobSource& where) {
  auto make = [](int k) {
    return KnobSetting{"kpoints", std::to_string(k), static_cast<double>(k), false,
                       [k](dftb::CalculatorSettings& s, dftb::CalculatorSettings&) {
                         s.band.helicalKPoints = k;
                       }};
  };
  std::vector<KnobSetting> listed;
  for (const std::string& v : values)
    listed.push_back(make(countValue(where, "kpoints", v, false,
                                     "positive numbers of helical k-points, e.g. --kpoints 12,24,48")));
  return finish(std::move(listed), make(own));
}

std::vector<KnobSetting> angularSettings(const std::vector<std::string>& values, int own,
                                         const KnobSource& where) {
  // "all" (0) is exact: the most accurate.
  auto make = [](int mu) {
    return KnobSetting{"angular", mu == 0 ? "all" : std::to_string(mu),
                       mu == 0 ? std::numeric_limits<double>::infinity() : static_cast<double>(mu),
                       false,
                       [mu](dftb::CalculatorSettings& straight, dftb::CalculatorSettings& ring) {
                         straight.band.angular.samples = mu;
                         ring.band.angular.samples = mu;
                       }};
  };
  std::vector<KnobSetting> listed;
  for (const std::string& v : values)
    listed.push_back(make(countValue(where, "angular", v, true,
                                     "positive numbers of sampled angular quantum numbers or all, "
                                     "e.g. --angular 6,12,24")));
  return finish(std::move(listed), make(own));
}

std::vector<KnobSetting> samplingSettings(const std::vector<std::string>& values, int ownKpoints,
                                          int ownAngular, const KnobSource& where) {
  auto make = [](int k, int mu) {
    return KnobSetting{"sampling", fmt::format("{}:{}", k, mu == 0 ? std::string("all") : std::to_string(mu)),
                       static_cast<double>(k), false,
                       [k, mu](dftb::CalculatorSettings& straight, dftb::CalculatorSettings& ring) {
                         straight.band.helicalKPoints = k;
                         ring.band.angular.samples = mu;
                       }};
  };
  const std::string expected =
      "K:M pairs of helical k-points and ring angular samples, e.g. --sampling 12:6,24:12,48:24";
  std::vector<KnobSetting> listed;
  for (const std::string& v : values) {
    const auto colon = v.find(':');
    if (colon == std::string::npos) throw InputError(where.source, where.option("sampling"), "'" + v + "'", expected);
    listed.push_back(make(countValue(where, "sampling", v.substr(0, colon), false, expected),
                          countValue(where, "sampling", v.substr(colon + 1), true, expected)));
  }
  return finish(std::move(listed), make(ownKpoints, ownAngular));
}

std::vector<KnobSetting> dispersionSettings(const std::vector<std::string>& values,
                                            const dftb::DispersionSettings& own,
                                            const KnobSource& where) {
  // The largest distance of the minimum over the pairs (per-element parameters: the largest r0_A).
  double largest = own.r0;
  for (double r : own.elementR0) largest = std::max(largest, r);
  const double r0 = largest * units::kBohrInAngstrom;
  const std::string expected = fmt::format(
      "cutoff:R (the LJ pairs to R Å, R > {}) or ewald (the helical Ewald sum of the r^-6 tail "
      "to the cell file's tolerance) or ewald:TOLERANCE, e.g. "
      "--dispersion cutoff:20,cutoff:30,ewald",
      own.enabled ? fmt::format("r0 = {:g} Å", r0) : std::string("0"));
  auto cutoff = [](double angstrom) {
    return KnobSetting{"dispersion", fmt::format("cutoff:{:g}", angstrom), angstrom, false,
                       [angstrom](dftb::CalculatorSettings& a, dftb::CalculatorSettings& b) {
                         for (auto* s : {&a, &b}) {
                           s->dispersion.ewald = false;
                           s->dispersion.cutoff = angstrom * units::kAngstromInBohr;
                         }
                       }};
  };
  // Ewald settings rank above every cutoff, a tighter tolerance above a looser one.
  auto ewald = [](double tolerance, bool named) {
    return KnobSetting{"dispersion", named ? fmt::format("ewald:{:g}", tolerance) : "ewald",
                       1e12 - std::log10(tolerance), false,
                       [tolerance](dftb::CalculatorSettings& a, dftb::CalculatorSettings& b) {
                         for (auto* s : {&a, &b}) {
                           s->dispersion.ewald = true;
                           s->dispersion.ewaldTolerance = tolerance;
                         }
                       }};
  };
  std::vector<KnobSetting> listed;
  for (const std::string& v : values) {
    if (v == "ewald") {
      listed.push_back(ewald(own.ewaldTolerance, false));
    } else if (v.rfind("ewald:", 0) == 0) {
      const double tol = numberValue(where, "dispersion", v.substr(6), expected);
      if (tol < 1e-13 || tol > 1e-2) throw InputError(where.source, where.option("dispersion"), "'" + v + "'",
                                                      "an Ewald tolerance in [1e-13, 1e-2]");
      listed.push_back(ewald(tol, true));
    } else if (v.rfind("cutoff:", 0) == 0) {
      const double r = numberValue(where, "dispersion", v.substr(7), expected);
      if (!(r > r0)) throw InputError(where.source, where.option("dispersion"), "'" + v + "'", expected);
      listed.push_back(cutoff(r));
    } else {
      throw InputError(where.source, where.option("dispersion"), "'" + v + "'", expected);
    }
  }
  return finish(std::move(listed), own.ewald ? ewald(own.ewaldTolerance, false)
                                             : cutoff(own.cutoff * units::kBohrInAngstrom));
}

std::vector<KnobSetting> temperatureSettings(const std::vector<std::string>& values,
                                             double ownHartree, const KnobSource& where) {
  // The lowest temperature is nearest the zero-temperature ground state: ranked most accurate.
  auto make = [](double kelvin) {
    return KnobSetting{"temperature", fmt::format("{:g}", kelvin), -kelvin, false,
                       [kelvin](dftb::CalculatorSettings& a, dftb::CalculatorSettings& b) {
                         a.band.electronicTemperature = b.band.electronicTemperature =
                             kelvin * units::kBoltzmannHartreePerKelvin;
                       }};
  };
  std::vector<KnobSetting> listed;
  for (const std::string& v : values)
    listed.push_back(make(numberValue(where, "temperature", v,
                                      "positive electronic temperatures in K, e.g. "
                                      "--temperature 100,300,1000")));
  return finish(std::move(listed), make(ownHartree / units::kBoltzmannHartreePerKelvin));
}

}  // namespace mesochain::workflows
