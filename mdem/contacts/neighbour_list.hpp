#pragma once
// Neighbour search for contacts between elements: cell lists with a Verlet skin, periodic
// boundaries on any axis (minimum image), and exclusion of near neighbours along one filament.
//
// Filaments are the connected components of the bond graph; an element's place along its
// filament is its rank by index within the component (elements of a generated filament are
// numbered along it). Two elements of one filament whose places differ by at most
// `excludeWithin` (cyclically for a closed filament) never form a contact pair.
#include <limits>
#include <utility>
#include <vector>

#include "mdem/body.hpp"
#include "mdem/contacts/contact_spec.hpp"
#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

class BinaryWriter;
class BinaryReader;

struct FilamentTopology {
  std::vector<int> filament;      // per element: filament id (ids ordered by first element)
  std::vector<int> place;         // per element: rank along its filament
  std::vector<int> filamentSize;  // per filament
  std::vector<char> closed;       // per filament
  int excludeWithin = 0;

  bool excluded(int i, int j) const;
};

FilamentTopology buildTopology(int elementCount, const std::vector<Bond>& bonds, int excludeWithin,
                               const std::vector<ClosedFilament>& closedFilaments);

class NeighbourList {
 public:
  // `interactionRange`: largest centre distance at which two elements can interact (nm).
  // `axisRange`: largest distance of the closest points of the two elements' axis segments at
  // which they can interact (nm; infinite: the centre distance alone decides). A pair is listed
  // when its centre distance is below interactionRange + skin and its segment distance below
  // axisRange + skin: the capsule around a 2-nm tube element holds about a third of the sphere
  // around its centre, and every listed pair costs its kernel's early-out test at every step.
  NeighbourList(double interactionRange, double skin, const Periodicity& periodicity,
                double axisRange = std::numeric_limits<double>::infinity());
  ~NeighbourList();
  NeighbourList(const NeighbourList&) = delete;
  NeighbourList& operator=(const NeighbourList&) = delete;

  // Rebuilds the pair list when an element end has moved by more than skin/2 since the last
  // build (or on the first call). Returns true when it rebuilt.
  bool update(const Bodies& bodies, const std::vector<double>& halfLength, const FilamentTopology& topology);
  // Half list (i < j), sorted, each pair within both ranges + skin at the last build.
  const std::vector<std::pair<int, int>>& pairs() const { return pairs_; }
  // For gathering per element: entries [start[i], start[i+1]) of `incident`, each 2*pair + side.
  const std::vector<int>& incidentStart() const { return start_; }
  const std::vector<int>& incident() const { return incident_; }
  long builds() const { return builds_; }
  double listRange() const { return range_ + skin_; }
  double axisRange() const { return axisRange_; }

  // Checkpoints: the pairs, the positions and axes of the last build and the build count.
  void save(BinaryWriter& out) const;
  void load(BinaryReader& in, int elementCount);

  // Number of NeighbourList objects alive (a scene without contacts must build none).
  static int live();

 private:
  void build(const Bodies& bodies, const std::vector<double>& halfLength, const FilamentTopology& topology);
  void buildIncidence(int elementCount);
  double range_, skin_, axisRange_;
  Periodicity periodicity_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<int> start_, incident_;
  std::vector<Vec3> builtPosition_, builtAxis_;
  long builds_ = 0;
  // Build buffers, kept between builds (no allocation once they have grown).
  std::vector<Vec3> wrapped_;
  std::vector<int> head_, members_, cellOf_, fill_;
  std::vector<std::vector<std::pair<int, int>>> threadPairs_;
};

}  // namespace mesochain::mdem
