#include "mdem/energy_ledger.hpp"

#include <cstdint>
#include <stdexcept>

#include "mdem/binary_io.hpp"

namespace mesochain::mdem {

void EnergyLedger::add(std::string_view name, EnergyKind kind, double value) {
  for (LedgerEntry& e : entries_)
    if (e.name == name) {
      if (e.kind != kind) throw std::logic_error("energy ledger: entry '" + e.name + "' reported with two kinds");
      e.value += value;
      return;
    }
  entries_.push_back({std::string(name), kind, value});
}

const LedgerEntry* EnergyLedger::find(std::string_view name) const {
  for (const LedgerEntry& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

double EnergyLedger::operator[](std::string_view name) const {
  const LedgerEntry* e = find(name);
  return e ? e->value : 0.0;
}

double EnergyLedger::sum(EnergyKind kind) const {
  double s = 0.0;
  for (const LedgerEntry& e : entries_)
    if (e.kind == kind) s += e.value;
  return s;
}

std::vector<std::string> EnergyLedger::names() const {
  std::vector<std::string> n;
  for (const LedgerEntry& e : entries_) n.push_back(e.name);
  return n;
}

void writeLedger(BinaryWriter& out, const EnergyLedger& ledger) {
  out.write<std::uint64_t>(ledger.entries().size());
  for (const LedgerEntry& e : ledger.entries()) {
    out.write(e.name);
    out.write<std::int32_t>(static_cast<std::int32_t>(e.kind));
    out.write(e.value);
  }
}

EnergyLedger readLedger(BinaryReader& in) {
  EnergyLedger ledger;
  const std::uint64_t entries = in.read<std::uint64_t>();
  for (std::uint64_t e = 0; e < entries; ++e) {
    const std::string name = in.read<std::string>();
    const int kind = in.read<std::int32_t>();
    if (kind < 0 || kind > 2) in.fail("an energy entry of unknown kind");
    ledger.add(name, static_cast<EnergyKind>(kind), in.read<double>());
  }
  return ledger;
}

}  // namespace mesochain::mdem
