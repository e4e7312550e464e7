#pragma once
// Slater-Koster parameter set: species data and pair integrals read from DFTB+ .skf tables.
//
// Orbital order inside one atom: s, p_x, p_y, p_z (only the first `orbitalCount` are used).
// All quantities in atomic units (Hartree, Bohr).
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace mesochain::dftb {

inline constexpr int kMaxOrbitalsPerAtom = 4;  // s and p shells
using OrbitalBlock = Eigen::Matrix<double, kMaxOrbitalsPerAtom, kMaxOrbitalsPerAtom>;

struct SpeciesData {
  std::string name;
  int maxAngularMomentum = 0;  // 0 = s only, 1 = s and p
  int orbitalCount = 1;        // 1 or 4
  double onsiteS = 0.0;        // Hartree (free-atom eigenvalues from the homonuclear table)
  double onsiteP = 0.0;
  double hubbardU = 0.0;       // Hartree (s-shell value, as used by SCC)
  double valenceElectrons = 0.0;  // sum of the occupations of the shells in use (s .. l_max)
  double mass = 0.0;              // atomic mass units, as in the table
};

// Integrals of one ordered species pair (A, B) as a function of the distance vector
// d = x_B - x_A (Bohr). Block (alpha, beta) = <phi_alpha^A | H | phi_beta^B> with the
// Slater-Koster rotation of s and p orbitals (Slater & Koster, Phys. Rev. 94, 1498 (1954)).
class PairIntegrals {
 public:
  virtual ~PairIntegrals() = default;
  // Largest distance with a non-zero integral (Bohr).
  virtual double cutoff() const = 0;
  // H and S blocks (top-left nA x nB used; the rest is zero).
  virtual void blocks(const Eigen::Vector3d& d, OrbitalBlock& h, OrbitalBlock& s) const = 0;
  // Blocks and their derivatives with respect to the components of d.
  virtual void blocksWithDerivatives(const Eigen::Vector3d& d, OrbitalBlock& h, OrbitalBlock& s,
                                     OrbitalBlock dh[3], OrbitalBlock ds[3]) const = 0;
};

// A radial pair potential V(r) (repulsive spline or polynomial of a table, dispersion kernel).
class RadialPotential {
 public:
  virtual ~RadialPotential() = default;
  virtual double cutoff() const = 0;
  // V(r) and dV/dr; zero beyond the cutoff.
  virtual void evaluate(double r, double& value, double& derivative) const = 0;
};

class ParameterSet {
 public:
  // files: "A-B" -> path of A-B.skf, for every ordered pair of the species in use
  // (A-A for each species). `source` names the input that listed them (for errors).
  // maxAngularMomentum: optional per-species override ("s" or "p"); by default the highest
  // shell with a non-zero occupation in A-A.skf. A d shell gives InputError
  // "d shells not supported yet".
  // polynomialRepulsive: pairs "A-B" whose repulsive is the polynomial of the mass line instead
  // of the Spline block (DFTB+ keyword PolynomialRepulsive; by default every pair uses the
  // spline and a table without a Spline block is an error, as in DFTB+).
  // Implementation: dftb/parameters.cpp; tables: dftb/skf_file.hpp; interpolation:
  // dftb/sk_grid.hpp; rotation and heteronuclear convention: dftb/sk_pair.hpp.
  static ParameterSet load(const std::vector<std::string>& species,
                           const std::map<std::string, std::string>& files,
                           const std::string& source,
                           const std::map<std::string, int>& maxAngularMomentum = {},
                           const std::set<std::string>& polynomialRepulsive = {});

  int speciesCount() const { return static_cast<int>(species_.size()); }
  const SpeciesData& species(int a) const { return species_[a]; }
  const PairIntegrals& integrals(int a, int b) const { return *integrals_[a * nSpecies() + b]; }
  const RadialPotential& repulsive(int a, int b) const { return *repulsive_[a * nSpecies() + b]; }
  // Largest integral cutoff and largest repulsive cutoff over all pairs (Bohr).
  double integralCutoff() const;
  double repulsiveCutoff() const;

 private:
  int nSpecies() const { return static_cast<int>(species_.size()); }
  std::vector<SpeciesData> species_;
  std::vector<std::shared_ptr<const PairIntegrals>> integrals_;    // row-major [a][b]
  std::vector<std::shared_ptr<const RadialPotential>> repulsive_;  // row-major [a][b]
};

}  // namespace mesochain::dftb
