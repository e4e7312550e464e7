#include "objective/drivers/scan.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/progress_bar.hpp"
#include "common/units.hpp"
#include "objective/core/collapsed_tube_builder.hpp"
#include "objective/core/kgrid.hpp"
#include "objective/drivers/scan_checkpoint.hpp"
#include "objective/drivers/scan_reference.hpp"

namespace mesochain::objective {

const char* scanKindName(ScanKind kind) {
  switch (kind) {
    case ScanKind::Stretch: return "stretch";
    case ScanKind::Twist: return "twist";
    case ScanKind::Bend: return "bend";
  }
  return "?";
}

const char* deformationUnit(ScanKind kind) {
  switch (kind) {
    case ScanKind::Stretch: return "strain";
    case ScanKind::Twist: return "rad_per_cell";
    case ScanKind::Bend: return "per_bohr";
  }
  return "?";
}

const char* bendDirectionName(BendDirection d) { return d == BendDirection::Soft ? "soft" : "hard"; }

namespace {

const char* kSource = "<scan>";

// One planned point: its deformation, the value that sets the symmetry, and the plan index of
// the point whose relaxed atoms start it (-1 for the reference).
struct PlanEntry {
  double deformation = 0.0;
  double value = 0.0;  // strain or twist change (rad); unused for bend
  int rotationOrder = 0;
  int from = -1;
};

// The geometry of a bend scan: rings from a straight translational cell, or (sector) a cell
// that is already a sector of 2 pi / N_ref about z (a bent graphene stack) rebent to other N_a.
struct BendSource {
  bool sector = false;
  int referenceOrder = 0;  // N_ref of a sector cell
  double arc = 0.0;        // sector: arc length per cell along the middle radius (Bohr)
};

// Checks a list of ring orders (>= 2, distinct, not empty).
void checkOrders(const std::vector<int>& orders) {
  if (orders.empty())
    throw InputError(kSource, "rotation orders", "an empty list", "at least one ring order N_a");
  std::set<int> seen;
  for (int n : orders) {
    if (n < 2)
      throw InputError(kSource, "rotation orders", std::to_string(n), "ring orders N_a >= 2");
    if (!seen.insert(n).second)
      throw InputError(kSource, "rotation orders", fmt::format("{} twice", n),
                       "distinct ring orders");
  }
}

std::vector<PlanEntry> makePlan(const ScanSettings& s, double t0, const BendSource& b) {
  std::vector<PlanEntry> plan{{0.0, 0.0, 0, -1}};
  if (s.kind == ScanKind::Bend && b.sector) {
    checkOrders(s.rotationOrders);
    auto curvature = [&](int n) { return 2 * units::kPi / (n * b.arc); };
    plan[0] = {curvature(b.referenceOrder), 0.0, b.referenceOrder, -1};
    std::vector<int> gentler, tighter;
    for (int n : s.rotationOrders) {
      if (n > b.referenceOrder) gentler.push_back(n);
      if (n < b.referenceOrder) tighter.push_back(n);
    }
    std::sort(gentler.begin(), gentler.end());
    std::sort(tighter.rbegin(), tighter.rend());
    for (const auto* side : {&gentler, &tighter}) {
      int from = 0;
      for (int n : *side) {
        plan.push_back({curvature(n), 0.0, n, from});
        from = static_cast<int>(plan.size()) - 1;
      }
    }
    return plan;
  }
  if (s.kind == ScanKind::Bend) {
    checkOrders(s.rotationOrders);
    std::vector<int> orders = s.rotationOrders;
    std::sort(orders.rbegin(), orders.rend());
    for (int n : orders) {
      const double radius = n * t0 / (2 * units::kPi);
      plan.push_back({1.0 / radius, 0.0, n, static_cast<int>(plan.size()) - 1});
    }
    return plan;
  }
  if (s.values.empty())
    throw InputError(kSource, s.kind == ScanKind::Stretch ? "strains" : "twists", "an empty list",
                     "at least one deformation");
  std::vector<double> pos, neg;
  std::set<double> seen;
  for (double v : s.values) {
    if (!std::isfinite(v) || (s.kind == ScanKind::Stretch && !(v > -1.0)))
      throw InputError(kSource, s.kind == ScanKind::Stretch ? "strains" : "twists",
                       fmt::format("{}", v),
                       s.kind == ScanKind::Stretch ? "finite strains > -1" : "finite twists");
    if (!seen.insert(v).second)
      throw InputError(kSource, s.kind == ScanKind::Stretch ? "strains" : "twists",
                       fmt::format("{} twice", v), "distinct deformations");
    if (v > 0) pos.push_back(v);
    if (v < 0) neg.push_back(v);  // 0 is the reference itself
  }
  std::sort(pos.begin(), pos.end());
  std::sort(neg.rbegin(), neg.rend());
  for (const auto* side : {&pos, &neg}) {
    int from = 0;
    for (double v : *side) {
      plan.push_back({v, v, 0, from});
      from = static_cast<int>(plan.size()) - 1;
    }
  }
  return plan;
}

// The warm-start cell of a point from the relaxed cell of its neighbour.
ObjectiveCell startingCell(const ScanSettings& s, const BendSource& b, const PlanEntry& e,
                           const ScanPoint& from, const ScanPoint& reference, double t0,
                           double gamma0) {
  if (s.kind == ScanKind::Bend && b.sector) {
    const double rFrom = from.rotationOrder * b.arc / (2 * units::kPi);
    const double rTo = e.rotationOrder * b.arc / (2 * units::kPi);
    return rebendSector(from.cell, rFrom, rTo, e.rotationOrder);
  }
  if (s.kind == ScanKind::Bend) {
    if (e.from == 0)
      return straightToRing(reference.cell, bendFrame(reference.cell, s.direction),
                            e.rotationOrder);
    const double rFrom = from.rotationOrder * t0 / (2 * units::kPi);
    return straightToRing(ringToStraight(from.cell, rFrom), BendFrame{}, e.rotationOrder);
  }
  ObjectiveCell c = from.cell;
  const Symmetry& sym = c.symmetry;
  if (s.kind == ScanKind::Stretch) {
    const double t = t0 * (1.0 + e.value);
    c.positions.row(2) *= t / sym.translation();
    c.symmetry = Symmetry::screw(t, gamma0, sym.rotationOrder());
  } else {
    const double g = gamma0 + e.value;
    const double dg = g - sym.twist();
    for (int a = 0; a < c.atomCount(); ++a) {
      const Eigen::Vector3d x = c.positions.col(a);
      c.positions.col(a) = rotationZ(dg * x.z() / sym.translation()) * x;
    }
    c.symmetry = Symmetry::screw(sym.translation(), g, sym.rotationOrder());
  }
  return c;
}

// The plan after the reference as chains: each starts from the reference (from == 0) and goes
// on while the next point starts from the previous one (how makePlan builds it).
std::vector<std::vector<int>> planChains(const std::vector<PlanEntry>& plan) {
  std::vector<std::vector<int>> chains;
  for (int k = 1; k < static_cast<int>(plan.size()); ++k) {
    if (plan[k].from == 0 || chains.empty()) {
      chains.push_back({k});
    } else {
      if (plan[k].from != k - 1) throw std::logic_error("scan plan: a point not after its neighbour");
      chains.back().push_back(k);
    }
  }
  return chains;
}

}  // namespace

ScanResult runScan(const ObjectiveCell& cell, std::shared_ptr<const dftb::ParameterSet> params,
                   const dftb::CalculatorSettings& calcSettings, const ScanSettings& s,
                   const parallel::Communicator& comm) {
  if (s.kind == ScanKind::Bend && std::abs(cell.symmetry.twist()) > 1e-12)
    throw InputError(kSource, "the cell of a bend scan",
                     fmt::format("rotation order {}, twist {:.6g} rad",
                                 cell.symmetry.rotationOrder(), cell.symmetry.twist()),
                     "a straight translational cell (twist 0, rotation order 1) or a sector "
                     "of a ring (twist 0, rotation order >= 2, e.g. a bent graphene stack)");
  if (cell.symmetry.isRing())
    throw InputError(kSource, "the cell of a scan", "a closed ring (translation 0)",
                     "a straight cell (translation > 0)");
  ScanResult out;
  out.kind = s.kind;
  out.direction = s.direction;
  out.atomsPerCell = cell.atomCount();
  out.inputHash = scanInputHash(cell, calcSettings, s);
  // Validates the lists before any work. The plan's curvatures need T0: the input's until the
  // reference is relaxed (or restored).
  BendSource bendSource;
  if (s.kind == ScanKind::Bend && !cell.symmetry.isRing() && cell.symmetry.rotationOrder() >= 2) {
    bendSource.sector = true;
    bendSource.referenceOrder = cell.symmetry.rotationOrder();
    bendSource.arc = 2 * units::kPi * meanRingRadius(cell) / bendSource.referenceOrder;
  }
  std::vector<PlanEntry> plan = makePlan(s, cell.symmetry.translation(), bendSource);

  dftb::CalculatorSettings ringSettings = calcSettings;
  ringSettings.band.helicalKPoints = 1;
  ringSettings.band.angular = s.ringAngular;
  // The calculators of straight cells and of rings, on the ranks that share one point.
  struct Calculators {
    dftb::Calculator straight, ring;
  };
  const auto calculatorsOn = [&](const parallel::Communicator& c) {
    return std::make_unique<Calculators>(Calculators{dftb::Calculator(params, calcSettings, c),
                                                     dftb::Calculator(params, ringSettings, c)});
  };
  const std::unique_ptr<Calculators> allRanks = calculatorsOn(comm);

  ScanCheckpoint checkpoint;
  checkpoint.inputHash = out.inputHash;
  checkpoint.settings = scanIdentity(cell, calcSettings, s);
  checkpoint.kind = s.kind;
  std::error_code ec;
  if (s.resume && !s.checkpointPath.empty() && std::filesystem::exists(s.checkpointPath, ec)) {
    ScanCheckpoint old = readScanCheckpoint(s.checkpointPath, cell);
    comm.barrier();  // every rank has read it before rank 0 rewrites it below
    requireCheckpointOfThisInput(s.checkpointPath, old, cell, calcSettings, s,
                                 "remove it or run without --resume to start afresh");
    // Points are matched by deformation value (bend: ring order) against the plan of this list.
    std::vector<PlannedPoint> keys;
    for (const PlanEntry& e : plan) keys.push_back({e.deformation, e.rotationOrder});
    std::map<std::string, std::string> settings = std::move(checkpoint.settings);
    checkpoint = reuseCheckpoint(std::move(old), keys);
    checkpoint.inputHash = out.inputHash;
    checkpoint.settings = std::move(settings);
    out.reused = static_cast<int>(checkpoint.completed.size());
    out.keptAside = static_cast<int>(checkpoint.keptAside.size());
    std::cerr << fmt::format("mesochain: resuming {}: {} points reused, {} new", s.checkpointPath,
                             out.reused, plan.size() - checkpoint.completed.size());
    if (out.keptAside > 0)
      std::cerr << fmt::format("; {} completed points not in the list kept aside in the "
                               "checkpoint (not part of the curve)", out.keptAside);
    std::cerr << "\n";
    writeScanCheckpoint(s.checkpointPath, checkpoint, cell);  // in the layout of this list
  }

  std::map<int, ScanPoint>& done = checkpoint.completed;
  if (s.reference && !done.count(0)) {
    // The shared reference stands for point 0 (the same relaxation, done once).
    requireSameReference(*s.reference, referenceIdentity(cell, calcSettings, s));
    ScanPoint p = s.reference->point;
    p.deformation = plan[0].deformation;
    p.rotationOrder = plan[0].rotationOrder;
    p.measuredCurvature = bendSource.sector ? 1.0 / meanRingRadius(p.cell) : std::nan("");
    done[0] = std::move(p);
  }
  // Converged SCC charges after each point computed here (the warm start of its neighbours).
  struct Charges {
    bool ring = false;
    std::vector<int> species;
    Eigen::VectorXd dq;
  };
  std::map<int, Charges> chargesAfter;
  // Points relaxed by all ranks together keep their progress in the checkpoint (rank 0 writes);
  // points of groups of ranks (below) do not.
  bool snapshotPoints = !s.checkpointPath.empty();
  auto relaxPoint = [&](const Calculators& calcs, int index, ObjectiveCell start, bool reference,
                        ProgressBar& bar, int total) {
    const PlanEntry& e = plan[index];
    const bool ring = start.symmetry.isRing();
    const dftb::Calculator& calc = ring ? calcs.ring : calcs.straight;
    calc.chargeCache().clear();
    if (const auto it = chargesAfter.find(e.from); it != chargesAfter.end() && it->second.ring == ring)
      calc.chargeCache().store(it->second.species, it->second.dq);
    const std::vector<int> species = start.species;
    RelaxSettings rs = s.relax;
    rs.relaxTranslation = reference && s.relax.relaxTranslation;
    const auto userProgress = s.relax.progress;
    rs.progress = [&, userProgress, index, total](int step, double f, double fmax) {
      if (userProgress) userProgress(step, f, fmax);
      bar.update(index, fmt::format("point {}/{}: evaluation {} max|force| {:.1e}", index + 1,
                                    total, step, fmax));
    };
    if (snapshotPoints) {
      if (checkpoint.inProgress && checkpoint.inProgress->index == index) {
        const RelaxProgress& from = checkpoint.inProgress->progress;
        if (comm.isRoot())
          std::cerr << fmt::format("mesochain: point {}/{} continues from its snapshot in {} ({} evaluations, "
                                   "{} fixed-T relaxation(s) done)\n",
                                   index + 1, total, s.checkpointPath, from.evaluations, from.history.size());
        rs.resumeFrom = std::make_shared<const RelaxProgress>(from);
      }
      rs.snapshotSeconds = s.snapshotSeconds;
      rs.snapshot = [&, index](const RelaxProgress& now) {
        checkpoint.inProgress = PointInProgress{index, e.deformation, e.rotationOrder, now};
        checkpoint.planSize = total;
        if (comm.isRoot()) writeScanCheckpoint(s.checkpointPath, checkpoint, cell);
      };
    }
    const auto t0 = std::chrono::steady_clock::now();
    RelaxOutcome o;
    try {
      o = relax(calc, std::move(start), rs);
    } catch (const InputError& err) {
      // A deformation (or a relaxation step) that collapses atoms: an error naming the point.
      const std::string what =
          s.kind == ScanKind::Bend
              ? fmt::format("scan point {} of {} (ring of rotation order {})", index + 1, total,
                            e.rotationOrder)
              : fmt::format("scan point {} of {} ({} {} {})", index + 1, total,
                            scanKindName(s.kind), e.deformation, deformationUnit(s.kind));
      throw InputError(what, err.what());
    }
    if (const auto dq = calc.chargeCache().stored(species)) chargesAfter[index] = {ring, species, *dq};
    if (checkpoint.inProgress && checkpoint.inProgress->index == index) checkpoint.inProgress.reset();
    ScanPoint p;
    p.timeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    p.deformation = e.deformation;
    p.rotationOrder = e.rotationOrder;
    p.energy = o.result.freeEnergy;
    for (const dftb::LedgerEntry& entry : o.result.energies.entries())
      p.energies[entry.name] = entry.value;
    p.converged = o.converged;
    p.maxForce = maxForce(o.result.gradient);
    p.evaluations = o.evaluations;
    const auto& band = calc.settings().band;
    p.helicalKPoints = ring ? 1 : band.helicalKPoints;
    p.angularPoints =
        HelicalKGrid(o.cell.symmetry, p.helicalKPoints, band.angular).angularCount();
    if (ring || (bendSource.sector && s.kind == ScanKind::Bend))
      p.measuredCurvature = 1.0 / meanRingRadius(o.cell);
    p.cell = std::move(o.cell);
    return p;
  };
  // The warm-start cell of plan point k (k >= 1) from the relaxed cell of its neighbour.
  const auto startOf = [&](int k) {
    const ScanPoint& ref = done.at(0);
    return startingCell(s, bendSource, plan[k], done.at(plan[k].from), ref,
                        ref.cell.symmetry.translation(), ref.cell.symmetry.twist());
  };

  ProgressBar bar(fmt::format("scan {}", scanKindName(s.kind)), static_cast<int>(plan.size()));
  if (!s.progressBar) bar.finish();
  bar.skip(static_cast<int>(done.size()));
  int computed = 0;
  const int total = static_cast<int>(plan.size());
  // Groups of ranks for the chains: with more than one rank, no --stop-after, and at least two
  // chains with points to compute.
  const std::vector<std::vector<int>> chains = planChains(plan);
  std::vector<std::vector<int>> pendingChains;
  for (const std::vector<int>& c : chains) {
    std::vector<int> pending;
    for (int k : c)
      if (!done.count(k)) pending.push_back(k);
    if (!pending.empty()) pendingChains.push_back(std::move(pending));
  }
  const bool grouped = comm.size() > 1 && s.stopAfter < 0 && pendingChains.size() >= 2;
  for (int k = 0; k < total; ++k) {
    if (grouped && k == 1) break;  // the chains, below
    if (!done.count(k)) {
      if (s.stopAfter >= 0 && computed >= s.stopAfter) break;
      bar.update(k, fmt::format("point {}/{}", k + 1, total));
      done[k] = k == 0 ? relaxPoint(*allRanks, 0, cell, true, bar, total)
                       : relaxPoint(*allRanks, k, startOf(k), false, bar, total);
      ++computed;
      checkpoint.planSize = total;
      if (!s.checkpointPath.empty()) writeScanCheckpoint(s.checkpointPath, checkpoint, cell);
      bar.update(k + 1);
    }
    if (s.pointDone && done.count(k)) s.pointDone(done.at(k), k, total);
    // Bend curvatures 1/R = 2 pi / (N_a T0) follow T0 of the relaxed reference.
    if (k == 0) plan = makePlan(s, done.at(0).cell.symmetry.translation(), bendSource);
  }
  if (grouped) {
    snapshotPoints = false;
    // Chain c of the pending ones goes to group c mod G; group g holds the ranks
    // [g size / G, (g + 1) size / G).
    const int groups = std::min<int>(static_cast<int>(pendingChains.size()), comm.size());
    const int color = comm.rank() * groups / comm.size();
    const parallel::Communicator group = comm.split(color);
    const std::unique_ptr<Calculators> groupCalcs = calculatorsOn(group);
    std::vector<std::vector<int>> work(groups);
    for (std::size_t c = 0; c < pendingChains.size(); ++c)
      for (int k : pendingChains[c]) work[c % groups].push_back(k);
    std::size_t rounds = 0;
    for (const auto& w : work) rounds = std::max(rounds, w.size());
    int reported = 1;  // the reference was reported above
    for (std::size_t r = 0; r < rounds; ++r) {
      std::string mine;  // from the group's first rank: "P" point, or "I"/"F" source \n error
      if (r < work[color].size()) {
        const int k = work[color][r];
        try {
          bar.update(static_cast<int>(done.size()), fmt::format("point {}/{}", k + 1, total));
          done[k] = relaxPoint(*groupCalcs, k, startOf(k), false, bar, total);
          if (group.isRoot()) mine = "P" + scanPointText(k, done.at(k));
        } catch (const InputError& e) {
          if (group.isRoot()) mine = "I" + e.source() + "\n" + e.what();
        } catch (const std::exception& e) {
          if (group.isRoot()) mine = std::string("F\n") + e.what();
        }
      }
      const std::vector<std::string> all = comm.allgatherText(mine);
      for (const std::string& t : all) {
        if (t.empty() || t[0] == 'P') continue;
        const std::size_t nl = t.find('\n');
        const std::string source = t.substr(1, nl - 1), what = t.substr(nl + 1);
        if (t[0] == 'F') throw NumericalError(what);
        const std::string prefix = source + ": ";
        throw InputError(source, what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
      }
      for (const std::string& t : all) {
        if (t.empty()) continue;
        auto [k, p] = scanPointFromText(t.substr(1), cell);
        if (!done.count(k)) done[k] = std::move(p);  // another group's point
        ++computed;
      }
      checkpoint.planSize = total;
      if (!s.checkpointPath.empty()) writeScanCheckpoint(s.checkpointPath, checkpoint, cell);
      bar.update(static_cast<int>(done.size()));
      for (; reported < total && done.count(reported); ++reported)
        if (s.pointDone) s.pointDone(done.at(reported), reported, total);
    }
  }
  bar.finish();

  out.computed = computed;
  out.complete = static_cast<int>(done.size()) == static_cast<int>(plan.size());
  if (done.count(0)) {
    const ObjectiveCell& ref = done.at(0).cell;
    out.translation0 = ref.symmetry.translation();
    out.twist0 = ref.symmetry.twist();
    out.cellsPerSlice = bendSource.sector ? 1 : ref.symmetry.rotationOrder();
    if (bendSource.sector) out.translation0 = bendSource.arc;
    if (s.dimensionsInterlayer > 0) {
      const CollapsedDimensions d = measureCollapsed(ref, s.dimensionsInterlayer);
      out.thickness = d.thickness;
      out.width = d.width;
    }
  }
  for (auto& [k, p] : done) out.points.push_back(p);
  std::sort(out.points.begin(), out.points.end(),
            [](const ScanPoint& a, const ScanPoint& b) { return a.deformation < b.deformation; });
  return out;
}

}  // namespace mesochain::objective
