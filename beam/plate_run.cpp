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

void readPlateFile(const std::string& path, PlateInputs& in) {
  const toml::value root = parseTomlFile(path, "plate file");
  in.source = path;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  auto where = [&](const std::string& key, const toml::value& v) {
    return fmt::format("key {} ({})", key, tomlWhere(v));
  };
  auto number = [&](const std::string& key, const toml::value& v) {
    double x = 0.0;
    if (v.is_integer()) x = static_cast<double>(v.as_integer());
    else if (v.is_floating()) x = v.as_floating();
    else throw InputError(path, where(key, v), "a " + toml::stringize(v.type()), "a number");
    requireFinite(x, path, where(key, v));
    return x;
  };
  const double a2 = units::kAngstromInBohr * units::kAngstromInBohr, ev = units::kEvInHartree;
  bool format = false, c2 = false, z0 = false, nu = false;
  auto once = [&](bool& flag, const std::string& key, const toml::value& v) {
    if (flag) throw InputError(path, where(key, v), "a second value for this quantity", "one key per quantity (one unit)");
    flag = true;
  };
  bool d1 = false;
  for (const auto& [key, v] : root.as_table()) {
    if (key == "format") {
      if (number(key, v) != 1.0) throw InputError(path, where(key, v), fmt::format("{}", number(key, v)), "1");
      format = true;
    } else if (key == "in_plane_stiffness_eV_per_angstrom2" || key == "in_plane_stiffness_N_per_m") {
      once(c2, key, v);
      const double x = number(key, v) * (key.ends_with("N_per_m") ? kNPerMInEvPerAngstrom2 : 1.0);
      in.inPlaneStiffness = x * ev / a2;
    } else if (key == "interlayer_spacing_angstrom" || key == "interlayer_spacing_bohr") {
      once(z0, key, v);
      in.spacing = number(key, v) * (key.ends_with("angstrom") ? units::kAngstromInBohr : 1.0);
    } else if (key == "poisson_ratio") {
      once(nu, key, v);
      in.poisson = number(key, v);
    } else if (key == "single_layer_rigidity_eV" || key == "single_layer_rigidity_hartree") {
      once(d1, key, v);
      in.singleLayer = GivenConstant{number(key, v) * (key.ends_with("eV") ? ev : 1.0), 0.0, path};
    } else if (key == "max_layers") {
      const double n = number(key, v);  // checked before narrowing (3e9 would wrap)
      if (!(n >= 1 && n <= 1000) || n != std::floor(n))
        throw InputError(path, where(key, v), fmt::format("{}", n), "an integer 1 <= max_layers <= 1000");
      in.maxLayers = static_cast<int>(n);
    } else if (key == "stack") {
      if (!v.is_array()) throw InputError(path, where(key, v), "a " + toml::stringize(v.type()), "[[stack]] tables");
      for (const toml::value& t : v.as_array()) {
        if (!t.is_table()) throw InputError(path, where(key, t), "a " + toml::stringize(t.type()), "[[stack]] tables");
        PlateStack s;
        s.source = fmt::format("{} ([[stack]] at line {})", path, t.location().line());
        bool hasLayers = false;
        std::optional<double> sigma;
        for (const auto& [k, x] : t.as_table()) {
          if (k == "layers") {
            const double n = number(k, x);
            if (n != std::floor(n) || !(n >= 1 && n <= 1000))
              throw InputError(path, where(k, x), fmt::format("{}", n), "an integer from 1 to 1000");
            s.layers = static_cast<int>(n), hasLayers = true;
          } else if (k == "scan") {
            if (!x.is_string()) throw InputError(path, where(k, x), "a " + toml::stringize(x.type()), "a file name");
            std::filesystem::path p(x.as_string().str);
            if (p.is_relative()) p = folder / p;
            s.scan = readScanTable(p.string());
          } else if (k == "rigidity_eV" || k == "rigidity_hartree") {
            if (s.rigidity) throw InputError(path, where(k, x), "a second rigidity", "one rigidity per stack");
            s.rigidity = GivenConstant{number(k, x) * (k.ends_with("eV") ? ev : 1.0), 0.0, s.source};
          } else if (k == "rigidity_uncertainty_eV") {
            sigma = number(k, x) * ev;
            if (*sigma < 0) throw InputError(path, where(k, x), fmt::format("{}", number(k, x)), "a value >= 0");
          } else if (k == "interlayer_spacing_angstrom") {
            s.spacing = number(k, x) * units::kAngstromInBohr;
            if (!(*s.spacing > 0)) throw InputError(path, where(k, x), fmt::format("{}", number(k, x)), "a value > 0");
          } else if (k == "area_per_cell_angstrom2") {
            s.areaPerCell = number(k, x) * a2;
            if (!(*s.areaPerCell > 0)) throw InputError(path, where(k, x), fmt::format("{}", number(k, x)), "a value > 0");
          } else {
            throw InputError(path, where(k, x), "an unknown key in [[stack]]",
                             "layers, scan, rigidity_eV | rigidity_hartree, rigidity_uncertainty_eV, area_per_cell_angstrom2, "
                             "interlayer_spacing_angstrom");
          }
        }
        if (!hasLayers) throw InputError(s.source, "key layers", "nothing", "layers = N");
        if (sigma) {
          if (!s.rigidity) throw InputError(s.source, "key rigidity_uncertainty_eV", "no rigidity_eV", "an uncertainty with a given rigidity");
          s.rigidity->uncertainty = *sigma;
        }
        in.stacks.push_back(std::move(s));
      }
    } else {
      throw InputError(path, where(key, v), "an unknown key",
                       "format, in_plane_stiffness_eV_per_angstrom2 | in_plane_stiffness_N_per_m, "
                       "interlayer_spacing_angstrom | interlayer_spacing_bohr, poisson_ratio, "
                       "single_layer_rigidity_eV | single_layer_rigidity_hartree, max_layers, [[stack]]");
    }
  }
  if (!format) throw InputError(path, "key format", "nothing", "format = 1");
  if (!c2) throw InputError(path, "key in_plane_stiffness_eV_per_angstrom2", "nothing", "C2, the in-plane stiffness per layer");
  if (!z0) throw InputError(path, "key interlayer_spacing_angstrom", "nothing", "Z0, the interlayer spacing");
  if (!nu) throw InputError(path, "key poisson_ratio", "nothing", "nu (0 when C2 is already the plane-strain stiffness)");
}

}  // namespace mesochain::beam
