// [output] plot_png: a run writes a PNG of its energies (and probes) that reads back with the
// expected panels; a blown-up run (non-finite energies) still gets its plot.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "common/plot/png_io.hpp"
#include "mdem/run.hpp"
#include "mdem/scene_file.hpp"
#include "mdem/time_series_plot.hpp"

namespace mesochain::mdem {
namespace {

namespace fs = std::filesystem;

fs::path freshDir() {
  const fs::path d = fs::temp_directory_path() /
                     ("mdem-plot-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string scene(const std::string& output) {
  return R"(format = 1
effects = ["bonds", "local_damping"]
[[element_types]]
name = "brick"
thickness_nm = 0.8
width_nm = 2.4
length_nm = 2.0
mass_ag = 0.01
[[bond_types]]
name = "b"
young_modulus_MPa = 1.0e6
shear_modulus_MPa = 0.4e6
[[filaments]]
element_type = "brick"
bond_type = "b"
count = 4
[[fixed]]
element = 0
[[loads]]
element = -1
moment_pN_nm = [0.0, 0.0, 10.0]
[run]
time_step_fraction = 0.5
steps = 40
[output]
energies_every = 5
)" + output;
}

TEST(MdemTimeSeriesPlot, SceneWithPlotPngWritesEnergyAndProbePanels) {
  const fs::path dir = freshDir();
  std::ofstream(dir / "with.toml") << scene("plot_png = \"plots/run.png\"\nprobes = [-1]\n");
  runScene(loadScene((dir / "with.toml").string()), (dir / "out").string(), nullptr);
  const plot::Image img = plot::readPng((dir / "out" / "plots" / "run.png").string());
  EXPECT_EQ(img.width(), 1000);
  EXPECT_EQ(img.height(), 3 * 450);  // energies, probe displacements, probe rotations

  std::ofstream(dir / "without.toml") << scene("plot_png = \"run.png\"\n");
  runScene(loadScene((dir / "without.toml").string()), (dir / "out2").string(), nullptr);
  EXPECT_EQ(plot::readPng((dir / "out2" / "run.png").string()).height(), 450);  // energies only
  fs::remove_all(dir);
}

TEST(MdemTimeSeriesPlot, NonFiniteSamplesDoNotStopThePlot) {
  const fs::path dir = freshDir();
  std::ofstream(dir / "s.toml") << scene("");
  const Scene s = loadScene((dir / "s.toml").string());
  TimeSeriesPlot plot({});
  for (int k = 0; k < 5; ++k) {
    EnergyLedger e;
    e.add("kinetic_translational", EnergyKind::Kinetic, k);
    e.add("twisting", EnergyKind::Potential, k == 3 ? std::numeric_limits<double>::infinity() : 0.5 * k);
    plot.record(0.1 * k, e, s.bodies);
  }
  EXPECT_EQ(plot.samples(), 5u);
  const std::string path = (dir / "p.png").string();
  EXPECT_NO_THROW(plot.write(path));
  EXPECT_EQ(plot::readPng(path).width(), 1000);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mesochain::mdem
