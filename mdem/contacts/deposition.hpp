#pragma once
// Deposition generator of buckypaper films ([network] method = "deposition",
// docs/scene-file.md): tubes are laid one at a time from above onto the growing film, each
// element coming to rest at the contact gap on whatever lies below it, so tubes cross and drape
// over each other.
//
// One tube: a start point uniform over the generation domain, an in-plane heading (isotropic, or
// with probability alignedFraction a normal spread of alignmentSpread about alignmentAngle; either
// way run forwards or backwards with probability 1/2) and, for a wavy tube, each next element's
// heading turned by a uniform angle in [-waviness, waviness] (as the random generator). The tube
// is a chain of equal elements whose consecutive ends meet: end heights zeta_0..zeta_n, element k
// from end k to end k+1 with in-plane length sqrt(L^2 - (zeta_{k+1} - zeta_k)^2) along its heading.
// Laying it:
//   1. place the elements with the current end heights (first: all on the floor z = 0);
//   2. support S_k of element k: the lowest centre height at which a horizontal element of full
//      length L at element k's in-plane centre and heading keeps the wall gap minimumGap from
//      every element laid before (drape_geometry.hpp, supportHeight; minimum image on periodic
//      axes), and at least the floor 0; required end heights r_e = max(S_{e-1}, S_e) (an element
//      whose two ends are at least S_k clears everything, tilted or not);
//   3. if the current end heights are >= r_e everywhere the tube is laid; otherwise the end
//      heights become the draped envelope of r (from round 1 on the maximum of r over the rounds,
//      which makes the loop settle) (drapeEnvelope: slope at most
//      maxSlope, bend per bond at most bendPerElement at a crest) and the tube is placed again
//      (the in-plane spacing shrinks where the tube climbs, so supports move: hence the loop).
// A clear profile is lowered again onto the supports at its new place until it rests there
// (within 0.02 nm: its crests at the contact gap to that precision); after 30 rounds the last clear profile is kept (counted as hovering). A
// tube that has no clear profile after 30 rounds, or (wavy tubes) comes closer than minimumGap to
// itself beyond 3 elements along it, is redrawn (attemptsPerTube times at most).
//
// Boundaries. Periodic: the domain is the film, periodic along x and y; a tube continues across
// an edge with unwrapped positions (the engine's convention). A tube of length l cannot meet its
// own periodic image when l + 2R + minimumGap <= the shorter box side (two of its points are at
// most l apart, images of a point at least a box side): a longer tube is an error. Cut: the tubes
// are laid on a periodic sheet (sheetSize) and the film is the rectangle [0, x] x [0, y] cut out
// of the sheet's middle; elements whose centre lies outside are removed, and a tube leaving and
// re-entering the specimen becomes separate filaments (no bond across a cut).
//
// Rest state of the bonds: Straight (bonds created on the straight tube, then the elements moved
// to their laid place, each orientation carried from the previous one by the minimal rotation
// between consecutive axes: the bonds store bending only, no stretch, shear or twist); AsLaid
// (bonds created in the laid configuration: zero bond energy).
//
// Reproducible: std::mt19937_64 with explicit uniform transforms.
#include <cstdint>
#include <string>

#include "mdem/scene.hpp"

namespace mesochain::mdem {

enum class RestShape { Straight, AsLaid };
enum class FilmBoundary { Periodic, Cut };

struct DepositionSpec {
  int elementType = 0;
  int bondType = 0;
  int elementsPerTube = 0;
  double sizeX = 0.0, sizeY = 0.0;   // nm, the film (the specimen in cut mode)
  FilmBoundary boundary = FilmBoundary::Periodic;
  double sheetX = 0.0, sheetY = 0.0; // nm, cut mode: the periodic sheet (> film + tube length)
  int tubes = 0;                     // > 0: lay this many tubes (on the sheet in cut mode)
  double thickness = 0.0;            // nm; tubes == 0: lay until the film is this thick; else a limit
  std::string countKey = "key network.tubes";  // where the count came from (messages)
  double waviness = 0.0;             // rad per element
  double alignedFraction = 0.0;      // fraction of tubes drawn about alignmentAngle
  double alignmentAngle = 0.0;       // rad from x, in plane
  double alignmentSpread = 0.0;      // rad, standard deviation of the aligned headings
  double maxSlope = 10.0 * 3.14159265358979323846 / 180.0;       // rad
  double bendPerElement = 5.0 * 3.14159265358979323846 / 180.0;  // rad
  double minimumGap = 0.3;           // nm, wall to wall: the rest gap and the least gap
  RestShape restShape = RestShape::Straight;
  std::uint64_t seed = 1;
  int attemptsPerTube = 200;
  long maximumElements = 20000000;   // the thickness target's budget
};

struct DepositionResult {
  int tubesLaid = 0;
  long elementsLaid = 0;          // on the generation domain (before any cut)
  double domainThickness = 0.0;   // nm, z extent of centres + 2R on the generation domain
  int filaments = 0;              // in the scene (cut tubes count each piece)
  long hoveringTubes = 0;         // laid on a clear profile that did not settle onto its supports
                                  // within the rounds (it lies above them, never into them)
};

// Appends the film's elements and bonds to `scene` (types must exist) and sets scene.filmSize
// (x, y, centre z span). Does not touch scene.periodic (the scene reader sets it). Throws
// InputError naming scene.source and the key for requests that cannot be met.
DepositionResult depositFilm(Scene& scene, const DepositionSpec& spec);


}  // namespace mesochain::mdem
