#include "mdem/checkpoint.hpp"

#include <cstring>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/build_info.hpp"
#include "common/errors.hpp"

namespace mesochain::mdem {

namespace {
constexpr char kMagic[8] = {'M', 'D', 'E', 'M', 'C', 'K', 'P', 'T'};
// 2: multiple time stepping (held outer forces, cycle start); 3: the writing build's commit.
constexpr std::uint32_t kVersion = 3;
constexpr std::uint32_t kOldestReadable = 2;  // format 2 is read as written by an unknown build
constexpr std::uint32_t kByteOrder = 0x01020304;

template <class T>
void hashValue(std::uint64_t& h, const T& v) {
  h = fnv1a(&v, sizeof(T), h);
}

}  // namespace

void writeBodiesTo(BinaryWriter& out, const Bodies& b) {
  out.writeVector(b.position);
  out.writeVector(b.orientation);
  out.writeVector(b.velocity);
  out.writeVector(b.angularMomentumBody);
  out.writeVector(b.force);
  out.writeVector(b.torque);
  out.writeVector(b.initialPosition);
  out.writeVector(b.accumulatedRotation);
}

namespace {
template <class T>
void readInto(BinaryReader& in, std::vector<T>& into, const char* what) {
  std::vector<T> v = in.readVector<T>(what);
  if (v.size() != into.size())
    in.fail(fmt::format("{} of {} elements for a scene of {}", what, v.size(), into.size()));
  into = std::move(v);
}

}  // namespace

void readBodiesFrom(BinaryReader& in, Bodies& b) {
  readInto(in, b.position, "positions");
  readInto(in, b.orientation, "orientations");
  readInto(in, b.velocity, "velocities");
  readInto(in, b.angularMomentumBody, "angular momenta");
  readInto(in, b.force, "forces");
  readInto(in, b.torque, "torques");
  readInto(in, b.initialPosition, "initial positions");
  readInto(in, b.accumulatedRotation, "accumulated rotations");
}

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t seed) {
  std::uint64_t h = seed == 0 ? 14695981039346656037ull : seed;
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t k = 0; k < size; ++k) h = (h ^ p[k]) * 1099511628211ull;
  return h;
}

std::uint64_t sceneFingerprint(const Scene& s) {
  std::uint64_t h = fnv1a(&s.inputHash, sizeof(s.inputHash));
  hashValue(h, s.run.timeStep), hashValue(h, s.run.timeStepFraction);
  hashValue(h, s.run.outerStepRatio), hashValue(h, s.run.outerStepFraction);
  for (const std::string& e : s.run.outerEffects) h = fnv1a(e.data(), e.size(), h);
  // Only when set, so that the checkpoints of unscaled runs keep their fingerprint.
  if (s.run.rotationalInertiaScale != 1.0) hashValue(h, s.run.rotationalInertiaScale);
  if (s.run.bodyFrameCriticalStep) hashValue(h, s.run.bodyFrameCriticalStep);
  if (s.run.massScale != 1.0) hashValue(h, s.run.massScale);
  for (const StageSpec& st : s.stages)
    if (st.massScale > 0.0) hashValue(h, st.massScale);
  for (const ElementType& t : s.elementTypes)
    for (double v : {t.thickness, t.width, t.radius, t.length, t.mass}) hashValue(h, v);
  const Bodies& b = s.bodies;
  for (int i = 0; i < b.size(); ++i) {
    hashValue(h, b.type[i]);
    for (int k = 0; k < 3; ++k) hashValue(h, b.position[i][k]);
    for (double v : {b.orientation[i].w, b.orientation[i].x, b.orientation[i].y, b.orientation[i].z}) hashValue(h, v);
  }
  for (const Bond& bd : s.bonds) hashValue(h, bd.a), hashValue(h, bd.b), hashValue(h, bd.k.kn), hashValue(h, bd.k.ks);
  for (const std::string& e : s.effects) h = fnv1a(e.data(), e.size(), h);
  hashValue(h, s.stages.size());
  return h;
}

void writeCheckpoint(const std::string& path, const Scene& scene, const Simulation& sim,
                     const std::function<void(BinaryWriter&)>& prelude,
                     const std::function<void(BinaryWriter&)>& tail) {
  BinaryWriter out;
  for (char c : kMagic) out.write(c);
  out.write(kVersion);
  out.write(kByteOrder);
  out.write(sceneFingerprint(scene));
  out.write(std::string(buildCommit()));
  BinaryWriter first;
  if (prelude) prelude(first);
  out.writeVector(first.bytes());
  BinaryWriter state;
  state.write<std::int64_t>(sim.stepCount());
  state.write(sim.time());
  state.write(sim.timeStep());
  writeBodiesTo(state, sim.bodies());
  state.write<std::int64_t>(sim.cycleStart());
  state.writeVector(sim.state().heldForce);
  state.writeVector(sim.state().heldTorque);
  state.write<std::uint64_t>(sim.effects().size());
  for (const EffectPtr& e : sim.effects()) {
    state.write(e->name());
    BinaryWriter block;
    e->saveState(block);
    state.writeVector(block.bytes());
  }
  out.writeVector(state.bytes());
  BinaryWriter last;
  if (tail) tail(last);
  out.writeVector(last.bytes());
  const std::uint64_t sum = fnv1a(out.bytes().data(), out.bytes().size());
  out.write(sum);
  AtomicOutputFile file(path);
  file.stream().write(reinterpret_cast<const char*>(out.bytes().data()), static_cast<std::streamsize>(out.bytes().size()));
  file.commit();
}

CheckpointFile::CheckpointFile(const std::string& path, const Scene& scene, bool sameScene) : path_(path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path, "", "no checkpoint file", "the checkpoint of the interrupted run (resume)");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (bytes.size() < sizeof(kMagic) + 8 || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    throw InputError(path, "checkpoint", "a file that is not an mDEM checkpoint", "a checkpoint written by mesochain dem");
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
  if (fnv1a(bytes.data(), bytes.size() - 8) != stored)
    throw InputError(path, "checkpoint", "a checksum that does not match (the file is corrupt or truncated)",
                     "an intact checkpoint");
  BinaryReader in(bytes.data() + sizeof(kMagic), bytes.size() - sizeof(kMagic) - 8, path);
  const auto version = in.read<std::uint32_t>();
  if (version < kOldestReadable || version > kVersion)
    throw InputError(path, "checkpoint", fmt::format("format version {}", version),
                     fmt::format("version {} to {}", kOldestReadable, kVersion));
  if (in.read<std::uint32_t>() != kByteOrder)
    throw InputError(path, "checkpoint", "another byte order", "a checkpoint written on a machine of this byte order");
  if (in.read<std::uint64_t>() != sceneFingerprint(scene) && sameScene)
    throw InputError(path, "checkpoint",
                     "a checkpoint of another scene (the scene or model file, its elements, bonds, effects or time "
                     "step changed since it was written)",
                     "the unchanged scene of the interrupted run, or a fresh run without --resume");
  if (version >= 3) writtenBy_ = in.read<std::string>();
  prelude_ = in.readVector<unsigned char>("prelude");
  state_ = in.readVector<unsigned char>("state");
  tail_ = in.readVector<unsigned char>("run section");
}

namespace {
constexpr const char* kFinalStateTag = "mDEM final state";

// What a final state must share with the scene that starts from it: the elements (count, types,
// the types' sizes and masses) and the bonds (ends and stiffnesses).
std::uint64_t elementsFingerprint(const Scene& s) {
  std::uint64_t h = 0;
  hashValue(h, s.bodies.size());
  for (const ElementType& t : s.elementTypes)
    for (double v : {t.thickness, t.width, t.radius, t.length, t.mass}) hashValue(h, v);
  for (int i = 0; i < s.bodies.size(); ++i) hashValue(h, s.bodies.type[i]);
  hashValue(h, s.bonds.size());
  for (const Bond& bd : s.bonds) hashValue(h, bd.a), hashValue(h, bd.b), hashValue(h, bd.k.kn), hashValue(h, bd.k.ks);
  return h;
}
}  // namespace

void writeFinalState(const std::string& path, const Scene& scene, const Simulation& sim) {
  writeCheckpoint(
      path, scene, sim,
      [&](BinaryWriter& out) {
        out.write(std::string(kFinalStateTag));
        out.write(elementsFingerprint(scene));
      },
      {});
}

FinalState readFinalState(const std::string& path, const Scene& scene) {
  const CheckpointFile file(path, scene, false);
  BinaryReader pre = file.prelude();
  // A run's checkpoint starts its prelude with the stage index (8 bytes), never this string.
  if (pre.remaining() < 8 + std::string(kFinalStateTag).size() || pre.read<std::string>() != kFinalStateTag)
    pre.fail("a run's checkpoint, not the final state of a completed run (written by [output] final_state)");
  if (pre.read<std::uint64_t>() != elementsFingerprint(scene))
    pre.fail("the final state of another film (its elements, their types or its bonds differ from this scene's)");
  FinalState f;
  BinaryReader in = file.state();
  f.step = in.read<std::int64_t>();
  f.time = in.read<double>();
  f.timeStep = in.read<double>();
  f.bodies = scene.bodies;
  readBodiesFrom(in, f.bodies);
  in.read<std::int64_t>();  // cycle start, held outer forces: a started run rebuilds them
  in.readVector<Vec3>("held outer forces");
  in.readVector<Vec3>("held outer torques");
  const auto n = in.read<std::uint64_t>();
  for (std::uint64_t k = 0; k < n; ++k) {
    std::string name = in.read<std::string>();
    f.effects.emplace_back(std::move(name), in.readVector<unsigned char>("effect state"));
  }
  return f;
}

std::string writingBuild(const std::string& commit) {
  return commit.empty() ? std::string("an earlier build (checkpoint format 2, no commit recorded)")
                        : "mesochain commit " + commit;
}

std::string resumedBuildNote(const std::string& commit) {
  if (commit == buildCommit()) return "";
  return fmt::format("note: the checkpoint was written by {}, this is mesochain commit {}: the run continues from "
                     "it, but it repeats an uninterrupted run bit for bit only on the build that wrote the checkpoint",
                     writingBuild(commit), buildCommit());
}

void CheckpointFile::restore(Simulation& sim) const {
  BinaryReader in = section(state_);
  const std::int64_t step = in.read<std::int64_t>();
  const double time = in.read<double>();
  if (in.read<double>() != sim.timeStep()) in.fail("a time step other than the rebuilt simulation's");
  State& state = sim.state();
  readBodiesFrom(in, state.bodies);
  state.time = time;
  sim.setStepCount(step);
  sim.setCycleStart(in.read<std::int64_t>());
  for (std::vector<Vec3>* held : {&state.heldForce, &state.heldTorque}) {
    std::vector<Vec3> v = in.readVector<Vec3>("held outer forces");
    if (v.size() != held->size())
      in.fail(fmt::format("held outer forces of {} elements where the scene's multiple time stepping holds {}", v.size(),
                          held->size()));
    *held = std::move(v);
  }
  in.expectCount("effects", sim.effects().size());
  for (const EffectPtr& e : sim.effects()) {
    const std::string name = in.read<std::string>();
    if (name != e->name()) in.fail("effect \"" + name + "\" where the scene has \"" + e->name() + "\"");
    const std::vector<unsigned char> block = in.readVector<unsigned char>("effect " + name);
    BinaryReader b(block.data(), block.size(), path_);
    e->loadState(b);
    if (b.remaining() != 0) b.fail("effect \"" + name + "\" has more state than this version reads");
  }
}

}  // namespace mesochain::mdem
