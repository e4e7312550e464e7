// Atomic output files (common/atomic_file.hpp), the writable-path check, and the finite check of
// JSON and TOML outputs (common/finite_output.hpp).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "common/atomic_file.hpp"
#include "common/electronic_temperature.hpp"
#include "common/errors.hpp"
#include "common/finite_output.hpp"
#include "common/units.hpp"

namespace mesochain {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("atomic-" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d / name;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int filesIn(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesAndReplacesWithoutLeavingTemporaries) {
  const fs::path p = scratch("a.txt");
  writeFileAtomically(p.string(), "first\n");
  EXPECT_EQ(slurp(p), "first\n");
  writeFileAtomically(p.string(), "second\n");
  EXPECT_EQ(slurp(p), "second\n");
  EXPECT_EQ(filesIn(p.parent_path()), 1);
}

// A writer interrupted by an exception (the stand-in for a kill mid-write) leaves the previous
// file untouched and no temporary file.
TEST(AtomicFile, AnAbandonedWriteLeavesThePreviousFile) {
  const fs::path p = scratch("b.csv");
  writeFileAtomically(p.string(), "x,y\n1,2\n");
  try {
    AtomicOutputFile out(p.string());
    out.stream() << "x,y\n3,";  // half a row
    EXPECT_EQ(slurp(p), "x,y\n1,2\n");  // not visible under the name while being written
    throw std::runtime_error("killed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(slurp(p), "x,y\n1,2\n");
  for (const auto& e : fs::directory_iterator(p.parent_path()))
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
}

TEST(AtomicFile, UnwritablePlacesAreInputErrorsNamingThem) {
  EXPECT_THROW(writeFileAtomically("/nonexistent/folder/x.json", "{}"), InputError);
  try {
    requireWritableOutput("/nonexistent/x.json", "<command line>", "option --json");
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("option --json"), std::string::npos) << m;
    EXPECT_NE(m.find("/nonexistent"), std::string::npos) << m;
  }
  EXPECT_THROW(requireWritableOutput("", "<command line>", "option --json"), InputError);
  EXPECT_THROW(requireWritableOutput(fs::temp_directory_path().string(), "s", "k"), InputError);
  EXPECT_NO_THROW(requireWritableOutput(scratch("ok.json").string(), "s", "k"));
}

TEST(FiniteOutput, NonFiniteNumbersInJsonOrTomlAreNamed) {
  nlohmann::json j = {{"beam", {{"young_GPa", 1000.0}, {"list", {1.0, 2.0}}}}, {"note", nullptr}};
  EXPECT_NO_THROW(requireFiniteJson(j, "beam.json"));
  j["beam"]["list"][1] = std::numeric_limits<double>::infinity();
  try {
    requireFiniteJson(j, "beam.json");
    FAIL();
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("beam.json: entry /beam/list/1"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(requireFiniteToml("a = 1.0\n[t]\nb = [2.0, 3]\n", "model.toml"));
  try {
    requireFiniteToml("a = 1.0\n[t]\nb = [2.0, inf]\n", "model.toml");
    FAIL();
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("t.b[1]"), std::string::npos) << e.what();
  }
  EXPECT_THROW(requireFiniteToml("x = nan\n", "m.toml"), NumericalError);
}

// One validation of the electronic temperature: the range and the real source in the message.
TEST(ElectronicTemperature, RangeWithTheSourceNamed) {
  const double k = units::kBoltzmannHartreePerKelvin;
  EXPECT_NO_THROW(requireElectronicTemperature(300 * k, "cell.toml", "key electrons.temperature"));
  EXPECT_NO_THROW(requireElectronicTemperature(kMinimumElectronicTemperatureKelvin * k, "s", "k"));
  for (double kelvin : {-3.0, 0.0, 1e-13, 1e-307, 1e6, std::nan("")}) {
    try {
      requireElectronicTemperature(kelvin * k, "<command line>", "option --temperature");
      FAIL() << kelvin;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("<command line>, option --temperature"), std::string::npos) << m;
      EXPECT_NE(m.find("0.01 K"), std::string::npos) << m;
    }
  }
}

}  // namespace
}  // namespace mesochain
