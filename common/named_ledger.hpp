#pragma once
// A ledger of named energies, the part that dftb's and mdem's energy ledgers share
// (dftb/energy_ledger.hpp: Hartree per cell, kinds Energy / Entropy / Reported;
// mdem/energy_ledger.hpp: zJ, kinds Kinetic / Potential / Dissipated). Entries keep the order
// in which they were first reported, so outputs made from the ledger (results JSON, terminal
// tables, CSV columns) list whatever the built terms or effects reported, in their order.
//
// `Entry` is an aggregate with at least `std::string name`, `kind` (an enum) and `double value`;
// each side adds its own members (dftb's table label) and its own sums (total, free energy,
// kinetic, dissipated...).
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mesochain {

template <class Entry>
class NamedLedger {
 public:
  using Kind = decltype(Entry::kind);

  bool has(std::string_view name) const { return find(name) != nullptr; }
  // The value of an entry; 0 when the ledger has no such entry (a term or effect that is not
  // built contributes nothing).
  double operator[](std::string_view name) const {
    const Entry* e = find(name);
    return e ? e->value : 0.0;
  }
  // The value of an entry that must be there (std::out_of_range otherwise).
  double at(std::string_view name) const {
    const Entry* e = find(name);
    if (!e) throw std::out_of_range(std::string(what_) + ": no entry '" + std::string(name) + "'");
    return e->value;
  }
  // Every entry of `other`, added in its order.
  void merge(const NamedLedger& other) {
    for (const Entry& e : other.entries_)
      if (!addToExisting(e.name, e.kind, e.value)) entries_.push_back(e);
  }

  const std::vector<Entry>& entries() const { return entries_; }
  bool empty() const { return entries_.empty(); }
  // Entry names in order (e.g. the layout of a CSV row).
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (const Entry& e : entries_) n.push_back(e.name);
    return n;
  }

 protected:
  // `what` names the ledger in messages ("dftb energy ledger").
  explicit NamedLedger(const char* what) : what_(what) {}

  // Adds `value` to the entry `name` and returns true, or returns false when there is none yet
  // (the caller then appends it, with its own members). The kind of an existing entry must match
  // (a programming error otherwise: std::logic_error).
  bool addToExisting(std::string_view name, Kind kind, double value) {
    for (Entry& e : entries_)
      if (e.name == name) {
        if (e.kind != kind)
          throw std::logic_error(std::string(what_) + ": entry '" + e.name + "' reported with two kinds");
        e.value += value;
        return true;
      }
    return false;
  }
  // The sum of the entries of one kind, in their order.
  double sum(Kind kind) const {
    double s = 0.0;
    for (const Entry& e : entries_)
      if (e.kind == kind) s += e.value;
    return s;
  }

  std::vector<Entry> entries_;

 private:
  const Entry* find(std::string_view name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }
  const char* what_;
};

}  // namespace mesochain
