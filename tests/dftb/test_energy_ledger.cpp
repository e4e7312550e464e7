// The dftb energy ledger: entries keep their order and kind, repeated names add up, totals sum
// by kind, and a missing or mis-kinded entry is a clear error rather than a silent zero.
#include <stdexcept>

#include <gtest/gtest.h>

#include "dftb/energy_ledger.hpp"

using mesochain::dftb::EnergyKind;
using mesochain::dftb::EnergyLedger;

TEST(DftbEnergyLedger, SumsByKindInOrder) {
  EnergyLedger l;
  l.add("band", EnergyKind::Energy, -10.0);
  l.add("entropy_term_ts", EnergyKind::Entropy, 0.25, "-TS");
  l.add("error_estimate", EnergyKind::Reported, 7.0);
  l.add("repulsive", EnergyKind::Energy, 3.0);
  l.add("band", EnergyKind::Energy, -1.0);  // adds to the existing entry
  ASSERT_EQ(l.entries().size(), 4u);
  EXPECT_EQ(l.entries()[0].name, "band");
  EXPECT_EQ(l.entries()[1].label, "-TS");
  EXPECT_EQ(l.entries()[3].label, "repulsive");  // the name when no label is given
  EXPECT_EQ(l.at("band"), -11.0);
  EXPECT_EQ(l.total(), -8.0);  // Reported entries are not part of it
  EXPECT_EQ(l.entropy(), 0.25);
  EXPECT_EQ(l.free(), -8.25);
  EXPECT_EQ(l.extrapolated(), -8.125);
  EXPECT_EQ(l["dispersion"], 0.0);
  EXPECT_FALSE(l.has("dispersion"));
  EXPECT_THROW(l.at("dispersion"), std::out_of_range);
  EXPECT_THROW(l.add("band", EnergyKind::Reported, 1.0), std::logic_error);
}

TEST(DftbEnergyLedger, MergeAddsEveryEntry) {
  EnergyLedger a, b;
  a.add("band", EnergyKind::Energy, 1.0);
  b.add("band", EnergyKind::Energy, 2.0);
  b.add("scc", EnergyKind::Energy, 0.5, "SCC");
  a.merge(b);
  EXPECT_EQ(a.at("band"), 3.0);
  EXPECT_EQ(a.entries().back().label, "SCC");
  EXPECT_EQ(a.total(), 3.5);
}
