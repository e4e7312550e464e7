// `mesochain skgen ELEMENTS.toml`: generates Slater-Koster tables (.skf) from confined atoms
// (docs/skgen.md).
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_checks.hpp"
#include "app/commands.hpp"
#include "common/progress_bar.hpp"
#include "skgen/skgen_job.hpp"

namespace mesochain::app {

namespace {
struct SkgenOptions {
  std::string input;
  std::string outputDir;
};
}  // namespace

Command makeSkgenCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<SkgenOptions>();
  Command c;
  c.attach = [sub, opt](CLI::App& app) {
    *sub = app.add_subcommand("skgen", "generate Slater-Koster tables (.skf) from confined atoms");
    (*sub)->add_option("elements", opt->input, "elements file (TOML, docs/skgen.md)")->required();
    (*sub)->add_option("-o,--output-dir", opt->outputDir, "folder for the .skf files (default: output_dir of the file)")
        ->check(nonEmptyPath());
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    skgen::SkgenJob job = skgen::readSkgenJob(opt->input);
    if (!opt->outputDir.empty()) job.outputDir = opt->outputDir;
    // The output folder is made and checked before the (long) generation.
    prepareOutputFolder(job.outputDir, opt->outputDir.empty() ? opt->input : "<command line>",
                        opt->outputDir.empty() ? "key output_dir" : "option --output-dir");
    // Progress in percent of the work; a plain line per stage (atom, pair) off a terminal.
    ProgressBar bar("skgen (% of work)", 100, 100);
    const skgen::SkgenOutput out = skgen::runSkgen(job, [&bar](double fraction, const std::string& what) {
      bar.stage(what);
      bar.update(static_cast<int>(std::lround(fraction * 100)), what);
    });
    bar.finish();
    const std::vector<std::string>& files = out.tables;
    for (const std::string& f : files) std::cout << "wrote " << f << "\n";
    std::cout << "wrote " << out.atomicData << " (atomic data: on-site energies, U, spin constants)\n";
    int fitted = 0;
    for (const auto& [a, b] : job.pairs)
      for (const auto& r : job.repulsive)
        if ((r.a == a && r.b == b) || (r.a == b && r.b == a)) ++fitted;
    std::cout << fmt::format("skgen: {} tables, {} with a fitted repulsive, {} with the explicit zero repulsive\n",
                             files.size(), fitted, files.size() - fitted);
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
