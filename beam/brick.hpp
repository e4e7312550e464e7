#pragma once
// Brick discretisation of a beam (atomic units: Bohr, Hartree, dalton).
//
// A brick of length L = n T0 holds n cells. Its mass is n times the cell mass; its principal
// moments of inertia are those of a homogeneous rectangular block h x w x L about its centre
// (body x = thickness, y = width, z = length, as an mDEM brick):
//   I = m / 12 (w^2 + L^2, h^2 + L^2, h^2 + w^2),
// or of a solid cylinder of radius r for a round beam: (m/12 (3r^2 + L^2), same, m r^2 / 2).
// The parallel bond between neighbouring bricks (distance L) has stiffness per unit area
// k_n = Y / L, k_s = G / L with the beam's A, I_x, I_y, J, so that a chain reproduces
// C, K, D_s, D_h per cell (mdem/parallel_bond.hpp).
#include <Eigen/Dense>

#include "beam/beam_model.hpp"

namespace mesochain::beam {

struct Brick {
  int cellsPerBrick = 0;
  double length = 0.0;         // L, Bohr
  double mass = 0.0;           // dalton
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  // principal moments, dalton Bohr^2
  double normalStiffness = 0.0;  // k_n, Hartree / Bohr^4
  double shearStiffness = 0.0;   // k_s, Hartree / Bohr^4
  double thickness = 0.0, width = 0.0;  // rectangle h, w (Bohr)
  double radius = 0.0;         // round beams: the radius of the equivalent solid cylinder
  Section section;             // of the bond (equal to the beam's, or the equivalent disc)
  double young = 0.0, shear = 0.0;  // moduli carried by the bond, Hartree / Bohr^3
};

// cellMass in dalton (e.g. atoms_per_cell * 12.011). Round beams (circle, annulus) become a
// solid cylinder of radius r = sqrt(4 D / C) with moduli that keep C, K and D (for the annulus
// the stiffnesses are exact; the rotational inertia is that of the solid cylinder).
Brick discretise(const Beam& beam, int cellsPerBrick, double cellMass, const std::string& source);

}  // namespace mesochain::beam
