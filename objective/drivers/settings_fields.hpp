#pragma once
// Every data member of the settings a scan point is computed from, named and visited in one
// place: forEachField(settings, f) calls f(name, member, role) for each member, nested settings
// as their own members. Each visitor takes the members by a structured binding, which names
// every non-static member of the struct or does not compile: a member added to one of these
// structs stops the build here until it is given a name and a role (so it cannot be left out
// of the scan identity silently). tests/drivers/test_settings_fields.cpp checks that each
// visitor reaches every member (aggregate member count) and that changing any Role::Result
// member changes the scan identity.
#include <string>
#include <type_traits>
#include <vector>

#include "dftb/calculator.hpp"
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
  requires std::is_same_v<std::remove_const_t<S>, dftb::BandSettings>
void forEachField(S& s, F&& f) {
  auto& [helicalKPoints, angular, electronicTemperature, eigenvectors] = s;
  f("helical_kpoints", helicalKPoints, FieldRole::Result);
  f("angular", angular, FieldRole::Result);
  f("electronic_temperature_hartree", electronicTemperature, FieldRole::Result);
  // The eigenvector path gives the same results to rounding (tests/dftb/test_eigenvector_paths.cpp).
  f("eigenvectors", eigenvectors, FieldRole::Run);
}

template <class S, class F>
  requires std::is_same_v<std::remove_const_t<S>, dftb::DispersionSettings>
void forEachField(S& s, F&& f) {
  auto& [enabled, epsilon, r0, cutoff, ewald, ewaldTolerance, elements, elementEpsilon, elementR0] = s;
  f("enabled", enabled, FieldRole::Result);
  f("epsilon_hartree", epsilon, FieldRole::Result);
  f("r0_bohr", r0, FieldRole::Result);
  f("cutoff_bohr", cutoff, FieldRole::Result);
  f("ewald", ewald, FieldRole::Result);
  f("ewald_tolerance", ewaldTolerance, FieldRole::Result);
  f("elements", elements, FieldRole::Result);
  f("element_epsilon_hartree", elementEpsilon, FieldRole::Result);
  f("element_r0_bohr", elementR0, FieldRole::Result);
}

template <class S, class F>
  requires std::is_same_v<std::remove_const_t<S>, dftb::KolmogorovCrespiSettings>
void forEachField(S& s, F&& f) {
  auto& [enabled, parameters, cutoff, taperStart, bondCutoff] = s;
  f("enabled", enabled, FieldRole::Result);
  f("parameters", parameters, FieldRole::Result);
  f("cutoff_bohr", cutoff, FieldRole::Result);
  f("taper_start_bohr", taperStart, FieldRole::Result);
  f("bond_cutoff_bohr", bondCutoff, FieldRole::Result);
}

template <class S, class F>
  requires std::is_same_v<std::remove_const_t<S>, dftb::SccSettings>
void forEachField(S& s, F&& f) {
  auto& [enabled, chargeTolerance, energyTolerance, maxIterations, mixer, mixing, ewaldTolerance,
         stopIfUnconverged, warmStart] = s;
  f("enabled", enabled, FieldRole::Result);
  f("charge_tolerance", chargeTolerance, FieldRole::Result);
  f("energy_tolerance", energyTolerance, FieldRole::Result);
  f("max_iterations", maxIterations, FieldRole::Result);
  f("mixer", mixer, FieldRole::Result);
  f("mixing", mixing, FieldRole::Result);
  f("ewald_tolerance", ewaldTolerance, FieldRole::Result);
  f("stop_if_unconverged", stopIfUnconverged, FieldRole::Result);
  // The warm start changes the converged charges within the tolerances.
  f("warm_start", warmStart, FieldRole::Result);
}

template <class S, class F>
  requires std::is_same_v<std::remove_const_t<S>, dftb::CalculatorSettings>
void forEachField(S& s, F&& f) {
  auto& [band, dispersion, kc, scc] = s;
  f("band", band, FieldRole::Result);
  f("dispersion", dispersion, FieldRole::Result);
  f("kc", kc, FieldRole::Result);
  f("scc", scc, FieldRole::Result);
}

template <class S, class F>
  requires std::is_same_v<std::remove_const_t<S>, RelaxSettings>
void forEachField(S& s, F&& f) {
  auto& [algorithm, forceTolerance, maxSteps, relaxTranslation, axialTolerance,
         maxTranslationSteps, maxDisplacement, progress] = s;
  f("algorithm", algorithm, FieldRole::Result);
  f("force_tolerance", forceTolerance, FieldRole::Result);
  f("max_steps", maxSteps, FieldRole::Result);
  f("relax_translation", relaxTranslation, FieldRole::Result);
  f("axial_tolerance", axialTolerance, FieldRole::Result);
  f("max_translation_steps", maxTranslationSteps, FieldRole::Result);
  f("max_displacement", maxDisplacement, FieldRole::Result);
  f("progress", progress, FieldRole::Run);
}

template <class S, class F>
  requires std::is_same_v<std::remove_const_t<S>, ScanSettings>
void forEachField(S& s, F&& f) {
  auto& [kind, direction, values, rotationOrders, relax, ringAngular, dimensionsInterlayer,
         identity, checkpointPath, resume, stopAfter, progressBar, pointDone, reference] = s;
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
