#pragma once
// Every data member of the driver settings a scan point is computed from (relaxation and scan),
// named and visited in one place: forEachField(settings, f) calls f(name, member, role) for each
// member, nested settings as their own members. The calculator settings are not listed here:
// the scan identity takes them as the cell file's tables (dftb/settings_tables.hpp). Each
// visitor takes the members by a structured binding, which names every non-static member of
// the struct or does not compile: a member added to one of these
// structs stops the build here until it is given a name and a role (so it cannot be left out
// of the scan identity silently). tests/drivers/test_settings_fields.cpp checks that each
// visitor reaches every member (aggregate member count) and that changing any Role::Result
// member changes the scan identity.
#include <string>
#include <type_traits>
#include <vector>

#include "objective/drivers/scan.hpp"

namespace mesochain::objective {

// Result: changes what a scan point computes (part of the scan identity). Run: how or where the
// run proceeds (progress output, checkpoint path, stopping early, the deformation list, which a
// resumed scan may change), not part of the identity.
enum class FieldRole { Result, Run };

template <class S, class F>
  requires std::is_same_v<std::remove_const_t<S>, AngularSampling>
void forEachField(S& s, F&& f) {
  auto& [samples] = s;
  f("samples", samples, FieldRole::Result);
}

template <class S, class F>
  requires std::is_same_v<std::remove_const_t<S>, RelaxSettings>
void forEachField(S& s, F&& f) {
  auto& [algorithm, forceTolerance, maxSteps, relaxTranslation, axialTolerance,
         maxTranslationSteps, maxDisplacement, progress, snapshot, snapshotSeconds, resumeFrom] = s;
  f("algorithm", algorithm, FieldRole::Result);
  f("force_tolerance", forceTolerance, FieldRole::Result);
  f("max_steps", maxSteps, FieldRole::Result);
  f("relax_translation", relaxTranslation, FieldRole::Result);
  f("axial_tolerance", axialTolerance, FieldRole::Result);
  f("max_translation_steps", maxTranslationSteps, FieldRole::Result);
  f("max_displacement", maxDisplacement, FieldRole::Result);
  f("progress", progress, FieldRole::Run);
  f("snapshot", snapshot, FieldRole::Run);
  f("snapshot_seconds", snapshotSeconds, FieldRole::Run);
  // A snapshot of the same relaxation: where it continues, not what it computes.
  f("resume_from", resumeFrom, FieldRole::Run);
}

template <class S, class F>
  requires std::is_same_v<std::remove_const_t<S>, ScanSettings>
void forEachField(S& s, F&& f) {
  auto& [kind, direction, values, rotationOrders, relax, ringAngular, dimensionsInterlayer,
         identity, checkpointPath, snapshotSeconds, resume, stopAfter, progressBar, pointDone,
         reference] = s;
  f("kind", kind, FieldRole::Result);
  f("direction", direction, FieldRole::Result);
  // The list may change between runs: points are matched by their deformation (reuseCheckpoint).
  f("values", values, FieldRole::Run);
  f("rotation_orders", rotationOrders, FieldRole::Run);
  f("relax", relax, FieldRole::Result);
  f("ring_angular", ringAngular, FieldRole::Result);
  f("dimensions_interlayer_bohr", dimensionsInterlayer, FieldRole::Result);
  f("identity", identity, FieldRole::Result);
  f("checkpoint_path", checkpointPath, FieldRole::Run);
  f("snapshot_seconds", snapshotSeconds, FieldRole::Run);
  f("resume", resume, FieldRole::Run);
  f("stop_after", stopAfter, FieldRole::Run);
  f("progress_bar", progressBar, FieldRole::Run);
  f("point_done", pointDone, FieldRole::Run);
  // Checked against the scan's referenceIdentity before use: the same point as a relaxed one.
  f("reference", reference, FieldRole::Run);
}

// True for the settings types above (visited member by member).
template <class T>
concept VisitedSettings = requires(const T& t) {
  forEachField(t, [](const char*, const auto&, FieldRole) {});
};

}  // namespace mesochain::objective
