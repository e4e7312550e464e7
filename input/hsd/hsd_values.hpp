#pragma once
// Typed, strict access to the nodes of an HSD tree (input/hsd/hsd_tree.hpp): every value that
// is not what a keyword expects is an InputError naming the file, the line and the keyword.
#include <string>
#include <vector>

#include "input/hsd/dftbplus_units.hpp"
#include "input/hsd/hsd_tree.hpp"

namespace mesochain::input::hsd {

// Throws for the first child whose name is not in `allowed` (case-insensitive), for a name
// given twice, and for data lines among the keywords.
void allowOnly(const Node& node, const std::vector<std::string>& allowed);
// Throws when the node has an attribute (a unit where none is taken).
void requireNoAttribute(const Node& node);

// Key = value: exactly one token (no attribute).
std::string word(const Node& node, const std::string& expected);
double real(const Node& node, const std::string& expected);
long integer(const Node& node, const std::string& expected);
// Yes / No (case-insensitive).
bool yesNo(const Node& node);
// A value with DFTB+'s units: the attribute (or `defaultUnit` without one) converted to atomic
// units; a unit DFTB+ does not accept for this kind is an error listing those it does.
double withUnit(const Node& node, UnitKind kind, const std::string& defaultUnit, const std::string& expected);
// Key = Method { ... }: the one child method node (Key { Method { ... } } as well).
const Node& method(const Node& node, const std::string& expected);
// All data tokens of a block (Key { 1 2 3 }) as reals, `count` of them.
std::vector<double> reals(const Node& node, std::size_t count, const std::string& expected);

}  // namespace mesochain::input::hsd
