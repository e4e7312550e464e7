#include "objective/core/uff_parameters.hpp"

#include <array>

namespace mesochain::objective {

namespace {
struct Entry {
  const char* element;
  double x;  // Å
  double d;  // kcal/mol
};
// Rappe et al., J. Am. Chem. Soc. 114, 10024 (1992), Table 1: x_I (Å), D_I (kcal/mol).
constexpr std::array<Entry, 36> kTable{{
    {"H", 2.886, 0.044},  {"He", 2.362, 0.056}, {"Li", 2.451, 0.025}, {"Be", 2.745, 0.085},
    {"B", 4.083, 0.180},  {"C", 3.851, 0.105},  {"N", 3.660, 0.069},  {"O", 3.500, 0.060},
    {"F", 3.364, 0.050},  {"Ne", 3.243, 0.042}, {"Na", 2.983, 0.030}, {"Mg", 3.021, 0.111},
    {"Al", 4.499, 0.505}, {"Si", 4.295, 0.402}, {"P", 4.147, 0.305},  {"S", 4.035, 0.274},
    {"Cl", 3.947, 0.227}, {"Ar", 3.868, 0.185}, {"K", 3.812, 0.035},  {"Ca", 3.399, 0.238},
    {"Sc", 3.295, 0.019}, {"Ti", 3.175, 0.017}, {"V", 3.144, 0.016},  {"Cr", 3.023, 0.015},
    {"Mn", 2.961, 0.013}, {"Fe", 2.912, 0.013}, {"Co", 2.872, 0.014}, {"Ni", 2.834, 0.015},
    {"Cu", 3.495, 0.005}, {"Zn", 2.763, 0.124}, {"Ga", 4.383, 0.415}, {"Ge", 4.280, 0.379},
    {"As", 4.230, 0.309}, {"Se", 4.205, 0.291}, {"Br", 4.189, 0.251}, {"Kr", 4.141, 0.220},
}};
}  // namespace

std::optional<UffLennardJonesParameters> uffParameters(const std::string& element) {
  for (const Entry& e : kTable)
    if (element == e.element) return UffLennardJonesParameters{e.x, e.d};
  return std::nullopt;
}

std::string uffElementRange() { return "H to Kr (Z = 1..36)"; }

}  // namespace mesochain::objective
