#pragma once
// Checkpoints of an mDEM run (`mesochain dem SCENE --resume`, docs/scene-file.md, restart):
// everything that determines the future, so that a resumed run continues bit for bit as the
// uninterrupted one would have:
//   the step count and time; every element's position, orientation, velocity, angular momentum,
//   force and torque (of the current state: the next half kick uses them), initial position and
//   accumulated rotation; each effect's evolving state (Effect::saveState: tracked twist
//   branches, dissipated work, the neighbour list and the positions it was built at); and what
//   the run loop adds (output file lengths, frame counter, recorded samples).
// Nothing in a run draws random numbers, so there is no RNG state to keep.
//
// Binary file: magic "MDEMCKPT", format version, byte-order mark, the scene's fingerprint, the
// commit of the build that wrote it (format 3; format 2 files are read without one), the
// sections, and an FNV-1a checksum of all bytes before it. Written atomically (temporary file +
// rename), so a kill while writing leaves the previous checkpoint. A truncated or corrupt file, a
// checkpoint of another scene (fingerprint: the scene and model file text, the element types,
// initial elements, bonds, effects and the time step) or of another machine's byte order is an
// InputError naming the file.
#include <cstdint>
#include <functional>
#include <string>

#include "mdem/binary_io.hpp"
#include "mdem/scene.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {

// FNV-1a, 64 bit, continuing from `seed` (0: start).
std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t seed = 0);

// What identifies a scene's run: the input files' hash plus its initial state and effects.
std::uint64_t sceneFingerprint(const Scene& scene);

// Writes the simulation's state to `path` atomically, with the run loop's two sections:
// `prelude` (what the loop needs to rebuild the simulation: e.g. the stage and its starting
// state) and `tail` (its outputs' state). `scene` is the scene file's scene (the fingerprint).
void writeCheckpoint(const std::string& path, const Scene& scene, const Simulation& sim,
                     const std::function<void(BinaryWriter&)>& prelude,
                     const std::function<void(BinaryWriter&)>& tail);

// A checkpoint read and checked (magic, checksum, version, byte order, fingerprint of `scene`):
// the prelude first, then restore() into a simulation rebuilt from it, then the tail.
class CheckpointFile {
 public:
  // sameScene = false: the fingerprint is not checked (a final-state file read by another scene:
  // readFinalState checks what must match).
  CheckpointFile(const std::string& path, const Scene& scene, bool sameScene = true);
  BinaryReader prelude() const { return section(prelude_); }
  // Step, time, every element's state and each effect's; the simulation's time step must be
  // the checkpoint's.
  void restore(Simulation& sim) const;
  BinaryReader tail() const { return section(tail_); }
  BinaryReader state() const { return section(state_); }
  // The commit of the build that wrote it (common/build_info.hpp); empty for format 2. Only
  // the same build continues a run bit for bit as the uninterrupted run would have.
  const std::string& writtenBy() const { return writtenBy_; }

 private:
  BinaryReader section(const std::vector<unsigned char>& bytes) const {
    return BinaryReader(bytes.data(), bytes.size(), path_);
  }
  std::string path_, writtenBy_;
  std::vector<unsigned char> prelude_, state_, tail_;
};

// The note for a run resumed from a checkpoint written by the build `commit` (writtenBy()), or ""
// when that is this build: the run continues correctly, but bit for bit as an uninterrupted run
// only on the build that wrote it (arithmetic may change between builds).
std::string resumedBuildNote(const std::string& commit);
// "mesochain commit X", or what a format-2 checkpoint's empty commit means.
std::string writingBuild(const std::string& commit);

// The state a completed run ends in ([output] final_state), for another scene's [run] start_from:
// the step and time, every element's state and each effect's evolving state by name. The file
// is a checkpoint whose prelude marks it as a final state and identifies the elements it holds
// (count, types, element types, bonds); written atomically.
struct FinalState {
  long step = 0;
  double time = 0.0;     // ns
  double timeStep = 0.0; // ns, of the run that wrote it
  Bodies bodies;
  std::vector<std::pair<std::string, std::vector<unsigned char>>> effects;  // name, saveState bytes (run.hpp EffectStates)
};
void writeFinalState(const std::string& path, const Scene& scene, const Simulation& sim);
// Reads `path` for `scene`, whose elements must be those of the run that wrote it (InputError
// naming the file otherwise: not a final-state file, another film, corrupt or truncated).
FinalState readFinalState(const std::string& path, const Scene& scene);

// Every per-element array of `b` (not types, masses, inertia: those come from the scene).
void writeBodiesTo(BinaryWriter& out, const Bodies& b);
// Reads them into `b`, which must have as many elements.
void readBodiesFrom(BinaryReader& in, Bodies& b);

}  // namespace mesochain::mdem
