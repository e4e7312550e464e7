// The command line's conventions (docs/command-line.md): --version with the git commit (also in
// the results JSON), the exit-code table, --set overrides read as TOML values by the strict
// readers, "-" for the standard output, -q / progress lines off a terminal, and scan's -o folder.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "common/csv.hpp"

namespace {

namespace fs = std::filesystem;
using mesochain::testing::readJson;
using mesochain::testing::runMesochain;
using mesochain::testing::slurp;

struct CommandLine : ::testing::Test {
  fs::path dir;
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::temp_directory_path() / fmt::format("cli-cmdline-{}-{}", ::getpid(), info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    write("cell.toml", cell(8));
  }
  void TearDown() override { fs::remove_all(dir); }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }
  static std::string cell(int kpoints) {
    return fmt::format(
        "format = 1\n[builder]\ntype = \"nanotube\"\nn = 5\nm = 5\ncell = \"helical\"\n"
        "[kpoints]\nhelical = {}\n[electrons]\ntemperature = 300\n[parameters]\nset = \"pbc-0-3\"\n"
        "[task]\ntype = \"energy\"\n",
        kpoints);
  }
  // Runs mesochain in dir with stdout and stderr in separate files (not a terminal, CI unset).
  int run(const std::string& args, std::string& out, std::string& err, const std::string& env = "") {
    return runProgram(MESOCHAIN_BINARY, args, out, err, env);
  }
  // The same for another program (mesochain-bench).
  int runProgram(const std::string& program, const std::string& args, std::string& out, std::string& err,
                 const std::string& env = "") {
    const std::string cmd = fmt::format("cd {} && env -u CI OMP_NUM_THREADS=1 {} {} {} > out.txt 2> err.txt",
                                        dir.string(), env, program, args);
    const int status = std::system(cmd.c_str());
    out = slurp(dir / "out.txt");
    err = slurp(dir / "err.txt");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
};

// Runs git in the source tree; its exit code (-1 when git is missing), output in `out`.
int git(const std::string& args, std::string& out) {
  const std::string cmd = fmt::format("git -C {} {} 2>/dev/null", MESOCHAIN_SOURCE_DIR, args);
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  out.clear();
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  const int status = pclose(p);
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(CommandLine, VersionNamesTheGitCommitAndTheResultsJsonCarriesIt) {
  std::string out, err;
  ASSERT_EQ(run("--version", out, err), 0) << err;
  std::smatch m;
  ASSERT_TRUE(std::regex_match(out, m, std::regex(R"(mesochain \d+\.\d+\.\d+ \(commit ([0-9a-f]{12}(-dirty)?|unknown)\)\n)")))
      << out;
  const std::string commit = m[1];
  // Built from a git checkout: git itself knows the commit, and it is HEAD or an ancestor of
  // it (a commit made after the build). Outside a checkout it is "unknown".
  std::string inside;
  if (git("rev-parse --is-inside-work-tree", inside) == 0 && inside == "true") {
    ASSERT_NE(commit, "unknown");
    const std::string id = commit.substr(0, 12);
    std::string full;
    EXPECT_EQ(git("rev-parse --verify " + id + "^{commit}", full), 0) << id;
    EXPECT_EQ(full.substr(0, 12), id);
    EXPECT_EQ(git("merge-base --is-ancestor " + id + " HEAD", full), 0) << id;
  } else {
    EXPECT_EQ(commit, "unknown");
  }
  std::string out2;
  ASSERT_EQ(run("version", out2, err), 0);
  EXPECT_EQ(out2, out);
  ASSERT_EQ(run("run cell.toml --json r.json", out, err), 0) << err;
  const nlohmann::json j = readJson(dir / "r.json");
  EXPECT_EQ(j.at("program").at("commit").get<std::string>(), commit);
  EXPECT_EQ(j.at("program").at("name").get<std::string>(), "mesochain");
}

TEST_F(CommandLine, UsageErrorsExitWithTwoAndHelpWithZero) {
  std::string out, err;
  EXPECT_EQ(run("--no-such-option", out, err), 2) << err;
  EXPECT_EQ(run("run", out, err), 2) << err;  // the cell file is required
  EXPECT_NE(err.find("cell is required"), std::string::npos) << err;
  EXPECT_EQ(run("no-such-command", out, err), 2) << err;
  EXPECT_EQ(run("scan x.toml --stop-after -5", out, err), 2) << err;
  EXPECT_EQ(run("-q -v run cell.toml", out, err), 2) << err;
  EXPECT_EQ(run("run missing.toml", out, err), 2) << err;  // an input error
  EXPECT_EQ(run("--help", out, err), 0) << err;
  EXPECT_EQ(run("run --help", out, err), 0) << err;
  // Defaults are shown in --help.
  EXPECT_NE(out.find("--unroll"), std::string::npos) << out;
  EXPECT_EQ(run("scan --help", out, err), 0) << err;
  EXPECT_TRUE(std::regex_search(out, std::regex(R"(--stop-after[^\n]*=-1)"))) << out;
}

TEST_F(CommandLine, SetOverridesAKeyAsTheFileWould) {
  write("cell4.toml", cell(4));
  std::string out, err;
  ASSERT_EQ(run("run cell4.toml --json file.json", out, err), 0) << err;
  ASSERT_EQ(run("run cell.toml --json set.json --set kpoints.helical=4", out, err), 0) << err;
  // Before or after the command, and a bare word read as a string.
  ASSERT_EQ(run("--set kpoints.helical=4 --set parameters.set=pbc-0-3 run cell.toml --json set2.json", out, err), 0)
      << err;
  const double fromFile = readJson(dir / "file.json").at("energies_hartree").at("mermin_free").at("per_cell").get<double>();
  EXPECT_EQ(readJson(dir / "set.json").at("energies_hartree").at("mermin_free").at("per_cell").get<double>(), fromFile);
  EXPECT_EQ(readJson(dir / "set2.json").at("energies_hartree").at("mermin_free").at("per_cell").get<double>(), fromFile);
  ASSERT_EQ(run("run cell.toml --json eight.json", out, err), 0) << err;
  EXPECT_NE(readJson(dir / "eight.json").at("energies_hartree").at("mermin_free").at("per_cell").get<double>(), fromFile);
}

TEST_F(CommandLine, SetIsCheckedByTheStrictReader) {
  std::string out, err;
  EXPECT_EQ(run("run cell.toml --set kpoints.helicall=4", out, err), 2);
  EXPECT_NE(err.find("key kpoints.helicall (set by --set kpoints.helicall=4)"), std::string::npos) << err;
  EXPECT_NE(err.find("unknown key"), std::string::npos) << err;
  EXPECT_EQ(run("run cell.toml --set kpoints.helical=-3", out, err), 2);
  EXPECT_NE(err.find("set by --set kpoints.helical=-3"), std::string::npos) << err;
  // Typed: a string where an integer belongs is the reader's type error.
  EXPECT_EQ(run("run cell.toml --set 'kpoints.helical=\"4\"'", out, err), 2);
  EXPECT_NE(err.find("kpoints.helical"), std::string::npos) << err;
  EXPECT_EQ(run("run cell.toml --set kpoints", out, err), 2);
  EXPECT_NE(err.find("section.key=value"), std::string::npos) << err;
  EXPECT_EQ(run("run cell.toml --set 'kpoints.helical=[4'", out, err), 2);
  EXPECT_NE(err.find("not a TOML value"), std::string::npos) << err;
  // A key below a value that is not a table.
  EXPECT_EQ(run("run cell.toml --set format.x=1", out, err), 2);
  EXPECT_NE(err.find("not a table"), std::string::npos) << err;
}

// A relaxation keeps where it stands in its checkpoint (docs/command-line.md, `mesochain run`):
// stopped after 6 evaluations (exit 4), refused without --resume, continued with it to the
// uninterrupted run's energy (to what the force tolerance allows), the checkpoint removed at the
// end; a checkpoint of other settings is refused naming the setting; an energy task takes no
// checkpoint options.
TEST_F(CommandLine, RelaxationStopsAndResumesFromItsCheckpoint) {
  std::string relax = cell(8);
  relax.replace(relax.find("type = \"energy\""), std::string("type = \"energy\"").size(),
                "type = \"relax\"\nforce_tolerance = 1e-5");
  write("relax.toml", relax);
  std::string out, err;
  ASSERT_EQ(run("run relax.toml --json whole.json --structure whole", out, err), 0) << err;
  const fs::path checkpoint = dir / "relax-relax.checkpoint.json";
  EXPECT_FALSE(fs::exists(checkpoint)) << "a finished relaxation keeps no checkpoint";
  EXPECT_EQ(run("run relax.toml --json part.json --structure part --stop-after 6", out, err), 4) << err;
  ASSERT_TRUE(fs::exists(checkpoint)) << err;
  EXPECT_FALSE(fs::exists(dir / "part.json"));
  // At the first accepted step after 6 evaluations (a line search may take two).
  const int done = readJson(checkpoint).at("in_progress").at("evaluations").get<int>();
  EXPECT_GE(done, 6);
  EXPECT_LE(done, 8);
  EXPECT_NE(err.find(fmt::format("stopped after {} evaluations", done)), std::string::npos) << err;
  // Without --resume: refused, nothing lost.
  EXPECT_EQ(run("run relax.toml --json part.json --structure part", out, err), 2);
  EXPECT_NE(err.find("--resume"), std::string::npos) << err;
  ASSERT_TRUE(fs::exists(checkpoint));
  // Other settings: refused, naming the setting with both values.
  EXPECT_EQ(run("run relax.toml --json part.json --structure part --resume --set task.force_tolerance=2e-5", out, err), 2);
  EXPECT_NE(err.find("scan.relax.force_tolerance (checkpoint 1.0000000000000001e-05, now 2.0000000000000002e-05)"),
            std::string::npos) << err;
  ASSERT_EQ(run("run relax.toml --json part.json --structure part --resume", out, err), 0) << err;
  EXPECT_NE(err.find(fmt::format("continuing the relaxation from relax-relax.checkpoint.json ({} evaluations", done)),
            std::string::npos) << err;
  EXPECT_FALSE(fs::exists(checkpoint));
  const auto energy = [&](const char* name) {
    return readJson(dir / name).at("energies_hartree").at("mermin_free").at("per_cell").get<double>();
  };
  EXPECT_NEAR(energy("part.json"), energy("whole.json"), 1e-8);
  // An energy task has nothing to checkpoint.
  EXPECT_EQ(run("run cell.toml --resume", out, err), 2);
  EXPECT_NE(err.find("task relax"), std::string::npos) << err;
}

// --unset removes keys before the reader sees the file (and before --set): a relaxation input
// becomes an energy input, which --set alone cannot do (the relax keys are errors then).
TEST_F(CommandLine, UnsetRemovesKeysBeforeSet) {
  std::string relax = cell(8);
  relax.replace(relax.find("type = \"energy\""), std::string("type = \"energy\"").size(),
                "type = \"relax\"\nforce_tolerance = 1e-4\nmax_steps = 7");
  write("relax.toml", relax);
  std::string out, err;
  ASSERT_EQ(run("run cell.toml --json energy.json", out, err), 0) << err;
  EXPECT_EQ(run("run relax.toml --set task.type=energy", out, err), 2);
  EXPECT_NE(err.find("force_tolerance"), std::string::npos) << err;
  ASSERT_EQ(run("run relax.toml --json unset.json --set task.type=energy --unset task", out, err), 0) << err;
  const auto energy = [&](const char* name) {
    return readJson(dir / name).at("energies_hartree").at("mermin_free").at("per_cell").get<double>();
  };
  EXPECT_EQ(energy("unset.json"), energy("energy.json"));
  EXPECT_NE(out.find("Mermin free energy"), std::string::npos) << out;
  // One key: the relaxation runs with the default step limit instead of 7 (it converges; no exit 3).
  ASSERT_EQ(run("run relax.toml --json relaxed.json --unset task.max_steps", out, err), 0) << err;
  // A key the file does not have, a value given to --unset, a malformed key: errors naming them.
  EXPECT_EQ(run("run cell.toml --unset task.max_steps", out, err), 2);
  EXPECT_NE(err.find("--unset task.max_steps"), std::string::npos) << err;
  EXPECT_NE(err.find("no key task.max_steps"), std::string::npos) << err;
  EXPECT_EQ(run("run cell.toml --unset nosuch.key", out, err), 2);
  EXPECT_NE(err.find("no table nosuch"), std::string::npos) << err;
  EXPECT_EQ(run("run cell.toml --unset task.type=energy", out, err), 2);
  EXPECT_NE(err.find("a key without a value"), std::string::npos) << err;
  EXPECT_EQ(run("run cell.toml --unset 'task.'", out, err), 2);
  EXPECT_NE(err.find("dotted bare TOML keys"), std::string::npos) << err;
}

TEST_F(CommandLine, DashWritesTheJsonToStandardOutput) {
  std::string out, err;
  ASSERT_EQ(run("run cell.toml --json -", out, err), 0) << err;
  const nlohmann::json j = nlohmann::json::parse(out);  // stdout is the JSON alone
  EXPECT_TRUE(j.contains("energies_hartree"));
  EXPECT_NE(err.find("Mermin free energy"), std::string::npos) << err;  // the summary on stderr
  EXPECT_FALSE(fs::exists(dir / "-"));
  ASSERT_EQ(run("build cnt 5 5 --task energy --kpoints 4 -o -", out, err), 0) << err;
  EXPECT_NE(out.find("[symmetry]"), std::string::npos) << out;
  EXPECT_NE(err.find("wrote -"), std::string::npos) << err;
}

// A small stretch scan: off a terminal, a plain progress line per point on stderr (never a
// carriage return) and a flushed table row per point on stdout; -q silences the progress;
// outputs go to -o, not beside the scan file.
TEST_F(CommandLine, ScanProgressLinesTableRowsAndOutputFolder) {
  fs::create_directories(dir / "inputs");
  write("inputs/cell.toml", cell(8));
  write("inputs/s.toml",
        "format = 1\ncell = \"cell.toml\"\nkind = \"stretch\"\nstrains = [-0.005, 0.005]\n"
        "[relax]\nforce_tolerance = 1e-4\n[output]\njson = \"s.json\"\ncsv = \"s.csv\"\n");
  std::string out, err;
  ASSERT_EQ(run("scan inputs/s.toml -o results", out, err), 0) << err;
  EXPECT_TRUE(fs::exists(dir / "results" / "s.json"));
  EXPECT_TRUE(fs::exists(dir / "results" / "s.csv"));
  EXPECT_TRUE(fs::exists(dir / "results" / "s.png"));
  EXPECT_FALSE(fs::exists(dir / "inputs" / "s.json"));
  EXPECT_EQ(err.find('\r'), std::string::npos);
  for (int k = 1; k <= 3; ++k) {
    EXPECT_NE(err.find(fmt::format("scan stretch: {}/3", k)), std::string::npos) << err;
    EXPECT_NE(out.find(fmt::format("      {}/3 ", k)), std::string::npos) << out;
  }
  // Without -o: the working folder.
  ASSERT_EQ(run("-q scan inputs/s.toml", out, err), 0) << err;
  EXPECT_TRUE(fs::exists(dir / "s.json"));
  EXPECT_EQ(err.find("scan stretch:"), std::string::npos) << err;
  // The CSV carries the header beam needs: beam accepts it as the JSON.
  EXPECT_NE(slurp(dir / "s.csv").find("# T0_bohr = "), std::string::npos);
}

}  // namespace

namespace {

// Parameter sets from MESOCHAIN_PARAMS_PATH and tables by [parameters] prefix (DFTB+'s
// Type2FileNames Prefix) give the energy of the project's set, from the files named in the JSON.
TEST_F(CommandLine, ParameterSetsFromTheSearchPathAndByPrefix) {
  const fs::path set = fs::path(MESOCHAIN_SOURCE_DIR) / "params" / "pbc-0-3";
  fs::create_directories(dir / "mysets" / "custom");
  fs::create_directories(dir / "skf");
  fs::copy_file(set / "C-C.skf", dir / "mysets" / "custom" / "C-C.skf");
  fs::copy_file(set / "C-C.skf", dir / "skf" / "mio-C-C.skf");
  std::string text = cell(4);
  write("custom.toml", std::regex_replace(text, std::regex("set = \"pbc-0-3\""), "set = \"custom\""));
  write("prefix.toml", std::regex_replace(text, std::regex("set = \"pbc-0-3\""), "prefix = \"skf/mio-\""));
  write("both.toml", std::regex_replace(text, std::regex("set = \"pbc-0-3\""), "set = \"pbc-0-3\"\nprefix = \"skf/\""));
  write("cell4.toml", text);
  std::string out, err;
  ASSERT_EQ(run("run cell4.toml --json ref.json", out, err), 0) << err;
  const double ref = readJson(dir / "ref.json").at("energies_hartree").at("mermin_free").at("per_cell").get<double>();
  // Not on the path: refused, naming the folders searched.
  EXPECT_EQ(run("run custom.toml", out, err), 2);
  EXPECT_NE(err.find("set \"custom\""), std::string::npos) << err;
  EXPECT_NE(err.find("MESOCHAIN_PARAMS_PATH"), std::string::npos) << err;
  ASSERT_EQ(run("run custom.toml --json custom.json", out, err, "MESOCHAIN_PARAMS_PATH=/nonexistent:" + (dir / "mysets").string()), 0)
      << err;
  const nlohmann::json c = readJson(dir / "custom.json");
  EXPECT_EQ(c.at("energies_hartree").at("mermin_free").at("per_cell").get<double>(), ref);
  EXPECT_EQ(c.at("parameters").at("files").at("C-C").get<std::string>(), (dir / "mysets" / "custom" / "C-C.skf").string());
  ASSERT_EQ(run("run prefix.toml --json prefix.json", out, err), 0) << err;
  const nlohmann::json p = readJson(dir / "prefix.json");
  EXPECT_EQ(p.at("energies_hartree").at("mermin_free").at("per_cell").get<double>(), ref);
  // Relative to the cell file (here the working folder of the run).
  EXPECT_TRUE(fs::equivalent(dir / p.at("parameters").at("files").at("C-C").get<std::string>(), dir / "skf" / "mio-C-C.skf"));
  EXPECT_EQ(run("run both.toml", out, err), 2);
  EXPECT_NE(err.find("both set and prefix"), std::string::npos) << err;
}

}  // namespace

namespace {

// dem and skgen off a terminal: a plain line per tenth of the run / per stage, no '\r'; -q: none.
TEST_F(CommandLine, DemAndSkgenProgressLinesOffATerminal) {
  const std::string scene = fmt::format("{}/examples/cantilever.toml --set run.steps=2000 --set run.minimum_steps=2000",
                                        MESOCHAIN_SOURCE_DIR);
  std::string out, err;
  ASSERT_EQ(run("dem " + scene + " -o d", out, err), 0) << err;
  EXPECT_EQ(err.find('\r'), std::string::npos);
  for (int k = 10; k <= 100; k += 10)
    EXPECT_NE(err.find(fmt::format("dem (% of steps): {}/100 ", k)), std::string::npos) << err;
  EXPECT_EQ(err.find("dem (% of steps): 5/100"), std::string::npos) << err;
  EXPECT_TRUE(fs::exists(dir / "d" / "vtk" / "frame.pvd"));
  ASSERT_EQ(run("-q dem " + scene + " -o d2", out, err), 0) << err;
  EXPECT_EQ(err.find("dem (% of steps)"), std::string::npos) << err;
  ASSERT_EQ(run(fmt::format("skgen {}/tests/data/skgen/cli-hydrogen.toml -o sk", MESOCHAIN_SOURCE_DIR), out, err), 0)
      << err;
  EXPECT_EQ(err.find('\r'), std::string::npos);
  EXPECT_NE(err.find("skgen (% of work): atom H\n"), std::string::npos) << err;
  EXPECT_NE(err.find("skgen (% of work): pair H-H\n"), std::string::npos) << err;
}

}  // namespace

namespace {

// `mesochain-bench kpoints --csv -` (issue 18: "(10,10)" written unquoted gave 7 fields under 6
// headers): the CSV on stdout, the table on stderr; every record has as many RFC 4180 fields as
// the header.
TEST_F(CommandLine, BenchKpointsCsvIsQuotedAndCanGoToStdout) {
  std::string out, err;
  ASSERT_EQ(runProgram(MESOCHAIN_BENCH_BINARY, "kpoints --csv -", out, err), 0) << err;
  std::istringstream lines(out);
  std::string line;
  std::vector<std::string> header, fields;
  ASSERT_TRUE(std::getline(lines, line));
  ASSERT_TRUE(mesochain::csvParseRecord(line, header));
  EXPECT_EQ(header.size(), 6u);
  int records = 0;
  std::set<std::string> tubes;
  while (std::getline(lines, line)) {
    ASSERT_TRUE(mesochain::csvParseRecord(line, fields)) << line;
    EXPECT_EQ(fields.size(), header.size()) << line;
    tubes.insert(fields[0]);
    ++records;
  }
  EXPECT_EQ(records, 32);  // 2 tubes x 2 temperatures x 8 grids
  EXPECT_EQ(tubes, (std::set<std::string>{"(10,10)", "(10,0)"}));
  EXPECT_NE(err.find("F per atom (Ha)"), std::string::npos) << err;  // the table on stderr
  EXPECT_FALSE(fs::exists(dir / "-"));
}

}  // namespace
