#pragma once
// The recipe of the published pbc-0-3 carbon and hydrogen tables (their documentation blocks:
// PBE, density superposition, Slater basis, (r/r0)^2 confinement; carbon exponents 0.50 1.14
// 2.62 6.0, density r0 7.0, wavefunction r0 2.7; hydrogen 0.50 1.0 2.0, 2.5, 3.0), built once
// per test binary.
#include <filesystem>
#include <string>

#include "skgen/element_basis.hpp"

namespace mesochain::testing {

inline skgen::ElementBasis pbcBasis(const std::string& symbol) {
  using namespace mesochain::skgen;
  ElementSettings s;
  s.symbol = symbol;
  s.xc = XcKind::Pbe;
  s.hubbardXc = XcKind::LdaPw92;  // the published carbon U is the LDA value
  s.h = 0.008;
  if (symbol == "C") {
    s.density = Confinement::powerLaw(7.0, 2.0);
    s.shells = {Confinement::powerLaw(2.7, 2.0), Confinement::powerLaw(2.7, 2.0)};
    s.slater = {{0.50, 1.14, 2.62, 6.0}, 3};
  } else {
    s.density = Confinement::powerLaw(2.5, 2.0);
    s.shells = {Confinement::powerLaw(3.0, 2.0)};
    s.slater = {{0.50, 1.0, 2.0}, 3};
  }
  return buildElementBasis(s);
}

inline const skgen::ElementBasis& pbcCarbon() {
  static const skgen::ElementBasis b = pbcBasis("C");
  return b;
}

inline const skgen::ElementBasis& pbcHydrogen() {
  static const skgen::ElementBasis b = pbcBasis("H");
  return b;
}

inline std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("mesochain-skgen-" + name)).string();
}

}  // namespace mesochain::testing
