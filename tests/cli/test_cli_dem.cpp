// `mesochain dem` killed for real (SIGKILL, at moments spread over its run) and continued with
// --resume: the outputs end byte for byte as those of an uninterrupted run. The in-process
// restart tests (tests/mdem/test_restart*.cpp) stop a run at a step boundary; this one kills the
// process wherever it is, also while it writes a CSV row, an XYZ or VTK frame, a checkpoint or
// the final JSON and plots (docs/scene-file.md, "Restart").
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using mesochain::testing::runMesochain;
using mesochain::testing::slurp;

TEST(CliDem, KilledAtAnyMomentResumesToTheUninterruptedOutputs) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("cli-dem-kill-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The tensile example, longer, with a checkpoint every 2000 steps and VTK frames.
  const std::string args = fmt::format(
      "dem {}/examples/network-tensile.toml --set run.steps=60000 --set output.checkpoint_every=2000 "
      "--set output.checkpoint_minutes=0 --set output.vtk_prefix=frames/f --set output.frames_every=2500",
      MESOCHAIN_SOURCE_DIR);
  std::string out;
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(runMesochain(args + " -o whole", dir, out), 0) << out;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // Each run continues the previous one's checkpoint when there is one (a kill before the first
  // checkpoint leaves none: the run starts afresh), and is killed after a share of the whole
  // run's time; their logs are appended.
  const std::string run = fmt::format(
      "cd {} && (if [ -f killed/checkpoint.mdem ]; then R=--resume; else R=--overwrite; fi; "
      "OMP_NUM_THREADS=2 CI=true {} {} -o killed $R >> killed.log 2>&1 & pid=$!; ",
      dir.string(), MESOCHAIN_BINARY, args);
  int interrupted = 0;
  for (const double share : {0.1, 0.25, 0.15, 0.4, 0.3, 0.55, 0.2, 0.45}) {
    std::system(fmt::format("{}sleep {:.3f}; kill -9 $pid 2>/dev/null; wait $pid) > /dev/null 2>&1", run, share * seconds)
                    .c_str());
    if (!fs::exists(dir / "killed" / "tensile.json")) ++interrupted;
  }
  EXPECT_GE(interrupted, 4) << "the kills came after the run had finished: nothing was tested";
  // Finish it.
  std::system(fmt::format("{}wait $pid) > /dev/null 2>&1", run).c_str());
  const std::string log = slurp(dir / "killed.log");
  EXPECT_NE(log.find("resumed from the checkpoint at step"), std::string::npos) << log;
  ASSERT_TRUE(fs::exists(dir / "killed" / "tensile.json")) << log;
  EXPECT_FALSE(fs::exists(dir / "killed" / "checkpoint.mdem"));  // a finished run removes it
  for (const char* f : {"energies.csv", "tensile.csv", "tensile.json", "trajectory.xyz", "film.json", "frames/f.pvd",
                        "frames/f_000000.vtk", "frames/f_000011.vtk", "frames/f_000024.vtk"})
    EXPECT_EQ(slurp(dir / "killed" / f), slurp(dir / "whole" / f)) << f;
  std::size_t framesWhole = 0, framesKilled = 0;
  for (const auto& e : fs::directory_iterator(dir / "whole" / "frames")) framesWhole += e.is_regular_file();
  for (const auto& e : fs::directory_iterator(dir / "killed" / "frames")) framesKilled += e.is_regular_file();
  EXPECT_EQ(framesKilled, framesWhole);
  // No temporary file of an interrupted atomic write is left behind.
  for (const auto& e : fs::recursive_directory_iterator(dir / "killed"))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  fs::remove_all(dir);
}

// A fresh run into a folder holding an interrupted run's checkpoint is refused before it writes
// anything (not even the film report), with what to do instead; the earlier run's files stay.
TEST(CliDem, RefusedRunWritesNothing) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("cli-dem-refused-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "checkpoint.mdem") << "an interrupted run's";
  std::ofstream(dir / "out" / "energies.csv") << "its rows";
  std::string out;
  EXPECT_NE(runMesochain(fmt::format("dem {}/examples/network-tensile.toml -o out", MESOCHAIN_SOURCE_DIR), dir, out), 0);
  EXPECT_NE(out.find("--resume to continue it"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "out" / "film.json"));
  EXPECT_EQ(slurp(dir / "out" / "energies.csv"), "its rows");
  fs::remove_all(dir);
}

// The two reference films of the networks issue generate as `mesochain dem` builds them (no
// step run): the film of 500 tubes of 950 nm on 1000 x 1000 nm at 0.154 ug/cm^2 and the ribbon
// of 814-nm tubes cut to 2000 x 500 nm at 0.211 ug/cm^2 (docs/benchmarks.md, "Deposited
// buckypaper films"). Their reports agree with a recount from the element count and mass.
TEST(CliDem, ReferenceFilmsGenerate) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("cli-dem-films-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  struct Film {
    const char* example;
    double arealDensity;  // ug/cm^2, requested
    long filaments;       // -1: cut at the edges (more pieces than tubes laid)
  };
  for (const Film& f : {Film{"buckypaper-film", 0.154, 500}, Film{"buckypaper-ribbon", 0.21119, -1}}) {
    std::string out;
    ASSERT_EQ(runMesochain(fmt::format("dem {}/examples/{}.toml --set run.steps=0 -o {}", MESOCHAIN_SOURCE_DIR, f.example,
                                       f.example),
                           dir, out),
              0)
        << out;
    const nlohmann::json j = mesochain::testing::readJson(dir / f.example / "film.json");
    const double elements = j["elements"].get<double>(), area = j["area_nm2"].get<double>();
    EXPECT_EQ(area, 1.0e6) << f.example;
    if (f.filaments > 0) {
      EXPECT_EQ(j["filaments"].get<long>(), f.filaments) << f.example;
    }
    // 2-nm elements of 0.0064862 ag (examples/buckypaper-model.toml).
    EXPECT_NEAR(j["mass_ag"].get<double>(), elements * 0.0064862, 1e-9 * elements) << f.example;
    // 1 ag/nm^2 = 100 ug/cm^2; the last tube laid overshoots the request by at most one tube
    // (950 nm: 0.3 % of the film), and the cut ribbon keeps what lies inside its edges.
    EXPECT_NEAR(j["areal_density_ug_per_cm2"].get<double>(), 100.0 * j["mass_ag"].get<double>() / area, 1e-12);
    EXPECT_NEAR(j["areal_density_ug_per_cm2"].get<double>(), f.arealDensity, 0.005 * f.arealDensity) << f.example;
    const double thickness = j["thickness_nm"].get<double>();
    // ug/cm^2 over nm: 1e-6 g / 1e-7 cm.
    EXPECT_NEAR(j["density_g_per_cm3"].get<double>(), 10.0 * j["areal_density_ug_per_cm2"].get<double>() / thickness, 1e-9)
        << f.example;
    EXPECT_GT(j["porosity"].get<double>(), 0.9) << f.example;
    EXPECT_LT(j["porosity"].get<double>(), 1.0) << f.example;
  }
  fs::remove_all(dir);
}

}  // namespace

namespace {

// The committed quarter-size film (bench/buckypaper-quarter-portable-2026-12-04/film.json, written
// by the run whose curves lie there) regenerates from its scene, every reported number equal: the
// committed data is main's, and a platform whose arithmetic differs from the reference machine's
// shows here, not silently in a new film (the generators call no libm function whose results
// differ between libraries: portable_math.hpp, MdemPortableMath.SameBitsAsWritten). The scene is
// the example's without its stages (no step run).
TEST(CliDem, QuarterFilmRegeneratesTheCommittedBenchFilm) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("cli-dem-quarter-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path source(MESOCHAIN_SOURCE_DIR);
  std::string scene = slurp(source / "examples" / "buckypaper-quarter-tensile.toml");
  scene = scene.substr(0, scene.find("[[stages]]"));
  scene.replace(scene.find("[run]\n"), 6, "[run]\nsteps = 0\n");
  std::ofstream(dir / "quarter.toml") << scene;
  fs::copy_file(source / "examples" / "buckypaper-model.toml", dir / "buckypaper-model.toml");
  std::string out;
  ASSERT_EQ(runMesochain("dem quarter.toml -o film", dir, out), 0) << out;
  const nlohmann::json made = mesochain::testing::readJson(dir / "film" / "film.json");
  const nlohmann::json committed =
      mesochain::testing::readJson(source / "bench" / "buckypaper-quarter-portable-2026-12-04" / "film.json");
  ASSERT_EQ(committed["elements"].get<long>(), 61391);
  int compared = 0;
  for (const auto& [key, value] : committed.items()) {
    if (key == "program") continue;  // the build that wrote it
    EXPECT_EQ(made[key], value) << key << " differs from the committed film: this platform generates another film";
    ++compared;
  }
  EXPECT_GE(compared, 20);
  fs::remove_all(dir);
}

}  // namespace
