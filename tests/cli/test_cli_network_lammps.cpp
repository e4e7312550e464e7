// `mesochain-bench network --lammps PREFIX` end to end: the files written for the LAMMPS peer
// (bench/lammps/in.network) describe the network (atom, bond, angle and molecule counts of 40
// tubes of 25 elements) and a pair table whose force column is -dU/dr of its energy column
// (central differences), vanishing at the cut-off, with its well at the tube-tube contact gap.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path = fs::temp_directory_path() / fmt::format("cli-network-lammps-{}", ::getpid());
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

std::vector<std::string> sectionLines(const fs::path& file, const std::string& header) {
  std::ifstream in(file);
  std::string line;
  std::vector<std::string> out;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside) {
      inside = line.rfind(header, 0) == 0;
      if (inside) std::getline(in, line);  // blank line after the header
      continue;
    }
    if (line.empty()) break;
    out.push_back(line);
  }
  return out;
}

TEST(CliNetworkLammps, WritesTheNetworkAndAConsistentPairTable) {
  TempDir dir;
  const std::string cmd = fmt::format("{} network --totals 1000 --lammps {} > {} 2>&1", MESOCHAIN_BENCH_BINARY,
                                      (dir.path / "net").string(), (dir.path / "log").string());
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const fs::path data = dir.path / "net-1000.data", table = dir.path / "net-1000.table";
  const fs::path settings = dir.path / "net-1000.settings";
  ASSERT_TRUE(fs::exists(data) && fs::exists(table) && fs::exists(settings));

  const auto atoms = sectionLines(data, "Atoms");
  const auto bonds = sectionLines(data, "Bonds");
  const auto angles = sectionLines(data, "Angles");
  ASSERT_EQ(atoms.size(), 1000u);
  std::set<int> molecules;
  for (const std::string& a : atoms) {
    std::istringstream s(a);
    int id, mol;
    s >> id >> mol;
    molecules.insert(mol);
  }
  EXPECT_EQ(molecules.size(), 40u);
  EXPECT_EQ(bonds.size(), 1000u - 40u);
  EXPECT_EQ(angles.size(), 1000u - 2 * 40u);

  // Pair table: lines "k r U F" after "N n R lo hi".
  std::ifstream in(table);
  std::string line;
  std::vector<double> r, u, f;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    int k;
    double x, e, g;
    if (line.empty() || line[0] == '#' || !(s >> k >> x >> e >> g)) continue;
    r.push_back(x), u.push_back(e), f.push_back(g);
  }
  ASSERT_EQ(r.size(), 2000u);
  double fmax = 0.0;
  for (double g : f) fmax = std::max(fmax, std::abs(g));
  // Below the gap 0.7 sigma = 0.238 nm the potential is continued linearly (tube_potential.hpp):
  // U is C1 there but its curvature changes abruptly, so central differences are skipped within
  // 0.01 nm of it (10 table steps; elsewhere they agree to 0.2 % of the largest force).
  const double wallJoint = 2 * 0.678 + 0.7 * 0.34, step = r[1] - r[0];
  for (std::size_t k = 1; k + 1 < r.size(); ++k)
    if (std::abs(r[k] - wallJoint) > 10 * step) {
      EXPECT_NEAR(f[k], -(u[k + 1] - u[k - 1]) / (r[k + 1] - r[k - 1]), 2e-3 * fmax) << "r = " << r[k];
    }
  EXPECT_NEAR(u.back(), 0.0, 1e-9);
  std::size_t well = 0;
  for (std::size_t k = 0; k < u.size(); ++k)
    if (u[k] < u[well]) well = k;
  EXPECT_LT(u[well], 0.0);
  // (10,10) radius 0.678 nm: the well sits at a wall gap near the graphite spacing (~0.31 nm).
  EXPECT_GT(r[well] - 2 * 0.678, 0.25);
  EXPECT_LT(r[well] - 2 * 0.678, 0.4);

  std::ifstream s(settings);
  const std::string text((std::istreambuf_iterator<char>(s)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("pair_coeff 1 1 net-1000.table VDW"), std::string::npos);
  EXPECT_NE(text.find("timestep "), std::string::npos);
}

}  // namespace
