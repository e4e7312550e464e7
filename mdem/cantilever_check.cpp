#include "mdem/cantilever_check.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {

CantileverCheck checkCantilever(const Scene& scene, const CantileverTheory& theory, long maxSteps) {
  const auto bad = [&](const std::string& found) {
    throw InputError(scene.source, "the cantilever check", found,
                     "a filament clamped at one element ([[fixed]] dofs = [\"all\"]) with one tip "
                     "moment ([[loads]] moment_pN_nm, no force)");
  };
  if (scene.boundary.fixed.size() != 1 || !scene.boundary.fixed[0].allRotationsFixed())
    bad(fmt::format("{} fixed elements", scene.boundary.fixed.size()));
  if (scene.boundary.loads.size() != 1) bad(fmt::format("{} loads", scene.boundary.loads.size()));
  const Load& load = scene.boundary.loads[0];
  if (load.force.norm() > 0.0 || load.moment.norm() == 0.0) bad("a load that is not a pure moment");
  if (!(theory.bendingStiffness > 0.0)) bad("no bending stiffness E I to compare with");
  const int clamp = scene.boundary.fixed[0].element, tip = load.element;
  const Vec3 axis0 = scene.bodies.position[tip] - scene.bodies.position[clamp];
  CantileverCheck c;
  c.length = axis0.norm();
  if (!(c.length > 0.0)) bad("the load on the clamped element");
  const Vec3 d = axis0 / c.length;
  c.twistingMoment = load.moment.dot(d);
  const Vec3 bending = load.moment - c.twistingMoment * d;
  c.bendingMoment = bending.norm();
  if (!(c.bendingMoment > 0.0)) bad("a moment without a bending part");
  const Vec3 bendAxis = bending / c.bendingMoment;
  // A moment about bendAxis turns the axis d towards bendAxis x d.
  const Vec3 deflectionDirection = bendAxis.cross(d);

  Simulation sim(scene);
  const long block = 200;
  for (; c.steps < maxSteps; c.steps += block) {
    sim.run(block);
    c.residualMoment = sim.residual().second;
    if (c.residualMoment < 1e-8 * load.moment.norm()) {
      c.relaxed = true;
      c.steps += block;
      break;
    }
  }
  const Bodies& b = sim.bodies();
  const Vec3 displacement = b.position[tip] - scene.bodies.position[tip];
  const Vec3 rotation = b.accumulatedRotation[tip];
  const double l = c.length, ei = theory.bendingStiffness;
  c.quantities.push_back({"tip deflection", "nm", displacement.dot(deflectionDirection),
                          c.bendingMoment * l * l / (2.0 * ei)});
  c.quantities.push_back({"tip bending rotation", "rad", rotation.dot(bendAxis), c.bendingMoment * l / ei});
  if (theory.torsionalStiffness > 0.0 && c.twistingMoment != 0.0)
    c.quantities.push_back({"tip twist", "rad", rotation.dot(d), c.twistingMoment * l / theory.torsionalStiffness});
  c.tolerance = theory.tolerance;
  c.passed = c.relaxed;
  for (const CantileverQuantity& q : c.quantities)
    c.passed = c.passed && std::abs(q.relativeDifference()) <= theory.tolerance;
  return c;
}

}  // namespace mesochain::mdem
