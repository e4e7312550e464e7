// `mesochain beam bend-curve TABLES... [--window-nm RMIN,RMAX] [-o bend-curve-out]`: merges bend
// tables of one direction, anchors them at the straight reference and writes the secant and
// tangent stiffness against curvature (bend-curve.json, .csv, .png) with the quadratic regime
// marked and the warnings printed (docs/beam.md, "Bending beyond the quadratic regime").
#include "app/cmd_beam_bend.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_checks.hpp"
#include "beam/bend_curve.hpp"
#include "beam/bend_curve_report.hpp"
#include "beam/beam_run.hpp"
#include "beam/scan_table.hpp"
#include "common/units.hpp"
#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/finite_output.hpp"
#include "common/plot/png_io.hpp"
#include "common/units.hpp"
#include "input/xyz_file.hpp"

namespace mesochain::app {

namespace {
namespace fs = std::filesystem;

struct BendCurveOptions {
  std::vector<std::string> tables;
  std::optional<double> reference;  // Hartree per cell
  std::vector<double> windowNm;     // RMIN, RMAX
  double tolerance = 0.02;
  double noise = 0.0;
  bool measuredCurvature = false;
  std::vector<std::string> structures;  // one prefix per table: PREFIX-NNN.xyz of `mesochain scan`
  std::string outputDir = "bend-curve-out";
};

// The ring section of point `index` of a table from the scan's structure PREFIX-NNN.xyz; the
// file's ring order must give the point's nominal curvature 2 pi / (N_a T0).
beam::RingSection ringSection(const std::string& prefix, std::size_t index, const beam::ScanCurve& c,
                              const beam::ScanPoint& p) {
  const std::string file = fmt::format("{}-{:03d}.xyz", prefix, index);
  const objective::XyzFrame f = objective::readXyzFile(file);
  const int na = f.cell.symmetry.rotationOrder();
  const double nominal = 2.0 * units::kPi / (na * c.cellLength);
  if (!f.cell.symmetry.isRing() || std::abs(nominal - p.deformation) > 1e-6 * p.deformation)
    throw InputError(file, "mesochain:rotation_order",
                     fmt::format("{} ({}, curvature {:.9g} per Bohr)", na, f.cell.symmetry.isRing() ? "a ring" : "not a ring",
                                 nominal),
                     fmt::format("the ring of point {} of {} (curvature {:.9g} per Bohr)", index, c.source,
                                 p.deformation));
  return beam::measureRingSection(f.cell.positions);
}

int runBendCurve(const BendCurveOptions& o) {
  const std::string cl = "<command line>";
  std::vector<beam::ScanCurve> curves;
  for (const std::string& t : o.tables) curves.push_back(beam::readScanTable(t));
  std::optional<double> reference = o.reference;
  std::string referenceFrom = reference ? "--reference-hartree" : "";
  std::vector<beam::BendSample> rings;
  const beam::ScanCurve& first = curves.front();
  if (!o.structures.empty() && o.structures.size() != curves.size())
    throw InputError(cl, "--structures", fmt::format("{} prefixes for {} tables", o.structures.size(), curves.size()),
                     "one structure prefix per table, in the order of the tables");
  for (const beam::ScanCurve& c : curves) {
    if (c.kind != "bend")
      throw InputError(c.source, "key kind", "\"" + c.kind + "\"", "bend tables only");
    if (c.direction != first.direction || std::abs(c.cellLength - first.cellLength) > 1e-6 * first.cellLength)
      throw InputError(c.source, "keys direction and T0_bohr",
                       fmt::format("{} at T0 = {:.10g} Bohr", c.label(), c.cellLength),
                       fmt::format("{} at T0 = {:.10g} Bohr as in {}: one cell, one direction", first.label(),
                                   first.cellLength, first.source));
    if (const auto e = beam::straightReferenceEnergy(c)) {
      if (reference && std::abs(*e - *reference) > 1e-9 * std::abs(*e))
        throw InputError(c.source, "the point at curvature 0", fmt::format("{:.12g} Ha", *e),
                         fmt::format("the reference {:.12g} Ha of {} (one straight cell)", *reference, referenceFrom));
      if (!reference) reference = e, referenceFrom = c.source;
    }
    const std::size_t table = static_cast<std::size_t>(&c - curves.data());
    for (std::size_t index = 0; index < c.points.size(); ++index) {
      const beam::ScanPoint& p = c.points[index];
      if (!p.converged || p.deformation == 0.0) continue;
      const double k = o.measuredCurvature ? p.measuredCurvature : p.deformation;
      if (std::isnan(k))
        throw InputError(c.source, fmt::format("point at deformation {:.6g}", p.deformation),
                         "no measured_curvature_per_bohr", "a measured curvature (or drop --measured-curvature)");
      bool duplicate = false;
      for (const beam::BendSample& r : rings)
        if (std::abs(r.curvature - k) <= 1e-12 * k) {
          if (std::abs(r.energy - p.energy) > 1e-9 * std::abs(p.energy))
            throw InputError(c.source, fmt::format("point at curvature {:.9g}", k),
                             fmt::format("an energy of {:.12g} Ha", p.energy),
                             fmt::format("{:.12g} Ha as in an earlier table (one energy per curvature)", r.energy));
          duplicate = true;
        }
      if (duplicate) continue;
      beam::BendSample sample{k, p.energy};
      if (!o.structures.empty()) {
        const beam::RingSection r = ringSection(o.structures[table], index, c, p);
        sample.radialExtent = r.radialExtent;
        sample.meanSquareRadialOffset = r.meanSquareRadialOffset;
        sample.axialExtent = r.axialExtent;
      }
      rings.push_back(sample);
    }
  }
  if (!reference)
    throw InputError(cl, "reference energy", "no converged point at curvature 0 in the tables",
                     "the straight reference: a table with it, or --reference-hartree E (energy per cell)");
  beam::BendCurveOptions bo;
  bo.tolerance = o.tolerance;
  bo.energyNoise = o.noise;
  bo.source = first.source;
  bo.quantity = beam::curveConstant(first).name;
  if (!o.windowNm.empty()) {
    if (o.windowNm.size() != 2 || !(o.windowNm[0] > 0.0) || !(o.windowNm[1] > o.windowNm[0]))
      throw InputError(cl, "--window-nm", fmt::format("{} values", o.windowNm.size()),
                       "two radii RMIN,RMAX in nm with 0 < RMIN < RMAX");
    bo.window = std::make_pair(units::si::kBohrInNm / o.windowNm[1], units::si::kBohrInNm / o.windowNm[0]);
  }
  prepareOutputFolder(o.outputDir, cl, "option --output-dir");
  const beam::BendCurve curve = beam::analyseBendCurve(rings, *reference, bo);
  nlohmann::json j = beam::bendCurveJson(curve, first.label());
  j["reference_source"] = referenceFrom;
  j["tables"] = o.tables;
  const fs::path dir(o.outputDir);
  requireFiniteJson(j, (dir / "bend-curve.json").string());
  fs::create_directories(dir);
  const std::string png = (dir / "bend-curve.png").string();
  plot::writePng(png, beam::renderBendCurvePlot(
                          curve, fmt::format("{}: D(k), anchored at the straight reference",
                                             first.label())));
  j["files"] = {{"csv", (dir / "bend-curve.csv").string()}, {"plot", png}};
  writeFileAtomically((dir / "bend-curve.csv").string(), beam::bendCurveCsv(curve));
  writeFileAtomically((dir / "bend-curve.json").string(), j.dump(2) + "\n");

  const double f = beam::hartreeBohr2InEvNm2();
  std::cout << fmt::format("{}: {} rings, reference {:.10f} Ha ({})\n", first.label(), rings.size(), *reference,
                           referenceFrom);
  const bool sections = !o.structures.empty();
  std::cout << "  R (nm)      1/R (1/Bohr)   secant (eV nm2)  tangent (eV nm2)  quadratic"
            << (sections ? "  radial extent (Bohr)  <u2> (Bohr2)" : "") << "\n";
  for (const beam::BendCurvePoint& p : curve.points)
    std::cout << fmt::format("  {:<10.4g}  {:<13.6g}  {:<15.6g}  {:<16.6g}  {:<9}{}\n", units::si::kBohrInNm / p.sample.curvature,
                             p.sample.curvature, p.secant * f, p.tangent * f, p.quadratic ? "yes" : "no",
                             sections ? fmt::format("  {:<20.6g}  {:.6g}", p.sample.radialExtent,
                                                    p.sample.meanSquareRadialOffset)
                                      : "");
  std::cout << fmt::format("linear regime ({}): D_0 = {:.6g} +- {:.2g} eV nm2 over {} ring(s), R >= {:.4g} nm\n",
                           curve.quadraticVerified ? "verified" : "NOT verified", curve.linear.value * f,
                           curve.linear.error * f, curve.linear.points, units::si::kBohrInNm / curve.quadraticMaxCurvature);
  if (curve.hasQuartic)
    std::cout << fmt::format("quartic law U = D k^2/2 - c k^4 over all rings: D = {:.6g} eV nm2, c = {:.6g} Ha Bohr^4\n",
                             curve.quarticStiffness.value * f, curve.quarticCoefficient);
  if (curve.window)
    std::cout << fmt::format("window R = {:.4g}..{:.4g} nm: D = {:.6g} +- {:.2g} eV nm2 over {} ring(s){}\n",
                             o.windowNm[0], o.windowNm[1], curve.window->stiffness.value * f,
                             curve.window->stiffness.error * f, curve.window->stiffness.points,
                             curve.window->quadratic ? "" : " (not a linear-regime constant)");
  for (const std::string& w : curve.warnings) std::cerr << "warning: " << w << "\n";
  std::cout << "wrote " << (dir / "bend-curve.json").string() << ", " << (dir / "bend-curve.csv").string() << ", "
            << png << "\n";
  return 0;
}

}  // namespace

CLI::Validator anyFiniteNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !std::isfinite(v))
          return fmt::format("found {}; expected a finite number", text);
        return {};
      },
      "NUMBER");
}

SubcommandHooks attachBendCurveCommand(CLI::App& beamApp) {
  auto o = std::make_shared<BendCurveOptions>();
  CLI::App* s = beamApp.add_subcommand(
      "bend-curve", "secant and tangent bending stiffness against curvature, anchored at the straight reference");
  s->add_option("tables", o->tables, "bend tables of one direction (.json, .csv), merged")->required();
  s->add_option("--reference-hartree", o->reference,
                "energy per cell of the straight reference (when no table has the point at curvature 0)")
      ->check(anyFiniteNumber());
  s->add_option("--window-nm", o->windowNm, "a constant over the rings with RMIN <= R <= RMAX (nm): RMIN,RMAX")
      ->delimiter(',')
      ->expected(2);
  s->add_option("--tolerance", o->tolerance, "relative tolerance of the quadratic regime (default 0.02)")
      ->check(finiteNumber(false, 1.0));
  s->add_option("--energy-noise-hartree", o->noise, "standard deviation of one energy (default 0: exact)")
      ->check(finiteNumber(true));
  s->add_flag("--measured-curvature", o->measuredCurvature, "use the curvature measured from the relaxed atoms");
  s->add_option("--structures", o->structures,
                "per table, the structure prefix of its scan ([output] structures): ring cross-sections")
      ->check(nonEmptyPath());
  s->add_option("-o,--output-dir", o->outputDir, "folder for bend-curve.json, .csv, .png")->check(nonEmptyPath());
  SubcommandHooks h;
  h.selected = [s] { return s->parsed(); };
  h.run = [o] { return runBendCurve(*o); };
  return h;
}

}  // namespace mesochain::app
