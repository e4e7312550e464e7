#include "mdem/energy_ledger.hpp"

#include <cstdint>

#include "mdem/binary_io.hpp"

namespace mesochain::mdem {

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
