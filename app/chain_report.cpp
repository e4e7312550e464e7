#include "app/chain_report.hpp"

#include <filesystem>
#include <iostream>

#include <unistd.h>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "input/cell_calculator.hpp"
#include "input/scan_file.hpp"
#include "workflows/knobs.hpp"

namespace mesochain::app {

namespace fs = std::filesystem;
using nlohmann::json;

std::string chainMarkdown(const ChainFile& c, const json& report, const beam::BeamRun* run) {
  std::string md = fmt::format("# Chain report: {}\n\nFilament: `{}`; force tolerance {:g} Ha/Bohr; {} cells per brick.\n\n"
                               "| stage | status | seconds |\n|---|---|---|\n",
                               c.file.filename().string(), c.cellPath, c.forceTolerance, c.cellsPerBrick);
  for (const json& s : report["stages"])
    md += fmt::format("| {} | {} | {:.1f} |\n", s["stage"].get<std::string>(), s["status"].get<std::string>(),
                      s["seconds"].get<double>());
  const json& ref = report["reference"];
  md += fmt::format("\nReference (relaxed once, shared by every scan: `reference.json`): T0 = {:.10g} Bohr "
                    "({:.8g} nm), twist {:.10g} rad per cell, rotation order {}, {} atoms per cell, "
                    "E = {:.10f} Ha per cell (max|F| {:.1e} Ha/Bohr{}).\n",
                    ref["T0_bohr"].get<double>(), ref["T0_nm"].get<double>(), ref["twist0_rad"].get<double>(),
                    ref["rotation_order"].get<int>(), ref["atoms_per_cell"].get<int>(),
                    ref["energy_hartree_per_cell"].get<double>(), ref["max_force_hartree_per_bohr"].get<double>(),
                    ref["converged"].get<bool>() ? "" : ", NOT converged");
  md += "\n| constant | value | uncertainty | source |\n|---|---|---|---|\n";
  for (const auto& [key, v] : report["constants"].items())
    if (v.is_object())
      md += fmt::format("| {} | {:.8g} | {:.2g} | {} |\n", key, v["value"].get<double>(), v["uncertainty"].get<double>(),
                        v["source"].get<std::string>());
  if (run)
    md += fmt::format("\nBeam ({}, {} closure): Y = {:.6g} GPa, G = {:.6g} GPa. Brick: L = {:.6g} nm, mass {:.6g} ag. "
                    "Files: `beam/beam.json`, `beam/model.toml`, `beam/cantilever.toml` (run it with `mesochain dem`).\n",
                      run->beam.shape, run->beam.closure, report["beam"]["young_modulus_GPa"].get<double>(),
                    report["beam"]["shear_modulus_GPa"].get<double>(), report["brick"]["length_nm"].get<double>(),
                    report["brick"]["mass_ag"].get<double>());
  if (report.contains("cantilever")) {
    const json& k = report["cantilever"];
    md += fmt::format(
        "\n## mDEM cantilever against beam theory\n\n`beam/cantilever.toml` run by the mdem engine to its static "
        "state ({} steps, residual moment {:.1e} pN nm): l = {:.6g} nm, tip moment {:.6g} pN nm bending, {:.6g} pN nm "
        "twisting; beam theory of the fitted constants, E I = D_s / T0 = {:.6g} pN nm², G J = K T0 = {:.6g} pN nm² "
        "(delta = M l² / 2EI, phi = M l / EI, theta = T l / GJ).\n\n"
        "| quantity | mDEM | beam theory | relative difference |\n|---|---|---|---|\n",
        k["steps"].get<long>(), k["residual_moment_pN_nm"].get<double>(), k["length_nm"].get<double>(),
        k["bending_moment_pN_nm"].get<double>(), k["twisting_moment_pN_nm"].get<double>(),
        k["bending_stiffness_pN_nm2"].get<double>(), k["torsional_stiffness_pN_nm2"].get<double>());
    for (const json& q : k["quantities"])
      md += fmt::format("| {} ({}) | {:.8g} | {:.8g} | {:.2e} |\n", q["name"].get<std::string>(),
                        q["unit"].get<std::string>(), q["measured"].get<double>(), q["beam_theory"].get<double>(),
                        q["relative_difference"].get<double>());
    md += fmt::format("\n**{}** (tolerance {:g} relative).\n", k["passed"].get<bool>() ? "PASS" : "FAIL",
                      k["tolerance"].get<double>());
    const double f = k["first_bending_frequency_GHz"].get<double>();
    const double ft = k["first_bending_frequency_beam_theory_GHz"].get<double>();
    md += fmt::format("\nFirst bending frequency (normal modes of the bricks): {:.6g} GHz; Euler-Bernoulli cantilever "
                      "with the half brick the bricks lump at the tip: {:.6g} GHz ({:+.2e}; reported, not part of the "
                      "pass: rotary inertia and lumping differ at O((L/l)²)).\n",
                      f, ft, f / ft - 1.0);
  }
  if (report.contains("knobs")) {
    md += "\n## Accuracy against time of the knobs\n\nEach scan's relaxed structures re-evaluated at other settings "
          "and fitted again (`mesochain bench knobs`, docs/benchmarks.md); error = relative difference of the constant "
          "to the knob's most accurate setting (ref); time = CPU seconds per energy evaluation.\n";
    const auto num = [](const json& x, const char* spec) {
      return x.is_number() ? fmt::format(fmt::runtime(spec), x.get<double>()) : std::string("-");
    };
    for (const json& t : report["knobs"]) {
      md += fmt::format("\n### {} ({})\n\n", t["stage"].get<std::string>(), t["kind"].get<std::string>());
      if (t.contains("knobs_not_applied"))
        for (const json& n : t["knobs_not_applied"]) md += "Not applied to this stage: " + n.get<std::string>() + ".\n\n";
      md += fmt::format("| knob | setting | {} | error | time (s) | note |\n|---|---|---|---|---|---|\n",
                        t["quantity"].get<std::string>());
      for (const json& row : t["rows"])
        md += fmt::format("| {} | {}{}{} | {} | {} | {} | {} |\n", row["knob"].get<std::string>(),
                          row["setting"].get<std::string>(), row["scan_setting"].get<bool>() ? " (scan)" : "",
                          row["reference"].get<bool>() ? " (ref)" : "", num(row["constant"], "{:.8g}"),
                          num(row["relative_difference"], "{:.2e}"), num(row["cpu_s_per_evaluation"], "{:.3g}"),
                          row["note"].get<std::string>());
    }
  }
  if (report.contains("plots") && !report["plots"].empty()) {
    md += "\n## Plots\n\n";
    for (const json& p : report["plots"])
      md += fmt::format("![{}]({})\n", p["title"].get<std::string>(), p["file"].get<std::string>());
  }
  if (report.contains("warnings"))
    for (const auto& w : report["warnings"]) md += "\nWarning: " + w.get<std::string>() + "\n";
  return md;
}

int checkChain(const ChainFile& chain) {
  // The generated scan files are read as the run reads them (the cell file with them), in a
  // temporary folder: nothing is written to the chain's folder.
  const fs::path tmp = fs::temp_directory_path() / fmt::format("mesochain-chain-check-{}", ::getpid());
  fs::create_directories(tmp);
  struct Cleanup {
    fs::path p;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(p, ec);
    }
  } cleanup{tmp};
  ChainFile c = chain;
  if (c.inlineCell) {  // the run writes it into the stages' folder; the check into its own
    c.cellPath = (tmp / "cell.toml").string();
    writeFileAtomically(c.cellPath, inlineCellText(c));
  }
  std::cout << fmt::format("chain file {}: valid; cell {}; output folder {}\nstages:\n", c.file.string(),
                           chain.inlineCell ? "[cell] of the chain file (the run writes " + chain.cellPath + ")"
                                            : chain.cellPath,
                           c.dir.string());
  std::cout << fmt::format("  reference   relax the reference cell (straight, or a sector as it is) at {:g} Ha/Bohr with its T0 -> reference.json\n",
                           c.forceTolerance);
  for (const auto& [stage, keys] : c.scans) {
    const fs::path f = tmp / (std::string(stage->name) + ".scan.toml");
    writeFileAtomically(f.string(), scanFileText(c, *stage, keys, stage->name, false));
    const objective::ScanInput in = objective::readScanFile(f.string(), tmp.string());
    const std::size_t n = in.settings.values.size() + in.settings.rotationOrders.size();
    std::cout << fmt::format("  {:<11} {} scan{}, {} points besides the reference -> {}.json\n", stage->name,
                             stage->kind, *stage->direction ? std::string(" (") + stage->direction + ")" : "", n,
                             stage->name);
  }
  if (c.beam) {
    std::cout << fmt::format("  beam        fit, {} cells per brick -> beam/beam.json, model.toml, cantilever.toml\n",
                             c.cellsPerBrick);
    std::cout << fmt::format("  cantilever  mDEM against beam theory, tolerance {:g}\n", c.cantileverTolerance);
  } else {
    std::cout << "  (beam = false: each curve fitted alone; no beam, bricks or cantilever)\n";
  }
  if (c.knobs.given) {
    // Every knob value is checked as the run checks it (the scan's own settings stand in).
    const workflows::KnobSource where{c.file.string(), "knobs."};
    const fs::path f = tmp / (std::string(c.scans.front().first->name) + ".scan.toml");
    const objective::ScanInput in = objective::readScanFile(f.string(), tmp.string());
    const dftb::CalculatorSettings calc = objective::calculatorSettings(in.cell);
    workflows::kpointSettings(c.knobs.kpoints, calc.band.helicalKPoints, where);
    workflows::angularSettings(c.knobs.angular, in.settings.ringAngular.samples, where);
    workflows::samplingSettings(c.knobs.sampling, calc.band.helicalKPoints, in.settings.ringAngular.samples, where);
    workflows::dispersionSettings(c.knobs.dispersion, calc.dispersion, where);
    workflows::temperatureSettings(c.knobs.temperature, calc.band.electronicTemperature, where);
    std::string stages;
    for (const std::string& s : c.knobs.stages) stages += " " + s;
    std::cout << fmt::format("  knobs       accuracy against time of{} -> knobs/STAGE.json\n", stages);
  }
  return 0;
}

}  // namespace mesochain::app
