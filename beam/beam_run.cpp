#include "beam/beam_run.hpp"

#include <array>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <toml.hpp>

#include "common/units.hpp"
#include "common/errors.hpp"
#include "common/toml_file.hpp"
#include "common/toml_table.hpp"

namespace mesochain::beam {

namespace {

using nlohmann::json;

// The four constants by slot: 0 C, 1 K, 2 D_s, 3 D_h.
constexpr std::array<const char*, 4> kNames = {"C", "K", "D_s", "D_h"};
constexpr std::array<const char*, 4> kKeys = {"C_hartree", "K_hartree_per_rad2", "D_soft_hartree_bohr2",
                                              "D_hard_hartree_bohr2"};

// The slot of the constant a curve gives (curveConstant decides which).
int slotOf(const ScanCurve& c) {
  const std::string key = curveConstant(c).key;
  int s = 0;
  while (s < 3 && key != kKeys[s]) ++s;
  return s;
}

double& slot(BeamConstants& c, int i) {
  switch (i) {
    case 0: return c.stretch;
    case 1: return c.twist;
    case 2: return c.bendSoft;
    default: return c.bendHard;
  }
}

json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json fitReport(const QuadraticFit& f) {
  json j;
  j["window_half_width"] = f.windowHalfWidth;
  j["points_used"] = f.pointsUsed;
  j["points_total"] = f.pointsTotal;
  j["statistical_error"] = f.statisticalError;
  j["truncation_error"] = f.truncationError;
  j["window_spread"] = f.windowSpread;
  j["slope_hartree_per_unit"] = f.slope;
  j["slope_error"] = f.slopeError;
  j["energy0_hartree"] = f.energy0;
  j["energy0_anchored"] = f.anchored;
  j["regime_verified"] = f.regimeVerified;
  j["note"] = f.note;
  json w = json::array();
  for (const WindowFit& x : f.windows)
    w.push_back({{"half_width", x.halfWidth}, {"points", x.points}, {"stiffness", x.stiffness},
                 {"standard_error", x.standardError}, {"anharmonicity", number(x.hasExtended ? x.anharmonicity : NAN)},
                 {"accepted", x.accepted}, {"rejection", x.rejection}});
  j["windows"] = w;
  return j;
}

json beamReport(const Beam& b, const std::optional<BeamConstants>& sigma) {
  const double nm = units::si::kBohrInNm, gpa = units::si::kHartreePerBohr3InMPa * 1e-3;
  json j;
  j["shape"] = b.shape;
  j["closure"] = b.closure;
  j["young_modulus_hartree_per_bohr3"] = b.young;
  j["young_modulus_GPa"] = b.young * gpa;
  j["shear_modulus_hartree_per_bohr3"] = b.shear;
  j["shear_modulus_GPa"] = b.shear * gpa;
  if (b.shape == "rectangle") {
    j["thickness_bohr"] = b.thickness;
    j["thickness_nm"] = b.thickness * nm;
    j["width_bohr"] = b.width;
    j["width_nm"] = b.width * nm;
  } else {
    j["radius_bohr"] = b.radius;
    j["radius_nm"] = b.radius * nm;
    if (b.shape == "annulus") j["wall_bohr"] = b.wall, j["wall_nm"] = b.wall * nm;
  }
  j["T0_bohr"] = b.cellLength;
  j["area_bohr2"] = b.section.area;
  j["I_x_bohr4"] = b.section.ix;
  j["I_y_bohr4"] = b.section.iy;
  j["J_z_bohr4"] = b.section.polar;
  j["area_nm2"] = b.section.area * nm * nm;
  j["I_x_nm4"] = b.section.ix * std::pow(nm, 4);
  j["I_y_nm4"] = b.section.iy * std::pow(nm, 4);
  j["J_z_nm4"] = b.section.polar * std::pow(nm, 4);
  j["relative_residuals"] = {{"C", number(b.residuals.stretch)}, {"K", number(b.residuals.twist)},
                             {"D_s", number(b.residuals.bendSoft)}, {"D_h", number(b.residuals.bendHard)}};
  if (sigma) {
    // Standard uncertainties propagated from the constants (first order, independent).
    j["uncertainty"] = {{"young_modulus_GPa", sigma->stretch * gpa}, {"shear_modulus_GPa", sigma->twist * gpa},
                        {b.shape == "rectangle" ? "thickness_nm" : "radius_nm", sigma->bendSoft * nm}};
    if (b.shape == "rectangle") j["uncertainty"]["width_nm"] = sigma->bendHard * nm;
  }
  return j;
}

json brickReport(const Brick& b) {
  const double nm = units::si::kBohrInNm, ag = units::si::kDaltonInAttogram;
  json j;
  j["cells_per_brick"] = b.cellsPerBrick;
  j["length_bohr"] = b.length;
  j["length_nm"] = b.length * nm;
  j["mass_dalton"] = b.mass;
  j["mass_ag"] = b.mass * ag;
  j["principal_inertia_dalton_bohr2"] = {b.inertia.x(), b.inertia.y(), b.inertia.z()};
  j["principal_inertia_ag_nm2"] = {b.inertia.x() * ag * nm * nm, b.inertia.y() * ag * nm * nm,
                                   b.inertia.z() * ag * nm * nm};
  j["k_n_hartree_per_bohr4"] = b.normalStiffness;
  j["k_s_hartree_per_bohr4"] = b.shearStiffness;
  j["k_n_MPa_per_nm"] = b.normalStiffness * units::si::kHartreePerBohr4InMPaPerNm;
  j["k_s_MPa_per_nm"] = b.shearStiffness * units::si::kHartreePerBohr4InMPaPerNm;
  j["bond_section"] = {{"area_nm2", b.section.area * nm * nm}, {"I_x_nm4", b.section.ix * std::pow(nm, 4)},
                       {"I_y_nm4", b.section.iy * std::pow(nm, 4)}, {"J_z_nm4", b.section.polar * std::pow(nm, 4)}};
  if (b.radius > 0.0) j["equivalent_cylinder_radius_nm"] = b.radius * nm;
  return j;
}

Beam closeBeam(const BeamConstants& c, const std::string& section, const std::string& closure,
               std::optional<double> thickness, double wall, const std::string& source) {
  if (section == "circle") return solidCircle(c, source);
  if (section == "annulus") return annulus(c, wall, source);
  if (closure == "measured_thickness") {
    if (!thickness)
      throw InputError(source, "closure measured_thickness", "no measured thickness",
                       "thickness_bohr in a scan table, or a thickness in the constants file or flags");
    return rectangleMeasuredThickness(c, *thickness, source);
  }
  return rectangleFourConstants(c, source);
}

// The quantities whose uncertainty is propagated, packed in a BeamConstants for brevity:
// (Y, G, h or r, w).
BeamConstants packed(const Beam& b) {
  BeamConstants p;
  p.stretch = b.young;
  p.twist = b.shear;
  p.bendSoft = b.shape == "rectangle" ? b.thickness : b.radius;
  p.bendHard = b.width;
  return p;
}

}  // namespace

std::optional<double> straightReferenceEnergy(const ScanCurve& c) {
  for (const ScanPoint& p : c.points)
    if (p.converged && p.deformation == 0.0) return p.energy;
  return std::nullopt;
}

FittedCurve fitScanCurve(const ScanCurve& c, const std::string& quantity, const std::string& reportKey,
                         double tolerance, const std::string& linearTerm, bool measuredCurvature,
                         const BendAnchor& anchor) {
  if (anchor.offset != "anchored" && anchor.offset != "free")
    throw InputError(c.source, "bend offset", "\"" + anchor.offset + "\"", "anchored or free");
  FittedCurve fc;
  fc.quantity = quantity;
  fc.reportKey = reportKey;
  fc.label = c.label();
  fc.source = c.source;
  fc.deformationUnit = c.deformationUnit;
  for (const ScanPoint& p : c.points) {
    if (!p.converged) {
      ++fc.unconvergedSkipped;
      continue;
    }
    double x = p.deformation;
    if (measuredCurvature && c.kind == "bend") {
      if (std::isnan(p.measuredCurvature))
        throw InputError(c.source, fmt::format("point at deformation {:.6g}", p.deformation),
                         "no measured_curvature_per_bohr", "a measured curvature for every point (or drop --measured-curvature)");
      x = p.measuredCurvature;
    }
    fc.points.push_back({x, p.energy});
  }
  fc.options.source = c.source;
  fc.options.quantity = quantity;
  fc.options.relativeTolerance = tolerance;
  fc.options.linearTerm = linearTerm == "on" || (linearTerm == "auto" && c.kind != "bend");
  if (c.kind == "bend" && anchor.offset == "anchored") {
    const std::optional<double> own = straightReferenceEnergy(c);
    if (own && anchor.referenceEnergy && std::abs(*own - *anchor.referenceEnergy) > 1e-9 * std::abs(*own))
      throw InputError(c.source, "the point at curvature 0",
                       fmt::format("the straight reference at {:.12g} Ha", *own),
                       fmt::format("the given reference energy {:.12g} Ha (one straight cell per curve)",
                                   *anchor.referenceEnergy));
    fc.options.anchorEnergy = own ? own : anchor.referenceEnergy;
    if (!fc.options.anchorEnergy)
      fc.warnings.push_back(
          "no straight reference (a converged point at curvature 0) and no reference energy given: "
          "U(0) is fitted as a free offset, which can absorb a curve that is not quadratic "
          "(give --bend-reference-hartree)");
  }
  fc.fit = fitQuadraticRegime(fc.points, fc.options);
  return fc;
}

BeamRun runBeam(const BeamInputs& in) {
  const std::string& src = in.source;
  if (in.cellsPerBrick < 1)
    throw InputError(src, "cells per brick", std::to_string(in.cellsPerBrick), "an integer >= 1 (--cells-per-brick)");
  if (in.section != "rectangle" && in.section != "circle" && in.section != "annulus")
    throw InputError(src, "section", "\"" + in.section + "\"", "rectangle, circle or annulus");
  if (in.closure != "four_constants" && in.closure != "measured_thickness")
    throw InputError(src, "closure", "\"" + in.closure + "\"", "four_constants or measured_thickness");
  if (in.linearTerm != "auto" && in.linearTerm != "on" && in.linearTerm != "off")
    throw InputError(src, "linear term", "\"" + in.linearTerm + "\"", "auto, on or off");

  BeamRun run;
  json& report = run.report;
  report["format"] = 1;
  std::array<bool, 4> have{};
  std::array<std::string, 4> from;
  std::optional<double> t0 = in.cellLength;
  std::optional<int> atoms = in.atomsPerCell;
  std::string t0From = t0 ? src : "", atomsFrom = atoms ? src : "";
  std::optional<double> thickness = in.thickness;
  json constants = json::object();

  for (const ScanCurve& c : in.curves) {
    const int s = slotOf(c);
    if (have[s])
      throw InputError(c.source, fmt::format("a second {} curve (the first is {})", c.label(), from[s]));
    if (t0 && std::abs(*t0 - c.cellLength) > 1e-6 * *t0)
      throw InputError(c.source, "key T0_bohr", fmt::format("{:.10g}", c.cellLength),
                       fmt::format("the T0 of {} ({:.10g} Bohr): all curves belong to one cell", t0From, *t0));
    if (!t0) t0 = c.cellLength, t0From = c.source;
    if (atoms && *atoms != c.atomsPerCell)
      throw InputError(c.source, "key atoms_per_cell", std::to_string(c.atomsPerCell),
                       fmt::format("{} as in {}", *atoms, atomsFrom));
    if (!atoms) atoms = c.atomsPerCell, atomsFrom = c.source;
    if (!in.thickness && !std::isnan(c.thickness) && !thickness) thickness = c.thickness;

    FittedCurve fc =
        fitScanCurve(c, kNames[s], kKeys[s], in.tolerance, in.linearTerm, in.measuredCurvature, in.bendAnchor);
    const QuadraticFit& f = fc.fit;
    slot(run.constants, s) = f.stiffness;
    slot(run.uncertainties, s) = f.uncertainty;
    have[s] = true;
    from[s] = c.source;
    json j = {{"value", f.stiffness}, {"uncertainty", f.uncertainty}, {"source", c.source},
              {"curve", c.label()}, {"deformation_unit", c.deformationUnit},
              {"linear_term", fc.options.linearTerm}, {"unconverged_points_skipped", fc.unconvergedSkipped},
              {"fit", fitReport(f)}};
    if (c.kind == "bend") j["offset"] = f.anchored ? "anchored" : "free";
    if (!fc.warnings.empty()) j["warnings"] = fc.warnings;
    if (!std::isnan(c.width)) j["measured_width_bohr"] = c.width;
    constants[kKeys[s]] = j;
    run.curves.push_back(std::move(fc));
  }
  const std::array<const std::optional<GivenConstant>*, 4> given = {&in.stretch, &in.twist, &in.bendSoft,
                                                                    &in.bendHard};
  for (int s = 0; s < 4; ++s) {
    if (!*given[s]) continue;
    const GivenConstant& g = **given[s];
    if (have[s])
      throw InputError(g.source, fmt::format("{} is given here and fitted from {}", kNames[s], from[s]),
                       "", "one source per constant");
    slot(run.constants, s) = g.value;
    slot(run.uncertainties, s) = g.uncertainty;
    have[s] = true;
    from[s] = g.source;
    constants[kKeys[s]] = {{"value", g.value}, {"uncertainty", g.uncertainty}, {"source", g.source}};
  }
  json warnings = json::array();
  for (const FittedCurve& fc : run.curves)
    for (const std::string& w : fc.warnings) warnings.push_back(fc.source + ": " + w);
  if (!warnings.empty()) report["warnings"] = warnings;
  if (!t0) throw InputError(src, "T0", "no cell length", "T0_bohr from a scan table or the constants");
  run.constants.cellLength = *t0;
  run.uncertainties.cellLength = 0.0;
  constants["T0_bohr"] = *t0;
  report["constants"] = constants;

  // Which constants the section needs.
  std::vector<int> needed = {0, 1};
  if (in.section == "rectangle") {
    needed.push_back(2), needed.push_back(3);
  } else if (!have[2] && have[3]) {
    run.constants.bendSoft = run.constants.bendHard;  // one D for a round section
    run.uncertainties.bendSoft = run.uncertainties.bendHard;
    have[2] = true;
  } else {
    needed.push_back(2);
  }
  std::string missing;
  for (int s : needed)
    if (!have[s]) missing += std::string(missing.empty() ? "" : ", ") + kNames[s];
  if (!missing.empty())
    throw InputError(src, "constants", "no " + missing,
                     "a scan table or a given value for each of " +
                         std::string(in.section == "rectangle" ? "C, K, D_s, D_h" : "C, K, D"));

  run.beam = closeBeam(run.constants, in.section, in.closure, thickness, in.wall, src);
  // First-order propagation of the constants' uncertainties to Y, G, h (r), w.
  BeamConstants sigma;
  BeamConstants base = packed(run.beam);
  for (int s = 0; s < 4; ++s) {
    const double u = slot(run.uncertainties, s);
    if (!(u > 0.0) || (s == 2 && in.section == "rectangle" && in.closure == "measured_thickness")) continue;
    BeamConstants c = run.constants;
    slot(c, s) += u;
    try {
      BeamConstants p = packed(closeBeam(c, in.section, in.closure, thickness, in.wall, src));
      for (int q = 0; q < 4; ++q) slot(sigma, q) = std::hypot(slot(sigma, q), slot(p, q) - slot(base, q));
    } catch (const InputError&) {
      // A perturbation beyond the closure's domain (e.g. an annulus wall): leave it out.
    }
  }
  report["beam"] = beamReport(run.beam, sigma);
  if (thickness) report["measured_thickness_bohr"] = *thickness;
  if (in.section == "rectangle" && thickness) {
    const std::string other = in.closure == "four_constants" ? "measured_thickness" : "four_constants";
    run.alternatives.push_back(closeBeam(run.constants, "rectangle", other, thickness, in.wall, src));
    report["alternatives"] = json::array({beamReport(run.alternatives.back(), std::nullopt)});
    const double hFit = in.closure == "four_constants" ? run.beam.thickness : run.alternatives.back().thickness;
    report["thickness_ratio_fitted_over_measured"] = hFit / *thickness;
  }

  double cellMass = 0.0;
  if (in.cellMass) {
    cellMass = *in.cellMass;
  } else {
    if (!atoms) throw InputError(src, "atoms per cell", "nothing", "atoms_per_cell (or cell_mass_dalton)");
    cellMass = *atoms * units::si::kCarbonMassDalton;
  }
  run.brick = discretise(run.beam, in.cellsPerBrick, cellMass, src);
  report["brick"] = brickReport(run.brick);
  report["brick"]["cell_mass_dalton"] = cellMass;
  return run;
}

void readConstantsFile(const std::string& path, BeamInputs& in) {
  const toml::value data = parseTomlFile(path, "constants file");
  const TomlTable root(path, data, "");
  const double a2b = units::kAngstromInBohr, ev2ha = units::kEvInHartree;
  // Each quantity in any one of its units: key and factor to atomic units.
  using Units = TomlTable::UnitKeys;
  const Units stretch = {{"C_hartree", 1}, {"C_eV", ev2ha}};
  const Units twist = {{"K_hartree_per_rad2", 1}, {"K_eV_per_rad2", ev2ha}};
  const Units bendSoft = {{"D_soft_hartree_bohr2", 1}, {"D_soft_eV_angstrom2", ev2ha * a2b * a2b}};
  const Units bendHard = {{"D_hard_hartree_bohr2", 1}, {"D_hard_eV_angstrom2", ev2ha * a2b * a2b}};
  const Units cellLength = {{"T0_bohr", 1}, {"T0_angstrom", a2b}};
  const Units cellMass = {{"cell_mass_dalton", 1}};
  const Units thickness = {{"thickness_bohr", 1}, {"thickness_angstrom", a2b}};
  std::vector<std::string> allowed = {"format", "atoms_per_cell", "cells_per_brick"};
  for (const Units* q : {&stretch, &twist, &bendSoft, &bendHard, &cellLength, &cellMass, &thickness})
    for (const auto& [key, factor] : *q) allowed.push_back(key);
  root.allowOnly(allowed);
  if (root.integer("format", "format = 1") != 1) root.fail("format", describe(root.at("format")), "format = 1");
  auto quantity = [&](const Units& q) { return root.positiveQuantity(q); };
  auto count = [&](const std::string& key, long long limit) -> std::optional<int> {
    if (!root.has(key)) return std::nullopt;
    return static_cast<int>(root.integerIn(key, 1, static_cast<long>(limit)));
  };
  const std::array<std::pair<const Units*, std::optional<GivenConstant>*>, 4> constants = {
      {{&stretch, &in.stretch}, {&twist, &in.twist}, {&bendSoft, &in.bendSoft}, {&bendHard, &in.bendHard}}};
  for (const auto& [q, target] : constants)
    if (const auto x = quantity(*q)) *target = GivenConstant{*x, 0.0, path};
  if (const auto x = quantity(cellLength)) in.cellLength = x;
  if (const auto x = quantity(cellMass)) in.cellMass = x;
  if (const auto x = quantity(thickness)) in.thickness = x;
  if (const auto n = count("atoms_per_cell", kMaxAtomsPerCell)) in.atomsPerCell = n;
  if (const auto n = count("cells_per_brick", kMaxCellsPerBrick)) in.cellsPerBrick = *n;
}

}  // namespace mesochain::beam
