// The scan identity covers every setting: each visitor of objective/drivers/settings_fields.hpp
// reaches every member of its struct (counted independently, by aggregate initialisation), and
// changing any Result member, one at a time, changes scanInputHash and names that member in
// scanIdentity, while changing a Run member (progress, checkpoint path, --stop-after, the list)
// leaves it as it is.
#include <cstddef>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

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
  EXPECT_EQ(visitedCount<dftb::BandSettings>(), memberCount<dftb::BandSettings>());
  EXPECT_EQ(visitedCount<dftb::DispersionSettings>(), memberCount<dftb::DispersionSettings>());
  EXPECT_EQ(visitedCount<dftb::SccSettings>(), memberCount<dftb::SccSettings>());
  EXPECT_EQ(visitedCount<dftb::KolmogorovCrespiSettings>(),
            memberCount<dftb::KolmogorovCrespiSettings>());
  EXPECT_EQ(visitedCount<dftb::CalculatorSettings>(), memberCount<dftb::CalculatorSettings>());
  EXPECT_EQ(visitedCount<RelaxSettings>(), memberCount<RelaxSettings>());
  EXPECT_EQ(visitedCount<ScanSettings>(), memberCount<ScanSettings>());
  // The counter itself counts: SccSettings has 9 members today.
  EXPECT_GE(memberCount<dftb::SccSettings>(), 9u);
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
  leaves("calculator.", calc, FieldRole::Result, all);
  const int calculatorLeaves = static_cast<int>(all.size());
  leaves("scan.", scan, FieldRole::Result, all);
  ASSERT_GE(all.size(), 30u);
  int results = 0;
  for (int k = 0; k < static_cast<int>(all.size()); ++k) {
    dftb::CalculatorSettings c = calc;
    ScanSettings s = scan;
    int index = k;
    if (k < calculatorLeaves) {
      perturbLeaf(c, index);
    } else {
      index -= calculatorLeaves;
      perturbLeaf(s, index);
    }
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
  EXPECT_GE(results, 25);
  // The cell: one atom moved by 1e-12 Bohr.
  ObjectiveCell moved = cell;
  moved.positions(0, 1) += 1e-12;
  EXPECT_NE(scanInputHash(moved, calc, scan), base);
}

}  // namespace
}  // namespace mesochain::objective
