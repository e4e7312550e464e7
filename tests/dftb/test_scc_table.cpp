// The [scc] table beside its settings (dftb/scc_table.hpp): every key read, written back and
// read again to the same settings; strict errors naming the key.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "common/errors.hpp"
#include "dftb/scc_table.hpp"

namespace mesochain::dftb {
namespace {

SccSettings readText(const std::string& text, SccSettings s = {}) {
  std::istringstream in(text);
  const toml::value v = toml::parse(in, "scc.toml");
  readSccTable(TomlTable("scc.toml", v, "scc"), s);
  return s;
}

bool same(const SccSettings& a, const SccSettings& b) {
  return a.enabled == b.enabled && a.chargeTolerance == b.chargeTolerance &&
         a.energyTolerance == b.energyTolerance && a.maxIterations == b.maxIterations &&
         a.mixer == b.mixer && a.mixing == b.mixing && a.ewaldTolerance == b.ewaldTolerance &&
         a.stopIfUnconverged == b.stopIfUnconverged && a.warmStart == b.warmStart;
}

TEST(SccTable, EveryKeyReadsWritesAndReadsBack) {
  const SccSettings s = readText(
      "enabled = true\ncharge_tolerance = 3e-9\nenergy_tolerance = 2.5e-7\nmax_iterations = 42\n"
      "mixer = \"simple\"\nmixing = 0.1\newald_tolerance = 1e-9\nstop_if_unconverged = false\n"
      "warm_start = false\n");
  const SccSettings d;
  // Every member differs from its default, so the round trip below checks each one.
  EXPECT_NE(s.enabled, d.enabled);
  EXPECT_NE(s.chargeTolerance, d.chargeTolerance);
  EXPECT_NE(s.energyTolerance, d.energyTolerance);
  EXPECT_NE(s.maxIterations, d.maxIterations);
  EXPECT_NE(s.mixer, d.mixer);
  EXPECT_NE(s.mixing, d.mixing);
  EXPECT_NE(s.ewaldTolerance, d.ewaldTolerance);
  EXPECT_NE(s.stopIfUnconverged, d.stopIfUnconverged);
  EXPECT_NE(s.warmStart, d.warmStart);
  const std::string text = tomlTableText(sccTableEntries(s));
  EXPECT_TRUE(same(readText(text), s)) << text;
  EXPECT_TRUE(same(readText(tomlTableText(sccTableEntries(d))), d));
  EXPECT_EQ(sccTableEntries(s).size(), sccTableEntries(d).size());  // off or on: every key
}

TEST(SccTable, BadKeysAreNamed) {
  EXPECT_THROW(readText("mix = 0.1\n"), InputError);
  try {
    readText("\nmixing = 1.5\n");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("key scc.mixing (line 2)"), std::string::npos) << m;
    EXPECT_NE(m.find("(0, 1]"), std::string::npos) << m;
  }
  EXPECT_THROW(readText("max_iterations = 2.5\n"), InputError);
  EXPECT_THROW(readText("warm_start = 1\n"), InputError);
}

}  // namespace
}  // namespace mesochain::dftb
