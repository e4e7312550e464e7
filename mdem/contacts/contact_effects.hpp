#pragma once
// Contacts as effects: "vdw_contact" (conservative, ledger entry "vdw") and "contact_damping"
// (dashpots, ledger entry "contact_dissipated"). Either one builds the neighbourhood they share
// (filament topology and neighbour list); a scene naming neither builds nothing (no list, no
// loop).
//
// Kernels run in parallel over the pairs into a per-pair buffer; each element then gathers its
// pairs' contributions in a fixed order, so results do not depend on the number of threads.
#include <limits>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "mdem/contacts/contact_dashpot.hpp"
#include "mdem/contacts/face_contact.hpp"
#include "mdem/contacts/neighbour_list.hpp"
#include "mdem/contacts/vdw_contact.hpp"
#include "mdem/effect.hpp"
#include "mdem/kick_work.hpp"
#include "mdem/scene.hpp"
#include "mdem/stability.hpp"

namespace mesochain::mdem {

class ContactNeighbourhood {
 public:
  // `interactionRange`, `axisRange`: as NeighbourList's (centre and axis-segment distances).
  ContactNeighbourhood(const Scene& scene, double interactionRange,
                       double axisRange = std::numeric_limits<double>::infinity());
  // Refreshes the list when needed; cheap otherwise.
  void update(const Bodies& b) { list_.update(b, halfLength_, topology_); }
  const NeighbourList& list() const { return list_; }
  const FilamentTopology& topology() const { return topology_; }
  const Periodicity& periodicity() const { return periodicity_; }
  double radius(int type) const { return radius_[type]; }
  Segment segment(const Bodies& b, int i) const {
    return {b.position[i], rotate(b.orientation[i], Vec3::UnitZ()), halfLength_[b.type[i]]};
  }
  // Segment of j placed at the minimum image next to `near`.
  Segment imageNear(const Bodies& b, int j, const Vec3& near) const {
    Segment s = segment(b, j);
    s.centre = near + periodicity_.minimumImage(s.centre - near);
    return s;
  }
  // The same two with the axis given (an effect's copy of every element's axis, formed in its
  // prepare() once per element instead of once per pair: the same bits as segment()'s rotation).
  Segment segment(const Bodies& b, int i, const Vec3& axis) const {
    return {b.position[i], axis, halfLength_[b.type[i]]};
  }
  Segment imageNear(const Bodies& b, int j, const Vec3& axis, const Vec3& near) const {
    return {near + periodicity_.minimumImage(b.position[j] - near), axis, halfLength_[b.type[j]]};
  }
  // The list's state (pairs and the positions it was built at), so that a resumed run rebuilds
  // at the same steps as an uninterrupted one.
  void saveList(BinaryWriter& out) const { list_.save(out); }
  void loadList(BinaryReader& in, int elementCount) { list_.load(in, elementCount); }

 private:
  Periodicity periodicity_;
  std::vector<double> halfLength_, radius_;  // per element type
  FilamentTopology topology_;
  NeighbourList list_;
};

class VdwContactEffect : public Effect {
 public:
  VdwContactEffect(const Scene& scene, std::shared_ptr<ContactNeighbourhood> neighbourhood, bool ownsNeighbourhood);
  std::string name() const override { return "vdw_contact"; }
  bool hasPrepare() const override { return true; }
  // Refreshes the neighbour list and the elements' axes.
  void prepare(const State& state, double time) override;
  int itemCount() const override { return static_cast<int>(results_.size()); }
  void computeItems(const State& state, double time, int lo, int hi) override;
  bool couplesFilaments() const override { return true; }
  void gather(const State& state, double time, int lo, int hi, Vec3* force, Vec3* torque) const override;
  // Entry "vdw".
  void reportEnergy(const State& state, EnergyLedger& ledger) const override;
  void addElementEnergies(const State& state, std::vector<double>& perElement) const override;
  void addStabilityTerms(std::vector<ContactStabilityTerms>& perType) const override;
  const ContactNeighbourhood* contactNeighbourhood() const override { return nb_.get(); }
  void saveState(BinaryWriter& out) const override;
  void loadState(BinaryReader& in) override;

  // Largest centre distance at which two elements of the scene interact.
  static double interactionRange(const Scene& scene);
  // Largest distance of the closest points of two axis segments at which the anisotropic tube
  // contact can be nonzero (its early-out distance, vdw_contact.hpp); infinite for the isotropic
  // form (centre distance) and for bricks.
  static double axisRange(const Scene& scene);
  // Tube types: the pair potential (null for bricks). Bricks: the face-to-face model (null for tubes).
  const TubePairPotential* potential(int typeA, int typeB) const;
  const FaceContactModel* faceModel() const { return face_.get(); }
  const ContactNeighbourhood& neighbourhood() const { return *nb_; }
  long pairCount() const { return static_cast<long>(nb_->list().pairs().size()); }
  // The contact of elements i and j (j at the minimum image next to i), whether listed or not.
  ContactPairResult evaluatePair(const Bodies& b, int i, int j) const { return evaluatePair(b, i, j, nullptr); }

 private:
  // With `axes` (null: formed here), every element's axis in `b`.
  ContactPairResult evaluatePair(const Bodies& b, int i, int j, const Vec3* axes) const;
  // InputError naming the elements when two start inside each other.
  void checkInitialOverlaps() const;
  struct TypePair {
    std::unique_ptr<TubePairPotential> potential;
    std::unique_ptr<IsotropicVdw> isotropic;
    // Anisotropic form: the segment kernel of the quadrature element against a partner of each
    // type (index: the partner's type), with its quadrature points (vdw_contact.hpp).
    std::vector<std::unique_ptr<AnisotropicVdwKernel>> kernelAgainst;
  };
  const Scene& scene_;
  VdwContactSpec spec_;
  int typeCount_ = 0;
  std::vector<TypePair> types_;  // typeCount^2, symmetric, shared pointers by (min, max)
  std::unique_ptr<FaceContactModel> face_;  // when the elements are bricks
  std::vector<double> width_, length_;      // per type
  std::shared_ptr<ContactNeighbourhood> nb_;
  bool ownsNeighbourhood_;  // saves the shared list in checkpoints
  std::vector<ContactPairResult> results_;
  std::vector<Vec3> axes_;  // per element, of the state of the last prepare (tubes)
};

class ContactDampingEffect : public Effect {
 public:
  ContactDampingEffect(const Scene& scene, std::shared_ptr<ContactNeighbourhood> neighbourhood, bool ownsNeighbourhood);
  std::string name() const override { return "contact_damping"; }
  bool dissipates() const override { return true; }
  bool hasPrepare() const override { return true; }
  // Refreshes the list when this effect owns that (refreshesList), and the elements' axes and
  // world angular velocities.
  void prepare(const State& state, double time) override;
  int itemCount() const override { return static_cast<int>(results_.size()); }
  void computeItems(const State& state, double time, int lo, int hi) override;
  bool couplesFilaments() const override { return true; }
  void gather(const State& state, double time, int lo, int hi, Vec3* force, Vec3* torque) const override;
  bool hasFinish() const override { return true; }
  void finish(const State& state, double time) override;  // charges the dissipated work
  bool wantsStepVelocities() const override { return true; }
  void kickForcesReplaced(const State& state) override;
  // Stores nothing; entry "contact_dissipated" (EnergyKind::Dissipated).
  void reportEnergy(const State& state, EnergyLedger& ledger) const override;
  void addStabilityTerms(std::vector<ContactStabilityTerms>& perType) const override;
  const ContactNeighbourhood* contactNeighbourhood() const override { return nb_.get(); }
  void saveState(BinaryWriter& out) const override;
  void loadState(BinaryReader& in) override;
  static double interactionRange(const Scene& scene);
  // The dashpot vanishes beyond a wall gap of cutoff_gap_nm: 2 R_max + that gap.
  static double axisRange(const Scene& scene);

 private:
  static bool refreshesList(const Scene& scene, bool owner);
  // The dashpots' work (kick_work.hpp): P = -F.v over every pair's forces and torques, in the
  // pairs' order (independent of the thread count).
  KickWork work_;
  // P at the velocities of the step's time (State::stepVelocity), with its pair forces and torques.
  double powerAtStepVelocities(const State& state) const;
  // P at the velocities the last force evaluation's items used.
  double powerAtItemVelocities() const;
  const Scene& scene_;
  ContactDampingSpec spec_;
  std::shared_ptr<ContactNeighbourhood> nb_;
  bool ownsNeighbourhood_;
  bool refreshesList_;  // refreshes the shared list in prepare (stepper.hpp)
  std::vector<ContactPairResult> results_;
  std::vector<double> power_;  // per pair
  std::vector<Vec3> axes_, angularVelocity_;  // per element (world), of the state of the last prepare
};

// Contact terms of the critical time step (stability.hpp, Effect::addStabilityTerms), per
// element type. Contacts change
// during a run, so each element is taken as crowded: in contact along its whole length with
// kContactCoordination neighbouring tubes (a close-packed bundle), each contact counted twice
// (Gershgorin: the element's own row and its coupling to the neighbour).
//  * vdW: the curvature Phi'' of the tube-tube potential at its minimum (the stiffest point of
//    the well), per unit length: stiffness 2 n Phi'' L, and about the axes normal to the element
//    2 n Phi'' L^3 / 12 (the contact resists tilting); none about the element's axis.
//  * dashpots: contact length lambda = L + R + R_max (aligned overlap plus the crossing term,
//    an upper bound), lever arm r of the contact point from the centre (sqrt((L/2)^2 + R_c^2)
//    about the normal axes, R_c = R + full_gap/2 about the element's axis): translational
//    2 n gamma lambda, rotational 2 n (gamma lambda r^2 + gamma_r lambda).
// Measured (docs/mdem-contacts.md): two crossed tubes at h = 2e-5 ns blow up for gamma between 5
// and 10 pN ns/nm^2; this estimate admits gamma up to about 2.7 there.
inline constexpr int kContactCoordination = 6;

// Contacts, aligned pairs, bundles and orientation of a network: contacts/network_structure.hpp.

}  // namespace mesochain::mdem
