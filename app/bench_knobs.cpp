// `mesochain bench knobs SCAN.toml [--kpoints ...] [--angular ...] [--dispersion ...]
// [--temperature ...] [--compare-curve OTHER.json ...] [--csv F] [--json F] [--png F]`:
// what each accuracy knob of a finished scan costs and changes, without relaxing again. The
// computation is workflows/knobs.hpp (shared with the knobs stage of `mesochain chain`); this
// file is its command line: options, output checks, the printed table and the files.
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_checks.hpp"
#include "app/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "workflows/knobs.hpp"

namespace mesochain::app {

namespace {

// The request of workflows/knobs.hpp and the output files.
struct KnobsOptions : workflows::KnobsRequest {
  std::string csv, json, png;
};

int benchKnobs(const KnobsOptions& o) {
  // The outputs are checked before the (minutes of) evaluations.
  if (!o.csv.empty()) requireWritableOutput(o.csv, "<command line>", "option --csv");
  if (!o.json.empty()) requireWritableOutput(o.json, "<command line>", "option --json");
  if (!o.png.empty()) requireWritableOutput(o.png, "<command line>", "option --png");
  const workflows::KnobsTable t = workflows::runKnobs(o);
  workflows::printKnobsTable(std::cout, t);
  if (t.largestDifference > 1e-7)
    std::cerr << fmt::format("mesochain: warning: the re-evaluated energies differ from the curve "
                             "by up to {:.2e} Ha: the structures, the cell file or the parameters "
                             "changed since the scan ran\n", t.largestDifference);
  // Under mpirun only rank 0 writes (common/atomic_file.hpp, fileOutputEnabled).
  if (!o.csv.empty() && fileOutputEnabled()) {
    writeFileAtomically(o.csv, workflows::knobsCsv(t));
    std::cerr << "wrote " << o.csv << "\n";
  }
  if (!o.json.empty() && fileOutputEnabled()) {
    writeFileAtomically(o.json, workflows::knobsJson(t).dump(2) + "\n");
    std::cerr << "wrote " << o.json << "\n";
  }
  if (!o.png.empty() && fileOutputEnabled()) {
    if (workflows::writeKnobsPlot(t, o.png))
      std::cerr << "wrote " << o.png << "\n";
    else
      std::cerr << "mesochain: note: no nonzero relative difference to plot; " << o.png << " not written\n";
  }
  return 0;
}

}  // namespace

Command makeBenchKnobsCommand() {
  auto o = std::make_shared<KnobsOptions>();
  auto sub = std::make_shared<CLI::App*>(nullptr);
  Command c;
  c.attach = [o, sub](CLI::App& bench) {
    auto* s = bench.add_subcommand(
        "knobs", "a finished scan's fitted constant and time against k-points, angular samples, "
                 "dispersion and temperature (its relaxed structures re-evaluated)");
    s->add_option("scan", o->scanFile, "the scan file (with [output] structures), already run")
        ->required();
    s->add_option("--scan-output-dir", o->scanOutputDir,
                  "the -o folder the scan ran with, where its [output] files are (default: the working folder)");
    s->add_option("--kpoints", o->kpoints, "helical k-points to try, e.g. 12,24,48")->delimiter(',');
    s->add_option("--angular", o->angular, "ring angular samples to try (bend), e.g. 6,12,24,all")
        ->delimiter(',');
    s->add_option("--sampling", o->sampling,
                  "bend: helical k-points of the straight reference and ring angular samples "
                  "together, K:M, e.g. 12:6,24:12,48:24 (consistent when K = 2M)")
        ->delimiter(',');
    s->add_option("--dispersion", o->dispersion,
                  "LJ tail treatments to try: cutoff:R (Å), ewald, ewald:TOL")
        ->delimiter(',');
    s->add_option("--temperature", o->temperature, "electronic temperatures to try (K)")
        ->delimiter(',');
    s->add_option("--compare-curve", o->compare,
                  "curve JSON of the same scan made otherwise (e.g. another force tolerance)");
    s->add_option("--csv", o->csv, "write the rows as CSV");
    s->add_option("--json", o->json, "write the rows as JSON");
    s->add_option("--png", o->png, "plot |relative difference| against CPU time per evaluation");
    s->add_option("--tolerance", o->tolerance,
                  "relative tolerance of the fit's quadratic regime (as mesochain beam; 0.02)");
    s->add_option("--linear-term", o->linearTerm, "auto (stretch, twist: on; bend: off), on, off");
    s->add_flag("--measured-curvature", o->measuredCurvature,
                "fit bends against the measured curvature");
    s->add_flag("--forces", o->forces,
                "evaluate forces too: the largest force on the relaxed structures at each "
                "setting, and the time of an evaluation as in a relaxation step");
    *sub = s;
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [o] { return benchKnobs(*o); };
  return c;
}

}  // namespace mesochain::app
