// The chain's mDEM cantilever check (mdem/cantilever_check.hpp): the cantilever scene written
// from a brick (beam/mdem_export.hpp), run by the mdem engine to its static state, bends and
// twists at its tip as Euler-Bernoulli theory of the beam constants says (delta = M l^2 / 2EI,
// phi = M l / EI, theta = T l / GJ) within the chain's tolerance; with the bonds 10 % too stiff
// or too soft it fails.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "beam/beam_model.hpp"
#include "beam_constants_support.hpp"
#include "beam/brick.hpp"
#include "beam/mdem_export.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "mdem/cantilever_check.hpp"
#include "mdem/scene_file.hpp"

namespace mesochain::beam {
namespace {

namespace fs = std::filesystem;

TEST(BeamCantileverCheck, BricksMatchBeamTheoryAndAWrongStiffnessFails) {
  // A collapsed-tube-like rectangle (beam_constants_support.hpp).
  const BeamConstants c = testing::collapsedTubeConstants();
  const double t0 = c.cellLength;
  const Brick b = discretise(rectangleFourConstants(c, "test"), 4, 120 * units::si::kCarbonMassDalton, "test");
  const fs::path dir = fs::temp_directory_path() / ("cantilever-check-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const MdemExportOptions o;  // the scene the chain writes (tip rotation 0.02 rad)
  std::ofstream(dir / o.modelFile) << mdemModelToml(b, o, "test");
  std::ofstream(dir / "cantilever.toml") << cantileverSceneToml(b, o);
  const mdem::Scene scene = mdem::loadScene((dir / "cantilever.toml").string());
  fs::remove_all(dir);

  // Beam theory from the constants, not from the bricks: E I = D_s / T0, G J = K T0.
  const double toPnNm2 = units::si::kHartreeInZeptojoule * units::si::kBohrInNm;
  mdem::CantileverTheory theory;
  theory.bendingStiffness = c.bendSoft / t0 * toPnNm2;
  theory.torsionalStiffness = c.twist * t0 * toPnNm2;
  theory.tolerance = 0.01;
  theory.massPerLength = b.mass * units::si::kDaltonInAttogram / (b.length * units::si::kBohrInNm);
  const mdem::CantileverCheck ok = mdem::checkCantilever(scene, theory);
  EXPECT_TRUE(ok.relaxed);
  ASSERT_EQ(ok.quantities.size(), 3u);
  for (const mdem::CantileverQuantity& q : ok.quantities)
    EXPECT_LT(std::abs(q.relativeDifference()), theory.tolerance) << q.name << " " << q.measured << " " << q.theory;
  EXPECT_TRUE(ok.passed);
  // The first bending frequency of the bricks against the tip-mass cantilever (the mass the
  // bricks lump at the tip): within 1 % for 10 bricks (reported, not part of passed).
  EXPECT_NEAR(ok.frequency / ok.frequencyTheory, 1.0, 0.01) << ok.frequency << " " << ok.frequencyTheory;
  // The deflection is the clamped-free closed form, not a multiple of it: l = 10 bricks.
  EXPECT_NEAR(ok.length, 10 * b.length * units::si::kBohrInNm, 1e-12 * ok.length);

  for (double factor : {1.1, 0.9}) {
    mdem::Scene wrong = scene;
    for (mdem::Bond& bond : wrong.bonds) {
      bond.k.kn *= factor;
      bond.k.ks *= factor;
    }
    const mdem::CantileverCheck bad = mdem::checkCantilever(wrong, theory);
    EXPECT_FALSE(bad.passed) << factor;
    EXPECT_NEAR(bad.quantities[0].relativeDifference(), 1.0 / factor - 1.0, 0.01) << factor;
  }

  // A scene that is no cantilever (no load) is an InputError naming the scene.
  mdem::Scene unloaded = scene;
  unloaded.boundary.loads.clear();
  EXPECT_THROW(mdem::checkCantilever(unloaded, theory), InputError);
}

}  // namespace
}  // namespace mesochain::beam
