#pragma once
// Confining potentials added to the atomic Kohn-Sham potential to compress the orbitals or the
// density of the free atom (Eschrig; Porezag et al., Phys. Rev. B 51, 12947 (1995)):
//   power law    v(r) = (r / r0)^n
//   Woods-Saxon  v(r) = W / (1 + exp(−a (r − r0)))
#include <string>

namespace mesochain::skgen {

struct Confinement {
  enum class Type { None, Power, WoodsSaxon };
  Type type = Type::None;
  double r0 = 0.0;     // Bohr
  double power = 2.0;  // power law exponent n
  double height = 0.0; // Woods-Saxon W (Hartree)
  double slope = 0.0;  // Woods-Saxon a (1/Bohr)

  static Confinement none() { return {}; }
  static Confinement powerLaw(double r0, double n) {
    Confinement c;
    c.type = Type::Power;
    c.r0 = r0;
    c.power = n;
    return c;
  }
  static Confinement woodsSaxon(double r0, double height, double slope) {
    Confinement c;
    c.type = Type::WoodsSaxon;
    c.r0 = r0;
    c.height = height;
    c.slope = slope;
    return c;
  }
  double operator()(double r) const;
  std::string describe() const;
};

}  // namespace mesochain::skgen
