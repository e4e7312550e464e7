#pragma once
// Critical time step of the explicit integrator, from the bond stiffness against the mass and
// the principal moments of inertia.
//
// Velocity Verlet is stable for a linear system when h < 2 / omega_max, omega_max^2 the largest
// eigenvalue of M^{-1} K. We bound omega_max^2 from above, rigorously, by Gershgorin's theorem
// applied to M^{-1/2} K M^{-1/2}, with K the bonds' linearised stiffness (parallel_bond.hpp,
// linearStiffness) written in each element's principal frame so that M is diagonal
// (m, m, m, I_1, I_2, I_3): omega_max^2 <= max_i sum_j |K_ij| / sqrt(M_ii M_jj).
// DOFs of elements that are completely constrained (all six fixed, or prescribed) are left
// out. The returned step is therefore never above the true stability limit; for a uniform
// chain it is within a factor of about 2 of it.
//
// Contacts (vdW springs and dashpots) come in as per-element-type terms (ContactStabilityTerms,
// built by the contact effects): a stiffness added to the Gershgorin row of each DOF, and a
// damping rate beta (1/ns) per DOF. For a damped oscillator x'' = -omega^2 x - beta x' the
// explicit central-difference / Verlet scheme is stable for
//   h <= (2 / omega) (sqrt(1 + zeta^2) - zeta),  zeta = beta / (2 omega)
// (-> 2 / beta without stiffness); the bound is taken per DOF with that DOF's omega and beta.
// Contacts change during a run, so their terms are an estimate for a crowded state (see
// contact_effects.hpp), not a bound on the initial state alone.
#include <string>
#include <vector>

#include "mdem/boundary.hpp"
#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

// Contact terms of one element type: what a crowded element feels from its contacts.
struct ContactStabilityTerms {
  double stiffness = 0.0;                  // pN/nm, Gershgorin row term of each translation
  Vec3 rotationalStiffness = Vec3::Zero(); // pN nm/rad, about the body axes
  double damping = 0.0;                    // pN ns/nm, dashpot row term of each translation
  Vec3 rotationalDamping = Vec3::Zero();   // pN nm ns, about the body axes
  ContactStabilityTerms& operator+=(const ContactStabilityTerms& o) {
    stiffness += o.stiffness, rotationalStiffness += o.rotationalStiffness;
    damping += o.damping, rotationalDamping += o.rotationalDamping;
    return *this;
  }
};

struct StabilityLimit {
  double criticalTimeStep = 0.0;  // ns (infinite without bonds or contacts)
  double omegaMax = 0.0;          // rad/ns, the Gershgorin bound (bonds + contact stiffness)
  int element = -1;               // element whose DOF gives the step
  bool rotational = false;        // whether that DOF is rotational
  // What limits that DOF most: "bonds", "van der Waals contacts" or "contact dashpots".
  std::string limitedBy = "bonds";
  double omega = 0.0;             // rad/ns, of the limiting DOF
  double dampingRate = 0.0;       // 1/ns, beta of the limiting DOF
};

// Frame of the translational DOFs in the Gershgorin rows ([run] critical_step). World: the
// world axes (the default). Body: each element's principal axes, like its rotations. The mass
// block of a translation is m 1 in any orthonormal frame, so both are rigorous bounds; in the
// body frame an element's axial stretching sits in one row instead of being spread over the world
// rows of an oblique element, which for a straight chain makes the axial rows exact
// (docs/benchmarks.md, "What sets the mDEM time step": world 1.12-1.22 x the true omega there).
enum class GershgorinFrame { World, Body };

// `contactTerms` (may be empty): one entry per element type.
StabilityLimit criticalTimeStep(const Bodies& bodies, const std::vector<Bond>& bonds,
                                const KinematicMap& kinematics,
                                const std::vector<ContactStabilityTerms>& contactTerms = {},
                                GershgorinFrame frame = GershgorinFrame::World);

}  // namespace mesochain::mdem
