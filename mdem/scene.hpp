#pragma once
// A scene: element and bond types, elements, bonds, boundary conditions, the effects to
// simulate, run control and outputs. Built by scene_file.cpp from a TOML file, or directly in
// C++ (tests, benchmarks) with the helpers below. Units: mdem/units.hpp.
#include <cstdint>
#include <string>
#include <vector>

#include "mdem/boundary.hpp"
#include "mdem/contacts/contact_spec.hpp"
#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

// Bond parameters. Either stiffness per unit area directly (k_n, k_s in MPa/nm), or moduli
// (MPa) from which k_n = Y / l, k_s = G / l with l the bond's rest length (centre distance).
// The cross-section is that of element a: brick h x w (h along the bond x axis), cylinder disc.
struct BondType {
  std::string name;
  bool fromModuli = false;
  double youngModulus = 0.0;  // MPa
  double shearModulus = 0.0;  // MPa
  BondStiffness stiffness;    // MPa/nm (when !fromModuli)

  BondStiffness stiffnessFor(double restLength) const;
};

// Largest outer_step_ratio that "auto" chooses (docs/benchmarks.md, multiple time stepping).
inline constexpr int kMaxAutoOuterRatio = 8;

struct RunControl {
  double timeStep = 0.0;              // ns
  double timeStepFraction = 0.0;      // > 0: time step = this fraction of the critical one
  // Moments of inertia of every element times this (mass unchanged; body.hpp,
  // scaleInertia): slows the rotational vibrations, lengthens their critical step.
  double rotationalInertiaScale = 1.0;
  // Mass and moments of inertia of every element times this (density scaling; body.hpp,
  // scaleInertia): slows every vibration by sqrt(massScale), lengthens the critical step as much.
  // A stage may set its own (StageSpec::massScale).
  double massScale = 1.0;
  // Frame of the translations in the critical step's Gershgorin bound (stability.hpp): false
  // world axes ("gershgorin", the default), true each element's body axes ("gershgorin_body").
  bool bodyFrameCriticalStep = false;
  // Multiple time stepping (stepper.hpp): the outer group is evaluated every outerStepRatio
  // steps (1: every step; 0: "auto", the largest ratio with ratio h <= outerStepFraction times
  // the outer group's own critical step, at most kMaxAutoOuterRatio).
  int outerStepRatio = 1;
  double outerStepFraction = 1.0;
  std::vector<std::string> outerEffects;  // empty: every conservative effect that couples filaments
  long steps = 0;                     // maximum number of steps
  // > 0 instead of steps: the run's length in ns, steps = ceil(duration / time step) once the
  // step is known (stepsForDuration).
  double durationNs = 0.0;
  double stopKineticEnergy = -1.0;    // zJ; stop when the total kinetic energy falls below (< 0: off)
  long checkEvery = 100;              // steps between stop checks
  long minimumSteps = 0;              // no stop before this step
  // A final-state file of another run ([output] final_state, absolute or relative to the scene
  // file when read): the run starts from its elements, time, step and effect states instead of
  // the scene's own state, as the next stage of that run would ("" = the scene's state).
  std::string startFrom;
};

// The steps of a run or stage of `durationNs` at time step h: the fewest steps whose time reaches
// the duration (a duration within 1e-9 of a whole number of steps is that number).
long stepsForDuration(double durationNs, double h);

struct OutputSpec {
  std::string directory = ".";        // relative to the working directory
  std::string energiesCsv;            // "" = none
  long energiesEvery = 100;
  std::string xyz;                    // extended XYZ trajectory, "" = none
  std::string vtkPrefix;              // legacy VTK frames PREFIX_000000.vtk, "" = none
  long framesEvery = 1000;
  std::vector<int> probes;            // elements whose displacement and rotation go to the CSV
  std::string plotPng;                // PNG of the energies and probes against time, "" = none
  // Checkpoints for --resume (checkpoint.hpp): every this many steps (0 = not by steps) and/or
  // this many minutes of wall time (0 = not by time); file name in the output folder.
  long checkpointEvery = 0;
  double checkpointMinutes = 30.0;
  std::string checkpoint = "checkpoint.mdem";
  // The state the run ends in, for another scene's [run] start_from (file name in the output
  // folder; "" = none): written atomically once the last stage is done.
  std::string finalState;
};

// [tensile]: uniaxial tensile test with grips (mdem/tensile.hpp, docs/scene-file.md).
struct TensileSpec {
  bool enabled = false;
  int axis = 0;                 // 0 = x, 1 = y
  double gripWidth = 0.0;       // nm: elements whose centre lies within this of either edge
  double strainRate = 0.0;      // 1/ns, engineering, of the gauge length
  double ramp = 0.0;            // ns, grip velocity ramp
  double crossSection = 0.0;    // nm^2 (0: from the [network] film)
  double contactGap = 0.5;      // nm, wall gap below which a pair counts as in contact
  double alignedAngle = 0.0;    // rad, aligned pairs cross below this angle
  std::string csv = "tensile.csv";
  std::string json = "tensile.json";  // the properties (mdem/tensile_properties.hpp), at the end
  std::string png;              // "" = none
  double finalStrain = 0.0;      // > 0: the test (stage) ends when the strain reaches this
  // Filled by setUpTensile from the positions at the start of the test: the grips, the gauge
  // length, the grips' mean axial positions then, and the time the test starts.
  std::vector<int> leftGrip, rightGrip;
  double gaugeLength = 0.0;     // nm
  double gripSpeed = 0.0;       // nm/ns, each grip (the two move apart at 2 x this)
  double leftReference = 0.0, rightReference = 0.0;  // nm
  double startTime = 0.0;       // ns
};

// [stages.compression]: compress-recover cycles between two rigid plates normal to z
// (mdem/compression.hpp, "walls" effect mdem/wall_effect.hpp, docs/scene-file.md).
struct CompressionSpec {
  bool enabled = false;
  int cycles = 1;
  double maxStrain = 0.0;       // compressive engineering strain of the plate gap, (H0 - H) / H0, in (0, 1)
  double strainRate = 0.0;      // 1/ns, of H0 (the plates close at strainRate * H0 together)
  double plateSpeed = 0.0;      // nm/ns, each plate (given instead of strainRate: rate = 2 v / H0)
  double holdTime = 0.0;        // ns, the plates rest at H0 after each recovery
  double wallGap = 0.34;        // nm, rest gap between a tube wall and a plate (no force beyond)
  double stiffness = 0.0;       // pN/nm^2 per unit tube length (0: the tube-tube contact's Phi'' at its minimum)
  int quadraturePoints = 8;     // Gauss points along an element
  double area = 0.0;            // nm^2, plate area for the pressure (0: the [network] film's x * y)
  std::string csv = "compression.csv", cyclesCsv = "compression-cycles.csv", png;
  // Filled by setUpCompression from the positions at the stage's start.
  double startTime = 0.0;       // ns
  double bottom0 = 0.0, top0 = 0.0;  // nm, plate planes at zero strain
};

// [[stages]]: one step of a protocol (relax, then pull); the state flows from stage to stage
// (docs/scene-file.md, stages). Without stages a scene is one stage made of [run], [output]'s
// time series and [tensile].
struct StageSpec {
  std::string name;
  bool tensileStage = false;            // kind = "tensile" (grips chosen at the stage's start)
  bool compressionStage = false;        // kind = "compression" (plates placed at the stage's start)
  long steps = 0;                       // maximum steps of the stage
  double durationNs = 0.0;              // > 0 instead of steps: the stage's length in ns (stepsForDuration)
  double stopKineticEnergy = -1.0;      // zJ (< 0: off)
  long checkEvery = 100;
  long minimumSteps = 0;
  std::vector<std::string> addEffects;  // named for this stage only, on top of `effects`
  double massScale = 0.0;               // > 0: the stage's mass_scale in place of [run]'s
  std::string energiesCsv;              // the stage's own time series ("" = none)
  long energiesEvery = 100;
  std::string plotPng;
  TensileSpec tensile;                  // tensile stages
  CompressionSpec compression;          // compression stages
};

struct Scene {
  std::string source = "<scene>";     // file name, for messages
  std::uint64_t inputHash = 0;        // of the scene (and model) file text; checkpoints check it
  std::vector<ElementType> elementTypes;
  std::vector<BondType> bondTypes;
  Bodies bodies;
  std::vector<Bond> bonds;
  std::vector<std::string> effects;   // "bonds", "vdw_contact", "contact_damping", "local_damping", "viscous_damping"
  double localDampingAlpha = 0.7;
  bool localDampingTracksWork = false;  // [local_damping] track_work
  double viscousRate = 0.0;           // 1/ns
  bool viscousDampingTracksWork = false;  // [viscous_damping] track_work
  Boundary boundary;
  Periodicity periodic;               // used by contacts (positions are never wrapped)
  ContactSpec contacts;               // parameters of vdw_contact / contact_damping
  Vec3 filmSize = Vec3::Zero();       // nm, the [network] film (zero without a network)
  RunControl run;
  OutputSpec output;
  TensileSpec tensile;
  CompressionSpec compression;        // set for a compression stage only (run.cpp)
  std::vector<StageSpec> stages;      // empty: one stage from [run], [output] and [tensile]
};

// Cross-section of a bond whose first element has type t.
BondSection sectionOf(const ElementType& t);

// Adds a bond of type bondType between existing elements a and b (rest state = current).
void addBond(Scene& scene, int a, int b, int bondType);

// Filament generator: `count` elements of one type, centres at start + k * spacing * direction,
// body z along direction, body x (thickness) along thicknessAxis projected normal to direction;
// consecutive elements bonded. Returns the index of the first element.
struct FilamentSpec {
  int elementType = 0;
  int bondType = 0;
  int count = 0;
  Vec3 start = Vec3::Zero();
  Vec3 direction = Vec3::UnitZ();
  Vec3 thicknessAxis = Vec3::UnitX();
  double spacing = 0.0;  // nm; 0 = the element length
};
int addFilament(Scene& scene, const FilamentSpec& spec);

}  // namespace mesochain::mdem
