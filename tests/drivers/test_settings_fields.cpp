// The scan identity covers every setting. The driver settings: each visitor of
// objective/drivers/settings_fields.hpp reaches every member of its struct (counted
// independently, by aggregate initialisation), and changing any Result member, one at a time,
// changes scanInputHash and names that member in scanIdentity, while changing a Run member
// (progress, checkpoint path, --stop-after, the list) leaves it as it is. The calculator
// settings (the cell file's tables, dftb/settings_tables.hpp): a list kept here, independently
// of the tables, changes every member of every struct (as many changes as the struct has
// members), and each change that alters the results changes the identity.
#include <algorithm>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "dftb/calculator.hpp"
#include "objective/core/nanotube_builder.hpp"
#include "objective/drivers/scan.hpp"
#include "objective/drivers/settings_fields.hpp"

namespace mesochain::objective {
namespace {

// Converts to any member type: T{AnyMember{} x N} compiles for N up to the member count.
struct AnyMember {
  template <class T>
  operator T() const;  // NOLINT: implicit on purpose
};

template <class T, class... A>
constexpr std::size_t memberCount() {
  if constexpr (requires { T{A{}..., AnyMember{}}; })
    return memberCount<T, A..., AnyMember>();
  else
    return sizeof...(A);
}

template <class T>
std::size_t visitedCount() {
  T t{};
  std::size_t n = 0;
  forEachField(t, [&](const char*, auto&, FieldRole) { ++n; });
  return n;
}

TEST(SettingsFields, EveryVisitorReachesEveryMember) {
  EXPECT_EQ(visitedCount<AngularSampling>(), memberCount<AngularSampling>());
  EXPECT_EQ(visitedCount<RelaxSettings>(), memberCount<RelaxSettings>());
  EXPECT_EQ(visitedCount<ScanSettings>(), memberCount<ScanSettings>());
  // The counter itself counts: RelaxSettings has 11 members today.
  EXPECT_GE(memberCount<RelaxSettings>(), 11u);
}

// A different value of the same type.
template <class T>
void perturb(T& v) {
  if constexpr (std::is_same_v<T, bool>) v = !v;
  else if constexpr (std::is_enum_v<T>) v = static_cast<T>(static_cast<int>(v) + 1);
  else if constexpr (std::is_floating_point_v<T>) v = v * 2 + 0.5;
  else if constexpr (std::is_integral_v<T>) v = v + 1;
  else if constexpr (std::is_same_v<T, std::string>) v += "x";
  else if constexpr (std::is_invocable_v<T, int, double, double>) v = [](int, double, double) {};
  else if constexpr (std::is_invocable_v<T, const ScanPoint&, int, int>) v = [](const ScanPoint&, int, int) {};
  else if constexpr (std::is_same_v<T, std::shared_ptr<const ScanReference>>) v = std::make_shared<ScanReference>();
  else if constexpr (std::is_invocable_v<T, const RelaxProgress&>) v = [](const RelaxProgress&) {};
  else if constexpr (std::is_same_v<T, std::shared_ptr<const RelaxProgress>>) v = std::make_shared<RelaxProgress>();
  else v.push_back(typename T::value_type{7});
}

struct Leaf {
  std::string name;
  FieldRole role;
};

// The leaves (non-settings members) of s in visiting order; a leaf inside a Run member is Run.
template <class S>
void leaves(const std::string& prefix, S& s, FieldRole outer, std::vector<Leaf>& out) {
  forEachField(s, [&](const char* name, auto& v, FieldRole role) {
    const FieldRole r = outer == FieldRole::Run ? FieldRole::Run : role;
    if constexpr (VisitedSettings<std::decay_t<decltype(v)>>)
      leaves(prefix + name + ".", v, r, out);
    else
      out.push_back({prefix + name, r});
  });
}

// Perturbs leaf number `index` (counted down as leaves are passed).
template <class S>
void perturbLeaf(S& s, int& index) {
  forEachField(s, [&](const char*, auto& v, FieldRole) {
    if constexpr (VisitedSettings<std::decay_t<decltype(v)>>) {
      perturbLeaf(v, index);
    } else {
      if (index-- == 0) perturb(v);
    }
  });
}

TEST(SettingsFields, EveryResultSettingChangesTheScanIdentity) {
  const ObjectiveCell cell = buildNanotubeHelical(5, 5, 1.42 * 1.8897);
  dftb::CalculatorSettings calc;
  calc.band.helicalKPoints = 8;
  calc.band.electronicTemperature = 1e-3;
  ScanSettings scan;
  scan.values = {0.01};
  scan.identity = "table C-C ...";
  const std::string base = scanInputHash(cell, calc, scan);
  const auto baseIdentity = scanIdentity(cell, calc, scan);

  std::vector<Leaf> all;
  leaves("scan.", scan, FieldRole::Result, all);
  ASSERT_GE(all.size(), 20u);
  int results = 0;
  for (int k = 0; k < static_cast<int>(all.size()); ++k) {
    dftb::CalculatorSettings c = calc;
    ScanSettings s = scan;
    int index = k;
    perturbLeaf(s, index);
    const std::string hash = scanInputHash(cell, c, s);
    if (all[k].role == FieldRole::Result) {
      ++results;
      EXPECT_NE(hash, base) << all[k].name << " does not change the scan identity";
      const auto identity = scanIdentity(cell, c, s);
      ASSERT_TRUE(identity.count(all[k].name)) << all[k].name;
      EXPECT_NE(identity.at(all[k].name), baseIdentity.at(all[k].name)) << all[k].name;
    } else {
      EXPECT_EQ(hash, base) << all[k].name << " (how the run proceeds) changes the identity";
    }
  }
  EXPECT_GE(results, 10);
  // The cell: one atom moved by 1e-12 Bohr.
  ObjectiveCell moved = cell;
  moved.positions(0, 1) += 1e-12;
  EXPECT_NE(scanInputHash(moved, calc, scan), base);
}

// One change of one member of the calculator settings, on a base in which that member matters
// (LJ on with one pair or with elements, KC on with its own cutoff, SCC on).
struct CalculatorChange {
  const char* structName;
  const char* member;
  std::function<void(dftb::CalculatorSettings&)> base;
  std::function<void(dftb::CalculatorSettings&)> change;
  bool changesResults = true;
};

std::vector<CalculatorChange> calculatorChanges() {
  using C = dftb::CalculatorSettings;
  auto none = [](C&) {};
  auto ljPair = [](C& c) {
    c.dispersion.enabled = true;
    c.dispersion.epsilon = 1e-4;
    c.dispersion.r0 = 7.0;
    c.dispersion.cutoff = 40.0;
    c.dispersion.ewald = true;
  };
  auto ljElements = [](C& c) {
    c.dispersion.enabled = true;
    c.dispersion.cutoff = 40.0;
    c.dispersion.elements = {"C"};
    c.dispersion.elementEpsilon = {1e-4};
    c.dispersion.elementR0 = {7.0};
  };
  auto kc = [](C& c) {
    c.kc.enabled = true;
    c.kc.cutoff = 26.0;
    c.kc.taperStart = 5.0;
    c.kc.bondCutoff = 3.2;
  };
  auto scc = [](C& c) { c.scc.enabled = true; };
  return {
      {"band", "helicalKPoints", none, [](C& c) { c.band.helicalKPoints += 2; }},
      {"band", "angular", none, [](C& c) { c.band.angular.samples = 3; }},
      {"band", "electronicTemperature", none, [](C& c) { c.band.electronicTemperature *= 1.5; }},
      {"band", "eigenvectors", none, [](C& c) { c.band.eigenvectors = dftb::EigenvectorPath::AllVectors; }, false},
      {"dispersion", "enabled", none, [](C& c) { c.dispersion.enabled = true; c.dispersion.cutoff = 40; }},
      {"dispersion", "epsilon", ljPair, [](C& c) { c.dispersion.epsilon *= 1.1; }},
      {"dispersion", "r0", ljPair, [](C& c) { c.dispersion.r0 *= 1.1; }},
      {"dispersion", "cutoff", ljPair, [](C& c) { c.dispersion.cutoff *= 1.1; }},
      {"dispersion", "ewald", ljPair, [](C& c) { c.dispersion.ewald = false; }},
      {"dispersion", "ewaldTolerance", ljPair, [](C& c) { c.dispersion.ewaldTolerance = 1e-11; }},
      {"dispersion", "elements", ljElements, [](C& c) { c.dispersion.elements = {"N"}; }},
      {"dispersion", "elementEpsilon", ljElements, [](C& c) { c.dispersion.elementEpsilon = {2e-4}; }},
      {"dispersion", "elementR0", ljElements, [](C& c) { c.dispersion.elementR0 = {6.0}; }},
      {"kc", "enabled", none, [](C& c) { c.kc.enabled = true; c.kc.bondCutoff = 3.2; }},
      {"kc", "parameters", kc, [](C& c) { c.kc.parameters = "ouyang2018"; }},
      {"kc", "cutoff", kc, [](C& c) { c.kc.cutoff = 28.0; }},
      {"kc", "taperStart", kc, [](C& c) { c.kc.taperStart = 6.0; }},
      {"kc", "bondCutoff", kc, [](C& c) { c.kc.bondCutoff = 3.3; }},
      {"scc", "enabled", scc, [](C& c) { c.scc.enabled = false; }},
      {"scc", "chargeTolerance", scc, [](C& c) { c.scc.chargeTolerance *= 0.1; }},
      {"scc", "energyTolerance", scc, [](C& c) { c.scc.energyTolerance *= 0.1; }},
      {"scc", "maxIterations", scc, [](C& c) { c.scc.maxIterations += 1; }},
      {"scc", "mixer", scc, [](C& c) { c.scc.mixer = "simple"; }},
      {"scc", "mixing", scc, [](C& c) { c.scc.mixing = 0.3; }},
      {"scc", "ewaldTolerance", scc, [](C& c) { c.scc.ewaldTolerance *= 0.1; }},
      {"scc", "stopIfUnconverged", scc, [](C& c) { c.scc.stopIfUnconverged = false; }},
      {"scc", "warmStart", scc, [](C& c) { c.scc.warmStart = false; }},
  };
}

TEST(SettingsFields, EveryCalculatorSettingChangesTheScanIdentity) {
  const ObjectiveCell cell = buildNanotubeHelical(5, 5, 1.42 * 1.8897);
  ScanSettings scan;
  scan.values = {0.01};
  const auto changes = calculatorChanges();
  // The list names as many members as each struct has (a new member needs a line here).
  auto count = [&](const std::string& name) {
    return static_cast<std::size_t>(
        std::count_if(changes.begin(), changes.end(), [&](const auto& c) { return c.structName == name; }));
  };
  EXPECT_EQ(count("band"), memberCount<dftb::BandSettings>());
  EXPECT_EQ(count("dispersion"), memberCount<dftb::DispersionSettings>());
  EXPECT_EQ(count("kc"), memberCount<dftb::KolmogorovCrespiSettings>());
  EXPECT_EQ(count("scc"), memberCount<dftb::SccSettings>());
  EXPECT_EQ(memberCount<dftb::CalculatorSettings>(), 4u);  // band, dispersion, kc, scc
  for (const CalculatorChange& ch : changes) {
    dftb::CalculatorSettings before;
    before.band.helicalKPoints = 8;
    before.band.electronicTemperature = 1e-3;
    ch.base(before);
    dftb::CalculatorSettings after = before;
    ch.change(after);
    const std::string what = std::string(ch.structName) + "." + ch.member;
    if (ch.changesResults)
      EXPECT_NE(scanInputHash(cell, after, scan), scanInputHash(cell, before, scan))
          << what << " does not change the scan identity";
    else
      EXPECT_EQ(scanInputHash(cell, after, scan), scanInputHash(cell, before, scan))
          << what << " (how, not what) changes the scan identity";
  }
}

// Both dispersion terms on at once (the API allows it): both tables enter the identity.
TEST(SettingsFields, LennardJonesAndKolmogorovCrespiTogetherBothCount) {
  const ObjectiveCell cell = buildNanotubeHelical(5, 5, 1.42 * 1.8897);
  ScanSettings scan;
  scan.values = {0.01};
  dftb::CalculatorSettings c;
  c.band.electronicTemperature = 1e-3;
  c.dispersion.enabled = true;
  c.dispersion.cutoff = 40.0;
  c.kc.enabled = true;
  c.kc.bondCutoff = 3.2;
  dftb::CalculatorSettings d = c;
  d.kc.bondCutoff = 3.3;
  EXPECT_NE(scanInputHash(cell, c, scan), scanInputHash(cell, d, scan));
  d = c;
  d.dispersion.cutoff = 41.0;
  EXPECT_NE(scanInputHash(cell, c, scan), scanInputHash(cell, d, scan));
}

}  // namespace
}  // namespace mesochain::objective
