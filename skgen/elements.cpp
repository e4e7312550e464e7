#include "skgen/elements.hpp"

#include "common/errors.hpp"

namespace mesochain::skgen {

namespace {
const std::vector<Element>& table() {
  static const std::vector<Element> t = {
      {"H", 1, 1.008, {{1, 0, 1.0}}, {0}},
      {"He", 2, 4.0026, {{1, 0, 2.0}}, {0}},
      {"Li", 3, 6.94, {{1, 0, 2.0}, {2, 0, 1.0}, {2, 1, 0.0}}, {1, 2}},
      {"Be", 4, 9.0122, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 0.0}}, {1, 2}},
      {"B", 5, 10.81, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 1.0}}, {1, 2}},
      {"C", 6, 12.011, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 2.0}}, {1, 2}},
      {"N", 7, 14.007, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 3.0}}, {1, 2}},
      {"O", 8, 15.999, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 4.0}}, {1, 2}},
      {"F", 9, 18.998, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 5.0}}, {1, 2}},
      {"Ne", 10, 20.180, {{1, 0, 2.0}, {2, 0, 2.0}, {2, 1, 6.0}}, {1, 2}},
  };
  return t;
}
}  // namespace

const Element& findElement(const std::string& symbol, const std::string& source,
                           const std::string& key) {
  for (const auto& e : table())
    if (e.symbol == symbol) return e;
  throw InputError(source, key, "unknown element '" + symbol + "'",
                   "an element from H to Ne (the table generator's element list)");
}

}  // namespace mesochain::skgen
