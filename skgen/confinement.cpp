#include "skgen/confinement.hpp"

#include <cmath>

#include <fmt/format.h>

namespace mesochain::skgen {

double Confinement::operator()(double r) const {
  switch (type) {
    case Type::None: return 0.0;
    case Type::Power: return std::pow(r / r0, power);
    case Type::WoodsSaxon: return height / (1.0 + std::exp(-slope * (r - r0)));
  }
  return 0.0;
}

std::string Confinement::describe() const {
  switch (type) {
    case Type::None: return "none";
    case Type::Power: return fmt::format("(r/{:g})^{:g}", r0, power);
    case Type::WoodsSaxon: return fmt::format("woods-saxon W={:g} a={:g} r0={:g}", height, slope, r0);
  }
  return "?";
}

}  // namespace mesochain::skgen
