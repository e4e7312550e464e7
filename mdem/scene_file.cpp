#include "mdem/scene_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/toml_file.hpp"
#include "mdem/checkpoint.hpp"
#include "mdem/compression.hpp"
#include "mdem/contacts/contact_file.hpp"
#include "mdem/effect_registry.hpp"
#include "mdem/tensile.hpp"
#include "common/toml_table.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

namespace {

// FNV-1a (64 bit) of a file's bytes, continuing from `seed` (0: the offset basis).
std::uint64_t hashFileText(const std::string& path, std::uint64_t seed) {
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return fnv1a(text.data(), text.size(), seed);
}

// Element index: 0-based, negative counts from the end (-1 = last).
int elementIndex(long i, int count, const TomlTable& t, const std::string& key) {
  const long j = i < 0 ? i + count : i;
  if (j < 0 || j >= count)
    t.fail(key, "element " + std::to_string(i),
           "an existing element: 0 .. " + std::to_string(count - 1) + " or -1 .. -" +
               std::to_string(count) + " (there are " + std::to_string(count) + ")");
  return static_cast<int>(j);
}

int oneElement(const TomlTable& t, int count) {
  return elementIndex(t.integer("element"), count, t, "element");
}

ElementType readElementType(const TomlTable& t) {
  t.allowOnly({"name", "shape", "thickness_nm", "width_nm", "radius_nm", "length_nm", "mass_ag",
               "density_kg_per_m3"});
  ElementType e;
  e.name = t.string("name");
  // The name is a column of the extended XYZ trajectory (type_name) and of VTK: one word.
  if (e.name.empty() || e.name.find_first_of(" \t\n\r\"'") != std::string::npos)
    t.fail("name", "\"" + e.name + "\"", "a name without spaces or quotes (e.g. collapsed_cnt)");
  const std::string shape = t.stringOr("shape", "brick");
  if (shape == "brick") {
    e.shape = Shape::Brick;
    e.thickness = t.positive("thickness_nm");
    e.width = t.positive("width_nm");
    if (t.has("radius_nm")) t.fail("radius_nm", "a radius for a brick", "thickness_nm and width_nm");
  } else if (shape == "cylinder") {
    e.shape = Shape::Cylinder;
    e.radius = t.positive("radius_nm");
    if (t.has("thickness_nm") || t.has("width_nm"))
      t.fail(t.has("width_nm") ? "width_nm" : "thickness_nm", "a brick dimension for a cylinder",
             "radius_nm only");
  } else {
    t.fail("shape", "\"" + shape + "\"", "\"brick\" or \"cylinder\"");
  }
  e.length = t.positive("length_nm");
  if (t.has("mass_ag") == t.has("density_kg_per_m3"))
    t.fail("mass_ag", t.has("mass_ag") ? "both mass_ag and density_kg_per_m3" : "neither",
           "exactly one of mass_ag, density_kg_per_m3");
  e.mass = t.has("mass_ag") ? t.positive("mass_ag")
                            : t.positive("density_kg_per_m3") * units::kKgPerM3 * e.volume();
  return e;
}

BondType readBondType(const TomlTable& t) {
  t.allowOnly({"name", "young_modulus_MPa", "shear_modulus_MPa", "normal_stiffness_MPa_per_nm",
               "shear_stiffness_MPa_per_nm"});
  BondType b;
  b.name = t.string("name");
  const bool moduli = t.has("young_modulus_MPa") || t.has("shear_modulus_MPa");
  const bool direct = t.has("normal_stiffness_MPa_per_nm") || t.has("shear_stiffness_MPa_per_nm");
  if (moduli == direct)
    t.fail("young_modulus_MPa", moduli ? "both moduli and stiffnesses" : "neither",
           "young_modulus_MPa + shear_modulus_MPa, or normal_stiffness_MPa_per_nm + "
           "shear_stiffness_MPa_per_nm");
  b.fromModuli = moduli;
  if (moduli) {
    b.youngModulus = t.positive("young_modulus_MPa");
    b.shearModulus = t.positive("shear_modulus_MPa");
  } else {
    b.stiffness.kn = t.positive("normal_stiffness_MPa_per_nm");
    b.stiffness.ks = t.positive("shear_stiffness_MPa_per_nm");
  }
  return b;
}

Quat readOrientation(const TomlTable& t) {
  if (!t.has("orientation")) return {};
  const std::vector<double> q = t.numbers("orientation");
  if (q.size() != 4) t.fail("orientation", std::to_string(q.size()) + " numbers", "[w, x, y, z]");
  const Quat r{q[0], q[1], q[2], q[3]};
  if (r.norm() < 1e-12) t.fail("orientation", "a zero quaternion", "a non-zero quaternion");
  return normalized(r);
}

void readElements(const TomlTable& root, Scene& s) {
  if (!root.has("elements")) return;
  for (const TomlTable& t : root.tables("elements")) {
    t.allowOnly({"type", "position_nm", "orientation", "velocity_nm_per_ns",
                 "angular_velocity_rad_per_ns"});
    const int type = findNamed(s.elementTypes, t, "type");
    s.bodies.add(type, s.elementTypes[type], t.vec3("position_nm"), readOrientation(t));
    const int i = s.bodies.size() - 1;
    s.bodies.velocity[i] = t.vec3Or("velocity_nm_per_ns", Vec3::Zero());
    s.bodies.setAngularVelocityWorld(i, t.vec3Or("angular_velocity_rad_per_ns", Vec3::Zero()));
  }
}

void readFilaments(const TomlTable& root, Scene& s) {
  if (!root.has("filaments")) return;
  for (const TomlTable& t : root.tables("filaments")) {
    t.allowOnly({"element_type", "bond_type", "count", "start_nm", "direction", "thickness_axis",
                 "spacing_nm"});
    FilamentSpec f;
    f.elementType = findNamed(s.elementTypes, t, "element_type");
    f.bondType = findNamed(s.bondTypes, t, "bond_type");
    const long n = t.integer("count");
    // Element indices are int; a scene holds at most 1e8 elements (about 30 GB of state).
    constexpr long kMaxElements = 100000000;
    if (n < 1 || n > kMaxElements - s.bodies.size())
      t.fail("count", std::to_string(n),
             fmt::format("1 to {} elements (at most {} in a scene)", kMaxElements - s.bodies.size(), kMaxElements));
    f.count = static_cast<int>(n);
    f.start = t.vec3Or("start_nm", Vec3::Zero());
    f.direction = t.vec3Or("direction", Vec3::UnitZ());
    if (f.direction.norm() < 1e-12) t.fail("direction", "a zero vector", "a direction");
    f.thicknessAxis = t.vec3Or("thickness_axis", Vec3::UnitX());
    if (t.has("spacing_nm")) f.spacing = t.positive("spacing_nm");
    addFilament(s, f);
  }
}

void readBonds(const TomlTable& root, Scene& s) {
  if (!root.has("bonds")) return;
  for (const TomlTable& t : root.tables("bonds")) {
    t.allowOnly({"elements", "type"});
    const std::vector<long> e = t.integers("elements");
    if (e.size() != 2) t.fail("elements", std::to_string(e.size()) + " indices", "[a, b]");
    const int a = elementIndex(e[0], s.bodies.size(), t, "elements");
    const int b = elementIndex(e[1], s.bodies.size(), t, "elements");
    if (a == b) t.fail("elements", "a bond of an element to itself", "two different elements");
    if ((s.bodies.position[a] - s.bodies.position[b]).norm() < 1e-9)
      t.fail("elements", "two elements at the same position", "distinct centres");
    addBond(s, a, b, findNamed(s.bondTypes, t, "type"));
  }
}

void readBoundary(const TomlTable& root, Scene& s) {
  const int n = s.bodies.size();
  if (root.has("fixed")) {
    for (const TomlTable& t : root.tables("fixed")) {
      t.allowOnly({"element", "dofs"});
      FixedDofs f;
      f.element = oneElement(t, n);
      const char* names[6] = {"x", "y", "z", "rx", "ry", "rz"};
      for (const std::string& d : t.has("dofs") ? t.strings("dofs") : std::vector<std::string>{"all"}) {
        bool ok = d == "all";
        if (ok) f.fixed.fill(true);
        for (int k = 0; k < 6; ++k)
          if (d == names[k]) f.fixed[k] = ok = true;
        if (!ok) t.fail("dofs", "\"" + d + "\"", "\"all\" or any of x, y, z, rx, ry, rz");
      }
      s.boundary.fixed.push_back(f);
    }
  }
  if (root.has("loads")) {
    for (const TomlTable& t : root.tables("loads")) {
      t.allowOnly({"element", "force_pN", "moment_pN_nm", "frame", "ramp_ns"});
      Load l;
      l.element = oneElement(t, n);
      l.force = t.vec3Or("force_pN", Vec3::Zero());
      l.moment = t.vec3Or("moment_pN_nm", Vec3::Zero());
      const std::string frame = t.stringOr("frame", "fixed");
      if (frame != "fixed" && frame != "following")
        t.fail("frame", "\"" + frame + "\"", "\"fixed\" or \"following\"");
      l.following = frame == "following";
      l.ramp = t.nonNegativeOr("ramp_ns", 0.0);
      s.boundary.loads.push_back(l);
    }
  }
  if (root.has("prescribed")) {
    for (const TomlTable& t : root.tables("prescribed")) {
      t.allowOnly({"element", "velocity_nm_per_ns", "angular_velocity_rad_per_ns", "ramp_ns",
                   "translate_by_nm", "rotate_by_rad", "duration_ns"});
      Prescribed p;
      p.element = oneElement(t, n);
      if (t.has("duration_ns")) {
        p.duration = t.positive("duration_ns");
        for (const char* k : {"velocity_nm_per_ns", "angular_velocity_rad_per_ns", "ramp_ns"})
          if (t.has(k)) t.fail(k, "a velocity-mode key with duration_ns", "translate_by_nm / rotate_by_rad");
        p.translateBy = t.vec3Or("translate_by_nm", Vec3::Zero());
        p.rotateBy = t.vec3Or("rotate_by_rad", Vec3::Zero());
      } else {
        for (const char* k : {"translate_by_nm", "rotate_by_rad"})
          if (t.has(k)) t.fail(k, "a displacement without duration_ns", "duration_ns as well");
        p.velocity = t.vec3Or("velocity_nm_per_ns", Vec3::Zero());
        p.angularVelocity = t.vec3Or("angular_velocity_rad_per_ns", Vec3::Zero());
        p.ramp = t.nonNegativeOr("ramp_ns", 0.0);
      }
      s.boundary.prescribed.push_back(p);
    }
  }
  // One kinematic rule per element.
  std::vector<int> seen(n, 0);
  for (const auto& f : s.boundary.fixed) ++seen[f.element];
  for (const auto& p : s.boundary.prescribed) ++seen[p.element];
  for (int i = 0; i < n; ++i)
    if (seen[i] > 1)
      throw InputError(s.source, "keys fixed / prescribed",
                       "element " + std::to_string(i) + " constrained more than once",
                       "at most one [[fixed]] or [[prescribed]] entry per element");
}

// rotational_inertia_scale, mass_scale: a factor in [1, 10000] (body.hpp, scaleInertia).
double inertiaFactor(const TomlTable& t, const std::string& key) {
  const double v = t.positive(key);
  if (v < 1.0 || v > 1e4) t.fail(key, std::to_string(v), "a factor in [1, 10000]");
  return v;
}

// [run] outer_step_ratio / outer_step_fraction / outer_effects (multiple time stepping).
void readOuterStep(const TomlTable& run, Scene& s) {
  if (run.isString("outer_step_ratio")) {
    const std::string v = run.string("outer_step_ratio");
    if (v != "auto") run.fail("outer_step_ratio", "\"" + v + "\"", "a whole number >= 1 or \"auto\"");
    s.run.outerStepRatio = 0;
  } else if (run.has("outer_step_ratio")) {
    const long r = run.integer("outer_step_ratio");
    if (r < 1 || r > 1000) run.fail("outer_step_ratio", std::to_string(r), "a whole number in [1, 1000] or \"auto\"");
    s.run.outerStepRatio = static_cast<int>(r);
  }
  if (run.has("outer_step_fraction")) {
    if (s.run.outerStepRatio != 0)
      run.fail("outer_step_fraction", "a fraction with a fixed outer_step_ratio",
               "outer_step_fraction only with outer_step_ratio = \"auto\"");
    s.run.outerStepFraction = run.positive("outer_step_fraction");
    if (s.run.outerStepFraction > 1.0)
      run.fail("outer_step_fraction", std::to_string(s.run.outerStepFraction), "a fraction in (0, 1]");
  }
  if (run.has("outer_effects")) {
    if (!run.has("outer_step_ratio"))
      run.fail("outer_effects", "outer effects without outer_step_ratio", "outer_step_ratio as well");
    s.run.outerEffects = run.strings("outer_effects");
    if (s.run.outerEffects.empty()) run.fail("outer_effects", "an empty list", "the effects of the outer step");
  }
}

void readRunAndOutput(const TomlTable& root, Scene& s) {
  const TomlTable run = root.requireTable("run");
  run.allowOnly({"time_step_ns", "time_step_fraction", "steps", "duration_ns", "stop_kinetic_energy_zJ",
                 "check_every", "minimum_steps", "outer_step_ratio", "outer_step_fraction", "outer_effects",
                 "rotational_inertia_scale", "mass_scale", "critical_step", "start_from"});
  if (run.has("time_step_ns") == run.has("time_step_fraction"))
    run.fail("time_step_ns", run.has("time_step_ns") ? "both time_step_ns and time_step_fraction" : "neither",
             "exactly one of time_step_ns, time_step_fraction");
  if (run.has("time_step_ns")) s.run.timeStep = run.positive("time_step_ns");
  if (run.has("time_step_fraction")) {
    s.run.timeStepFraction = run.positive("time_step_fraction");
    if (s.run.timeStepFraction > 1.0)
      run.fail("time_step_fraction", std::to_string(s.run.timeStepFraction), "a fraction in (0, 1]");
  }
  readOuterStep(run, s);
  if (run.has("critical_step")) {
    const std::string v = run.string("critical_step");
    if (v != "gershgorin" && v != "gershgorin_body")
      run.fail("critical_step", "\"" + v + "\"", "\"gershgorin\" (world axes) or \"gershgorin_body\" (body axes)");
    s.run.bodyFrameCriticalStep = v == "gershgorin_body";
  }
  if (run.has("rotational_inertia_scale")) s.run.rotationalInertiaScale = inertiaFactor(run, "rotational_inertia_scale");
  if (run.has("mass_scale")) s.run.massScale = inertiaFactor(run, "mass_scale");
  if (!root.has("stages")) {
    if (run.has("steps") && run.has("duration_ns"))
      run.fail("duration_ns", "both steps and duration_ns", "exactly one of steps, duration_ns (the run's length)");
    if (run.has("duration_ns")) {
      s.run.durationNs = run.positive("duration_ns");
    } else {
      s.run.steps = run.integer("steps");
      if (s.run.steps < 0) run.fail("steps", std::to_string(s.run.steps), "a number of steps >= 0");
    }
  }
  s.run.stopKineticEnergy = run.has("stop_kinetic_energy_zJ") ? run.positive("stop_kinetic_energy_zJ") : -1.0;
  s.run.checkEvery = run.integerOr("check_every", 100);
  if (s.run.checkEvery < 1) run.fail("check_every", std::to_string(s.run.checkEvery), "at least 1");
  s.run.minimumSteps = run.integerOr("minimum_steps", 0);
  if (run.has("start_from")) {
    std::filesystem::path from = run.string("start_from");
    if (from.is_relative()) from = std::filesystem::path(s.source).parent_path() / from;
    if (!std::filesystem::is_regular_file(from))
      run.fail("start_from", "\"" + from.string() + "\", which does not exist",
               "the final-state file of another run ([output] final_state)");
    s.run.startFrom = from.string();
  }
  if (!root.has("output")) return;
  const TomlTable out = root.requireTable("output");
  out.allowOnly({"directory", "energies_csv", "energies_every", "xyz", "vtk_prefix",
                 "frames_every", "probes", "plot_png", "checkpoint", "checkpoint_every", "checkpoint_minutes",
                 "final_state"});
  s.output.directory = out.stringOr("directory", ".");
  s.output.energiesCsv = out.stringOr("energies_csv", "");
  s.output.energiesEvery = out.integerOr("energies_every", 100);
  s.output.xyz = out.stringOr("xyz", "");
  s.output.vtkPrefix = out.stringOr("vtk_prefix", "");
  s.output.framesEvery = out.integerOr("frames_every", 1000);
  s.output.plotPng = out.stringOr("plot_png", "");
  for (const char* k : {"energies_every", "frames_every"})
    if (out.integerOr(k, 1) < 1) out.fail(k, std::to_string(out.integer(k)), "at least 1");
  s.output.checkpoint = out.stringOr("checkpoint", s.output.checkpoint);
  if (s.output.checkpoint.empty()) out.fail("checkpoint", "an empty name", "a file name for the checkpoints");
  s.output.checkpointEvery = out.integerOr("checkpoint_every", 0);
  if (s.output.checkpointEvery < 0) out.fail("checkpoint_every", std::to_string(s.output.checkpointEvery), "a number of steps >= 0 (0: not by steps)");
  s.output.checkpointMinutes = out.nonNegativeOr("checkpoint_minutes", s.output.checkpointMinutes);
  s.output.finalState = out.stringOr("final_state", "");
  if (out.has("final_state") && (s.output.finalState.empty() || s.output.finalState == s.output.checkpoint))
    out.fail("final_state", "\"" + s.output.finalState + "\"", "a file name other than the checkpoint's");
  if (out.has("probes"))
    for (long p : out.integers("probes"))
      s.output.probes.push_back(elementIndex(p, s.bodies.size(), out, "probes"));
}


void readTensileTable(const TomlTable& t, TensileSpec& ts) {
  t.allowOnly({"axis", "grip_width_nm", "strain_rate_per_ns", "ramp_ns", "cross_section_nm2", "contact_gap_nm",
               "aligned_angle_deg", "csv", "json", "plot_png", "final_strain"});
  ts.enabled = true;
  const std::string axis = t.stringOr("axis", "x");
  if (axis != "x" && axis != "y") t.fail("axis", "\"" + axis + "\"", "\"x\" or \"y\" (in the film plane)");
  ts.axis = axis == "x" ? 0 : 1;
  ts.gripWidth = t.positive("grip_width_nm");
  ts.strainRate = t.positive("strain_rate_per_ns");
  ts.ramp = t.nonNegativeOr("ramp_ns", 0.0);
  ts.crossSection = t.has("cross_section_nm2") ? t.positive("cross_section_nm2") : 0.0;
  ts.contactGap = t.nonNegativeOr("contact_gap_nm", 0.5);
  ts.alignedAngle = t.numberOr("aligned_angle_deg", 10.0) * units::kPi / 180.0;
  if (ts.alignedAngle < 0.0 || ts.alignedAngle > 0.5 * units::kPi)
    t.fail("aligned_angle_deg", fmt::format("{}", t.number("aligned_angle_deg")), "an angle in [0, 90] degrees");
  ts.csv = t.stringOr("csv", ts.csv);
  ts.json = t.stringOr("json", ts.json);
  ts.png = t.stringOr("plot_png", ts.png);
  ts.finalStrain = t.has("final_strain") ? t.positive("final_strain") : 0.0;
}

void readCompressionTable(const TomlTable& t, CompressionSpec& c) {
  t.allowOnly({"cycles", "max_strain", "strain_rate_per_ns", "plate_speed_nm_per_ns", "hold_ns", "wall_gap_nm",
               "wall_stiffness_pN_per_nm2", "quadrature_points", "area_nm2", "csv", "cycles_csv", "plot_png"});
  c.enabled = true;
  c.cycles = static_cast<int>(t.integerOr("cycles", 1));
  if (c.cycles < 1) t.fail("cycles", std::to_string(c.cycles), "at least 1 cycle");
  c.maxStrain = t.positive("max_strain");
  if (c.maxStrain >= 1.0) t.fail("max_strain", fmt::format("{}", c.maxStrain), "a compressive strain in (0, 1)");
  if (t.has("strain_rate_per_ns") == t.has("plate_speed_nm_per_ns"))
    t.fail("strain_rate_per_ns", t.has("strain_rate_per_ns") ? "both strain_rate_per_ns and plate_speed_nm_per_ns" : "neither",
           "exactly one of strain_rate_per_ns, plate_speed_nm_per_ns");
  if (t.has("strain_rate_per_ns")) c.strainRate = t.positive("strain_rate_per_ns");
  if (t.has("plate_speed_nm_per_ns")) c.plateSpeed = t.positive("plate_speed_nm_per_ns");
  c.holdTime = t.nonNegativeOr("hold_ns", 0.0);
  c.wallGap = t.has("wall_gap_nm") ? t.positive("wall_gap_nm") : c.wallGap;
  c.stiffness = t.has("wall_stiffness_pN_per_nm2") ? t.positive("wall_stiffness_pN_per_nm2") : 0.0;
  c.quadraturePoints = static_cast<int>(t.integerOr("quadrature_points", c.quadraturePoints));
  if (c.quadraturePoints < 1 || c.quadraturePoints > 32)
    t.fail("quadrature_points", std::to_string(c.quadraturePoints), "1 to 32 Gauss points along an element");
  c.area = t.has("area_nm2") ? t.positive("area_nm2") : 0.0;
  c.csv = t.stringOr("csv", c.csv);
  c.cyclesCsv = t.stringOr("cycles_csv", c.cyclesCsv);
  c.png = t.stringOr("plot_png", c.png);
}

// [[stages]] (docs/scene-file.md): [run] keeps the time step; its steps and stop keys move to
// the stages.
void readStages(const TomlTable& root, Scene& s) {
  const TomlTable run = root.requireTable("run");
  for (const char* k : {"steps", "duration_ns", "stop_kinetic_energy_zJ", "check_every", "minimum_steps"})
    if (run.has(k)) run.fail(k, "a [run] stop key beside [[stages]]", "the key in each stage (the time step stays in [run])");
  if (!s.output.energiesCsv.empty() || !s.output.plotPng.empty())
    root.fail("output", "energies_csv / plot_png in [output] beside [[stages]]", "each stage's own energies_csv / plot_png");
  for (const TomlTable& t : root.tables("stages")) {
    t.allowOnly({"name", "kind", "steps", "duration_ns", "stop_kinetic_energy_zJ", "check_every", "minimum_steps", "add_effects",
                 "mass_scale", "energies_csv", "energies_every", "plot_png", "tensile", "compression"});
    StageSpec st;
    st.name = t.string("name");
    if (st.name.empty()) t.fail("name", "an empty name", "a stage name (used in file names and messages)");
    for (const StageSpec& o : s.stages)
      if (o.name == st.name) t.fail("name", "\"" + st.name + "\" given twice", "a name of its own for each stage");
    const std::string kind = t.stringOr("kind", "relax");
    if (kind != "relax" && kind != "tensile" && kind != "compression")
      t.fail("kind", "\"" + kind + "\"", "\"relax\", \"tensile\" or \"compression\"");
    st.tensileStage = kind == "tensile";
    st.compressionStage = kind == "compression";
    if (t.has("steps") == t.has("duration_ns"))
      t.fail(t.has("steps") ? "duration_ns" : "steps", t.has("steps") ? "both steps and duration_ns" : "neither steps nor duration_ns",
             "exactly one of steps, duration_ns (the stage's length)");
    if (t.has("duration_ns")) {
      st.durationNs = t.positive("duration_ns");
    } else {
      st.steps = t.integer("steps");
      if (st.steps < 1) t.fail("steps", std::to_string(st.steps), "at least 1 step");
    }
    st.stopKineticEnergy = t.has("stop_kinetic_energy_zJ") ? t.positive("stop_kinetic_energy_zJ") : -1.0;
    st.checkEvery = t.integerOr("check_every", 100);
    if (st.checkEvery < 1) t.fail("check_every", std::to_string(st.checkEvery), "at least 1");
    st.minimumSteps = t.integerOr("minimum_steps", 0);
    if (t.has("add_effects")) st.addEffects = t.strings("add_effects");
    if (t.has("mass_scale")) st.massScale = inertiaFactor(t, "mass_scale");
    for (const std::string& e : st.addEffects) {
      if (std::find(s.effects.begin(), s.effects.end(), e) != s.effects.end())
        t.fail("add_effects", "\"" + e + "\", already in effects", "effects named for this stage only");
      // Effects with evolving state (bonds, contacts: neighbour lists, dissipated work) are
      // named for the whole run; a stage adds numerical damping (EffectRegistration::stageable).
      const EffectRegistration* r = findEffect(e);
      if (!r || !r->stageable)
        t.fail("add_effects", "\"" + e + "\"", stageableEffectNames() + " (other effects are named in effects, for every stage)");
    }
    st.energiesCsv = t.stringOr("energies_csv", st.name + "-energies.csv");
    st.energiesEvery = t.integerOr("energies_every", 100);
    if (st.energiesEvery < 1) t.fail("energies_every", std::to_string(st.energiesEvery), "at least 1");
    st.plotPng = t.stringOr("plot_png", st.name + "-energies.png");  // "" for none
    if (st.tensileStage != t.has("tensile"))
      t.fail("tensile", st.tensileStage ? "a tensile stage without its [stages.tensile] table" : "a [stages.tensile] table in a " + kind + " stage",
             "kind = \"tensile\" with its table, or neither");
    if (st.tensileStage) {
      st.tensile.csv = st.name + "-tensile.csv";
      st.tensile.json = st.name + "-tensile.json";
      st.tensile.png = st.name + "-tensile.png";
      readTensileTable(t.requireTable("tensile"), st.tensile);
    }
    if (st.compressionStage != t.has("compression"))
      t.fail("compression",
             st.compressionStage ? "a compression stage without its [stages.compression] table" : "a [stages.compression] table in a " + kind + " stage",
             "kind = \"compression\" with its table, or neither");
    if (st.compressionStage) {
      st.compression.csv = st.name + "-compression.csv";
      st.compression.cyclesCsv = st.name + "-cycles.csv";
      st.compression.png = st.name + "-compression.png";
      readCompressionTable(t.requireTable("compression"), st.compression);
    }
    s.stages.push_back(std::move(st));
  }
  if (s.stages.empty()) root.fail("stages", "an empty list", "at least one [[stages]] table");
}
}  // namespace

void readModelTables(const TomlTable& root, Scene& s) {
  if (root.has("element_types"))
    for (const TomlTable& t : root.tables("element_types")) s.elementTypes.push_back(readElementType(t));
  if (root.has("bond_types"))
    for (const TomlTable& t : root.tables("bond_types")) s.bondTypes.push_back(readBondType(t));
}

Scene loadScene(const std::string& path) {
  const toml::value data = parseTomlFile(path, "scene file");
  const TomlTable root(path, data, "");
  std::vector<std::string> tables{"format", "model", "effects", "element_types", "bond_types", "elements",
                                  "filaments", "bonds", "fixed", "loads", "prescribed", "run", "output",
                                  "contacts", "periodic", "network", "tensile", "stages"};
  for (const EffectRegistration* r : registeredEffects())  // each effect's own table
    if (!r->table.name.empty()) tables.push_back(r->table.name);
  root.allowOnly(tables);
  if (root.integer("format") != 1)
    root.fail("format", std::to_string(root.integer("format")), "1");
  Scene s;
  s.source = path;
  s.inputHash = hashFileText(path, 0);
  if (root.has("model")) {
    std::filesystem::path model = root.string("model");
    if (model.is_relative()) model = std::filesystem::path(path).parent_path() / model;
    if (!std::filesystem::is_regular_file(model))
      root.fail("model", "\"" + model.string() + "\", which does not exist", "an existing model file");
    const toml::value m = parseTomlFile(model.string(), "model file");
    s.inputHash = hashFileText(model.string(), s.inputHash);
    const TomlTable mroot(model.string(), m, "");
    mroot.allowOnly({"format", "element_types", "bond_types"});
    if (mroot.integerOr("format", 1) != 1) mroot.fail("format", std::to_string(mroot.integer("format")), "1");
    readModelTables(mroot, s);
  }
  readModelTables(root, s);
  s.effects = root.strings("effects");
  readElements(root, s);
  readFilaments(root, s);
  readBonds(root, s);
  readNetworkTable(root, s);
  readBoundary(root, s);
  std::vector<std::string> stageEffects;  // named by a stage only
  if (root.has("stages"))
    for (const TomlTable& t : root.tables("stages"))
      if (t.has("add_effects"))
        for (const std::string& e : t.strings("add_effects")) stageEffects.push_back(e);
  readEffectTables(root, s, stageEffects);  // each effect reads its own table (mdem/effect_registry.hpp)
  readContactTables(root, s);
  readRunAndOutput(root, s);
  if (s.bodies.size() == 0)
    throw InputError(path, "keys elements / filaments", "no elements", "at least one element");
  if (root.has("tensile")) {
    if (root.has("stages"))
      root.fail("tensile", "a [tensile] table beside [[stages]]", "the test as a stage with kind = \"tensile\"");
    readTensileTable(root.requireTable("tensile"), s.tensile);
    setUpTensile(s);
  }
  if (root.has("stages")) readStages(root, s);
  // A compression stage's plates on the initial state: errors (no plate area, no stiffness) now,
  // not when the stage starts hours into the run.
  for (std::size_t k = 0; k < s.stages.size(); ++k)
    if (s.stages[k].compressionStage) {
      Scene probe;
      probe.source = s.source, probe.elementTypes = s.elementTypes, probe.bodies = s.bodies;
      probe.periodic = s.periodic, probe.contacts = s.contacts, probe.filmSize = s.filmSize;
      probe.compression = s.stages[k].compression;
      setUpCompression(probe, 0.0, fmt::format("key stages[{}].compression", k));
    }
  return s;
}

}  // namespace mesochain::mdem
