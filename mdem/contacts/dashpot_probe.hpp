#pragma once
// Where and how fast the contact dashpots act (`mesochain-bench zipping`, docs/mdem-contacts.md
// "Why the zipping time hardly depends on gamma"). The element pairs of different filaments are
// sorted by the wall gap of their axis segments (contact_dashpot.hpp: wallGap) into the bands of
// the two contact effects:
//   full      gap <  fullGap                 dashpot at full weight (s = 1)
//   ramp      fullGap <= gap < cutoffGap     dashpot weight falling from 1 to 0
//   vdwOnly   cutoffGap <= gap < vdW cut-off van der Waals force, no dashpot
// and for each band the relative velocity of the two elements at their contact point c (the
// midpoint of the closest points of the axes, as in the dashpot) is summed. The dashpots'
// dissipated power follows from the same pass:
//   P = gamma sum(lambda s |v_rel|^2) + gamma_r sum(lambda s |w_b - w_a|^2)   (pN nm/ns = zJ/ns),
// which equals -(sum of F.v + M.w) of the dashpot forces of contactDashpot (the identity the test
// checks).
// sum(lambda s |c - pivot|^2) gives the dashpots' resistance to a relative rotation about a pivot
// (the crossing point of two zipping tubes).
#include <cmath>
#include <vector>

#include "mdem/contacts/contact_dashpot.hpp"

namespace mesochain::mdem {

struct ContactBandProbe {
  int pairs = 0;
  double sumSpeedSquared = 0.0;  // sum of |v_rel|^2 at the contact points, nm^2/ns^2
  // Root mean square relative speed of the band's pairs (nm/ns); 0 for an empty band.
  double rmsSpeed() const { return pairs > 0 ? std::sqrt(sumSpeedSquared / pairs) : 0.0; }
};

struct DashpotProbe {
  ContactBandProbe full, ramp, vdwOnly;
  double weightedLength = 0.0;     // sum of lambda s, nm
  double translationalRate = 0.0;  // sum of lambda s |v_rel|^2, nm^3/ns^2 (power / gamma)
  double rotationalRate = 0.0;     // sum of lambda s |w_b - w_a|^2, nm/ns^2 (power / gamma_r)
  // sum of lambda s |c - pivot|^2, nm^3: the dashpots resist a relative rotation about `pivot` at
  // rate theta' with the moment gamma (this) theta' (translational part).
  double weightedLengthMoment = 0.0;
  // Power dissipated by the dashpots, zJ/ns.
  double power(const ContactDampingSpec& spec) const {
    return spec.translational * translationalRate + spec.rotational * rotationalRate;
  }
  // lambda s weighted root mean square of |v_rel| over the dashpot contacts (nm/ns): the speed
  // with which P_translational = gamma (sum lambda s) v^2.
  double weightedRmsSpeed() const {
    return weightedLength > 0.0 ? std::sqrt(translationalRate / weightedLength) : 0.0;
  }
};

struct ProbeElement {
  Segment segment;
  double radius = 0.0;  // nm
  Vec3 velocity = Vec3::Zero(), angularVelocity = Vec3::Zero();  // nm/ns, rad/ns (world)
  int filament = 0;     // pairs of one filament are left out
};

// All pairs of elements of different filaments (O(N^2): for small calibration scenes; no
// periodic images). `vdwCutoffGap` (nm) closes the vdwOnly band; `pivot` is the point the
// weightedLengthMoment is taken about.
DashpotProbe probeDashpots(const ContactDampingSpec& spec, double vdwCutoffGap,
                           const std::vector<ProbeElement>& elements, const Vec3& pivot = Vec3::Zero());

}  // namespace mesochain::mdem
