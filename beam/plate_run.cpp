#include "beam/plate_run.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>
#include <toml.hpp>

#include "beam/plate.hpp"
#include "common/errors.hpp"
#include "common/toml_file.hpp"
#include "common/toml_table.hpp"
#include "common/units.hpp"

namespace mesochain::beam {

namespace {

using nlohmann::json;
constexpr double kEv = units::kHartreeInEv;
constexpr double kNPerMInEvPerAngstrom2 = 1.0 / 16.02176634;  // 1 eV/Å^2 = 16.02176634 N/m

double toEvPerAngstrom2(double hartreePerBohr2) {
  return hartreePerBohr2 * kEv / (units::kBohrInAngstrom * units::kBohrInAngstrom);
}

}  // namespace

PlateRun runPlate(const PlateInputs& in) {
  const std::string& src = in.source;
  auto positive = [&](double x, const char* what, const char* expected) {
    if (!(x > 0.0) || !std::isfinite(x)) throw InputError(src, what, fmt::format("{:.6g}", x), expected);
  };
  positive(in.inPlaneStiffness, "in-plane stiffness C2", "a value > 0 (in_plane_stiffness_*)");
  positive(in.spacing, "interlayer spacing Z0", "a value > 0 (interlayer_spacing_*)");
  if (!(in.poisson > -1.0 && in.poisson < 1.0))
    throw InputError(src, "poisson_ratio", fmt::format("{:.6g}", in.poisson), "-1 < nu < 1 (two-dimensional)");

  PlateRun run;
  std::map<int, std::string> seen;
  for (const PlateStack& s : in.stacks) {
    if (s.layers < 1)
      throw InputError(s.source, "layers", std::to_string(s.layers), "an integer >= 1");
    if (seen.count(s.layers))
      throw InputError(s.source, fmt::format("a second stack of {} layers", s.layers), "",
                       "one stack per N (the first is in " + seen[s.layers] + ")");
    seen[s.layers] = s.source;
    if (s.scan.has_value() == s.rigidity.has_value())
      throw InputError(s.source, fmt::format("stack of {} layers", s.layers),
                       s.scan ? "both a scan and a rigidity" : "neither a scan nor a rigidity",
                       "exactly one of scan = \"table.json\" and rigidity_eV");
    PlateStackResult r;
    r.layers = s.layers;
    r.spacing = s.spacing.value_or(in.spacing);
    if (s.rigidity) {
      positive(s.rigidity->value, "rigidity", "a rigidity > 0");
      r.rigidity = s.rigidity->value;
      r.uncertainty = s.rigidity->uncertainty;
      r.source = s.rigidity->source;
    } else {
      const ScanCurve& c = *s.scan;
      if (c.kind != "bend")
        throw InputError(c.source, "key kind", "\"" + c.kind + "\"", "a bend table for a stack's rigidity");
      double area = 0.0;
      if (s.areaPerCell) {
        area = *s.areaPerCell;
      } else if (!std::isnan(c.width)) {
        area = c.cellLength * c.width;
      } else {
        throw InputError(c.source, "key width_bohr", "nothing",
                         "the width of the sheet per cell (width_bohr in the table, or area_per_cell_angstrom2 in the "
                         "stack of " + s.source + ")");
      }
      FittedCurve fc = fitScanCurve(c, "D", "D_hartree_bohr2", in.tolerance,
                                    "off", in.measuredCurvature);
      fc.label = fmt::format("bend, {} layer{}", s.layers, s.layers == 1 ? "" : "s");
      r.rigidity = fc.fit.stiffness / area;
      r.uncertainty = fc.fit.uncertainty / area;
      r.source = c.source;
      r.curve = std::move(fc);
      r.areaPerCell = area;
    }
    run.stacks.push_back(std::move(r));
  }
  std::sort(run.stacks.begin(), run.stacks.end(), [](const auto& a, const auto& b) { return a.layers < b.layers; });

  std::string d1From;
  if (in.singleLayer) {
    positive(in.singleLayer->value, "single_layer_rigidity", "a value > 0");
    run.singleLayer = in.singleLayer->value;
    run.singleLayerUncertainty = in.singleLayer->uncertainty;
    d1From = in.singleLayer->source;
  } else if (!run.stacks.empty() && run.stacks.front().layers == 1) {
    run.singleLayer = run.stacks.front().rigidity;
    run.singleLayerUncertainty = run.stacks.front().uncertainty;
    d1From = "the 1-layer stack (" + run.stacks.front().source + ")";
  } else {
    throw InputError(src, "single-layer rigidity D1", "nothing",
                     "single_layer_rigidity_eV, or a stack with layers = 1");
  }

  int nMax = in.maxLayers > 0 ? in.maxLayers : 6;
  if (in.maxLayers <= 0)
    for (const auto& s : run.stacks) nMax = std::max(nMax, s.layers);
  for (int n = 1; n <= nMax; ++n) {
    run.layers.push_back(n);
    run.bonded.push_back(plateBendingRigidity(n, in.inPlaneStiffness, in.spacing, in.poisson, run.singleLayer));
    run.sliding.push_back(slidingLayersRigidity(n, run.singleLayer));
  }

  // Report (energies in eV and Hartree; a plate rigidity is an energy).
  json& rep = run.report;
  rep["format"] = 1;
  rep["formula"] = "bonded: D = N D1 + C2 Z0^2 N (N^2 - 1) / (12 (1 - nu^2)); sliding: D = N D1";
  rep["inputs"] = {{"in_plane_stiffness_eV_per_angstrom2", toEvPerAngstrom2(in.inPlaneStiffness)},
                   {"in_plane_stiffness_N_per_m", toEvPerAngstrom2(in.inPlaneStiffness) / kNPerMInEvPerAngstrom2},
                   {"interlayer_spacing_angstrom", in.spacing * units::kBohrInAngstrom},
                   {"poisson_ratio", in.poisson},
                   {"single_layer_rigidity_eV", run.singleLayer * kEv},
                   {"single_layer_rigidity_uncertainty_eV", run.singleLayerUncertainty * kEv},
                   {"single_layer_rigidity_source", d1From}};
  rep["curves"] = {{"layers", run.layers}, {"bonded_eV", json::array()}, {"sliding_eV", json::array()}};
  for (std::size_t i = 0; i < run.layers.size(); ++i) {
    rep["curves"]["bonded_eV"].push_back(run.bonded[i] * kEv);
    rep["curves"]["sliding_eV"].push_back(run.sliding[i] * kEv);
  }
  json stacks = json::array();
  for (const PlateStackResult& s : run.stacks) {
    // The stack's bonded bound uses its own measured spacing when given (layers of thicker
    // stacks sit closer: 3.39 Å for two layers, 3.36 Å on average for six with LJ dispersion).
    const double bonded = plateBendingRigidity(s.layers, in.inPlaneStiffness, s.spacing, in.poisson, run.singleLayer);
    const double sliding = slidingLayersRigidity(s.layers, run.singleLayer);
    json j = {{"layers", s.layers}, {"rigidity_eV", s.rigidity * kEv}, {"uncertainty_eV", s.uncertainty * kEv},
              {"source", s.source}, {"bonded_eV", bonded * kEv}, {"sliding_eV", sliding * kEv},
              {"ratio_to_bonded", s.rigidity / bonded}, {"ratio_to_sliding", s.rigidity / sliding},
              {"interlayer_spacing_angstrom", s.spacing * units::kBohrInAngstrom}};
    // 0: layers slide freely, 1: bonded plate (the share of the membrane term that is met).
    j["bonded_fraction"] = s.layers > 1 ? json((s.rigidity - sliding) / (bonded - sliding)) : json(nullptr);
    if (s.curve) {
      const double area = s.areaPerCell;
      j["fit"] = {{"D_cell_hartree_bohr2", s.curve->fit.stiffness},
                  {"D_cell_uncertainty_hartree_bohr2", s.curve->fit.uncertainty},
                  {"area_per_cell_angstrom2", area * units::kBohrInAngstrom * units::kBohrInAngstrom},
                  {"window_half_width_per_bohr", s.curve->fit.windowHalfWidth},
                  {"points_used", s.curve->fit.pointsUsed},
                  {"points_total", s.curve->fit.pointsTotal},
                  {"unconverged_points_skipped", s.curve->unconvergedSkipped},
                  {"note", s.curve->fit.note}};
    }
    stacks.push_back(j);
  }
  rep["stacks"] = stacks;
  return run;
}

namespace {

// One [[stack]] table; `folder` resolves a relative scan path.
PlateStack readPlateStack(const TomlTable& t, const std::filesystem::path& folder) {
  const double a2 = units::kAngstromInBohr * units::kAngstromInBohr, ev = units::kEvInHartree;
  t.allowOnly({"layers", "scan", "rigidity_eV", "rigidity_hartree", "rigidity_uncertainty_eV",
               "area_per_cell_angstrom2", "interlayer_spacing_angstrom"});
  PlateStack s;
  s.source = fmt::format("{} ([[stack]] at line {})", t.source(), t.line("layers"));
  s.layers = static_cast<int>(t.integerIn("layers", 1, 1000));
  if (t.has("scan")) {
    std::filesystem::path p(t.string("scan", "a file name"));
    if (p.is_relative()) p = folder / p;
    s.scan = readScanTable(p.string());
  }
  if (const auto x = t.quantity({{"rigidity_eV", ev}, {"rigidity_hartree", 1.0}}))
    s.rigidity = GivenConstant{*x, 0.0, s.source};
  if (t.has("rigidity_uncertainty_eV")) {
    if (!s.rigidity) t.fail("rigidity_uncertainty_eV", "no rigidity_eV", "an uncertainty with a given rigidity");
    s.rigidity->uncertainty = t.nonNegativeOr("rigidity_uncertainty_eV", 0.0, "a value >= 0") * ev;
  }
  if (t.has("interlayer_spacing_angstrom"))
    s.spacing = t.positive("interlayer_spacing_angstrom", "a value > 0") * units::kAngstromInBohr;
  if (t.has("area_per_cell_angstrom2")) s.areaPerCell = t.positive("area_per_cell_angstrom2", "a value > 0") * a2;
  return s;
}

}  // namespace

void readPlateFile(const std::string& path, PlateInputs& in) {
  const toml::value data = parseTomlFile(path, "plate file");
  const TomlTable root(path, data, "");
  in.source = path;
  root.allowOnly({"format", "in_plane_stiffness_eV_per_angstrom2", "in_plane_stiffness_N_per_m",
                  "interlayer_spacing_angstrom", "interlayer_spacing_bohr", "poisson_ratio",
                  "single_layer_rigidity_eV", "single_layer_rigidity_hartree", "max_layers", "stack"});
  const double a2 = units::kAngstromInBohr * units::kAngstromInBohr, ev = units::kEvInHartree;
  if (root.integer("format", "format = 1") != 1) root.fail("format", describe(root.at("format")), "format = 1");
  const auto c2 = root.quantity({{"in_plane_stiffness_eV_per_angstrom2", 1.0},
                                 {"in_plane_stiffness_N_per_m", kNPerMInEvPerAngstrom2}});
  if (!c2) root.missing("in_plane_stiffness_eV_per_angstrom2", "C2, the in-plane stiffness per layer");
  in.inPlaneStiffness = *c2 * ev / a2;
  const auto z0 = root.quantity({{"interlayer_spacing_angstrom", units::kAngstromInBohr}, {"interlayer_spacing_bohr", 1.0}});
  if (!z0) root.missing("interlayer_spacing_angstrom", "Z0, the interlayer spacing");
  in.spacing = *z0;
  in.poisson = root.number("poisson_ratio", "nu (0 when C2 is already the plane-strain stiffness)");
  if (const auto d1 = root.quantity({{"single_layer_rigidity_eV", ev}, {"single_layer_rigidity_hartree", 1.0}}))
    in.singleLayer = GivenConstant{*d1, 0.0, path};
  if (root.has("max_layers")) in.maxLayers = static_cast<int>(root.integerIn("max_layers", 1, 1000));
  if (root.has("stack"))
    for (const TomlTable& t : root.tables("stack"))
      in.stacks.push_back(readPlateStack(t, std::filesystem::path(path).parent_path()));
}

}  // namespace mesochain::beam
