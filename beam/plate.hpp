#pragma once
// Few-layer graphene as a plate: the bending rigidity per unit width of N layers that bend
// together (no interlayer slip), each layer a membrane of in-plane stiffness C2 at spacing Z0,
// about the stack's mid-plane (sum of C2 z_i^2 over z_i = (i - (N+1)/2) Z0, which is
// C2 Z0^2 N (N^2 - 1) / 12), with the plate factor 1 / (1 - nu^2), plus N times the bending
// rigidity D1 of a single layer:
//   D_plate(N) = N D1 + C2 Z0^2 N (N^2 - 1) / (12 (1 - nu^2)).
// With free interlayer sliding the layers bend independently: D_plate = N D1.
// Units: any consistent set, e.g. C2 in eV/Å^2, Z0 in Å, D1 and D_plate in eV (a plate's
// bending rigidity is a moment per unit width per unit curvature: an energy). The per-cell
// constant of a ribbon of width w and cell length T0 (U = 1/2 D (1/R)^2 per cell, as fitted by
// beam/) is D = D_plate w T0 in the same energy and length units.
namespace mesochain::beam {

double plateBendingRigidity(int layers, double inPlaneStiffness, double spacing, double poisson,
                            double singleLayerRigidity = 0.0);
double slidingLayersRigidity(int layers, double singleLayerRigidity);
// Per-cell bending constant (U = 1/2 D (1/R)^2 per cell) of a ribbon of width w.
double ribbonBendingConstant(double plateRigidity, double width, double cellLength);

}  // namespace mesochain::beam
