// Under mpirun (docs/cluster.md) every rank runs the same command: the calculators share their
// k-points over the ranks, rank 0 alone prints and writes files, and an error ends every rank
// with its message printed once (parallel/session.hpp).
#include "app/cli/program.hpp"

#include <exception>
#include <functional>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/exit_codes.hpp"
#include "common/atomic_file.hpp"
#include "common/build_info.hpp"
#include "common/errors.hpp"
#include "common/progress_bar.hpp"
#include "common/toml_file.hpp"
#include "parallel/session.hpp"

namespace mesochain::app {

int runProgram(int argc, char** argv, const Program& program) {
  parallel::Session mpi(argc, argv);
  mpi.silenceOtherRanks();
  if (mpi.rank() != 0) setFileOutputEnabled(false);
  CLI::App app{program.description};
  // Every option's default is shown in --help; options of the main program are also accepted
  // after the subcommand.
  app.fallthrough();
  app.set_version_flag("--version", versionLine(), "print the version and git commit, then exit");
  bool quiet = false, verbose = false;
  std::vector<std::string> sets, unsets;
  app.add_flag("-q,--quiet", quiet, "no progress output (bars or lines); warnings and errors only");
  app.add_flag("-v,--verbose", verbose,
               "progress as plain lines even on a terminal, with every step (e.g. each relaxation step)");
  app.add_option("--set", sets,
                 "override a key of the input file (the first TOML file the command reads), typed as "
                 "TOML: --set kpoints.helical=8 --set task.type=energy (repeatable)")
      ->type_name("SECTION.KEY=VALUE");
  app.add_option("--unset", unsets,
                 "remove a key or a whole table of the input file before it is read (applied before "
                 "--set): --unset task --set task.type=energy (repeatable)")
      ->type_name("SECTION.KEY");
  app.option_defaults()->always_capture_default();  // for every option added from here on
  app.require_subcommand(1);
  std::vector<Command> commands = program.commands();
  for (auto& c : commands) c.attach(app);
  // An empty list has no default worth showing ("=[]").
  std::function<void(CLI::App*)> hideEmptyDefaults = [&](CLI::App* a) {
    for (CLI::Option* o : a->get_options())
      if (o->get_default_str() == "[]") o->default_str("");
    for (CLI::App* sub : a->get_subcommands([](CLI::App*) { return true; })) hideEmptyDefaults(sub);
  };
  hideEmptyDefaults(&app);
  try {
    app.parse(argc, argv);
    if (quiet && verbose) throw CLI::ValidationError("-q and -v", "at most one of them");
  } catch (const CLI::ParseError& e) {
    // --help and --version end with 0; any usage error with kUsageError (CLI11's own codes,
    // 105-109, are not part of mesochain's table).
    const int rc = app.exit(e);
    return rc == 0 ? kSuccess : kUsageError;
  }
  try {
    setVerbosity(quiet ? Verbosity::Quiet : verbose ? Verbosity::Verbose : Verbosity::Normal);
    std::vector<TomlOverride> overrides;
    for (const std::string& s : unsets) overrides.push_back(parseTomlRemoval(s));
    for (const std::string& s : sets) overrides.push_back(parseTomlOverride(s));
    setTomlOverrides(std::move(overrides));
    for (auto& c : commands)
      if (c.selected()) {
        const int rc = c.run();
        if (tomlOverridesUnused())
          std::cerr << program.name << ": warning: --set/--unset were not used: this command read no TOML input file\n";
        return rc;
      }
  } catch (const InputError& e) {
    std::cerr << program.name << ": error: " << e.what() << "\n";
    mpi.endAfterError(e.what(), kUsageError);
    return kUsageError;
  } catch (const std::exception& e) {
    std::cerr << program.name << ": error: " << e.what() << "\n";
    mpi.endAfterError(e.what(), kFailure);
    return kFailure;
  }
  return kSuccess;
}

}  // namespace mesochain::app
