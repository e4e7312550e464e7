#include "mdem/cantilever_check.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/normal_modes.hpp"
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
  if (theory.massPerLength > 0.0) {
    // The bending modes in the plane of the deflection: the displacement along it and the
    // rotation about the bending axis of every element but the clamped one (world axes).
    int a = 0, r = 0;
    deflectionDirection.cwiseAbs().maxCoeff(&a);
    bendAxis.cwiseAbs().maxCoeff(&r);
    if (std::abs(deflectionDirection[a]) < 1.0 - 1e-9 || std::abs(bendAxis[r]) < 1.0 - 1e-9)
      bad("a filament or moment not along world axes (no in-plane modes)");
    std::vector<bool> dofs(6 * scene.bodies.size(), false);
    for (int i = 0; i < scene.bodies.size(); ++i)
      if (i != clamp) dofs[6 * i + a] = dofs[6 * i + 3 + r] = true;
    const double twoPi = 2.0 * 3.14159265358979323846;
    c.frequency = eigenfrequencies(scene.bodies, scene.bonds, dofs)[0] / twoPi;  // rad/ns -> GHz
    // The first root bl of the tip-mass cantilever's frequency equation (bisection: it lies
    // between 0.5 and 1.8751 for tip masses up to 4 mu l).
    const double tipRatio = 0.5 * scene.bodies.mass[tip] / (theory.massPerLength * l);
    const auto equation = [tipRatio](double x) {
      return 1.0 + std::cos(x) * std::cosh(x) +
             tipRatio * x * (std::cos(x) * std::sinh(x) - std::sin(x) * std::cosh(x));
    };
    double lo = 0.5, hi = 1.8751040687119611;
    for (int k = 0; k < 100; ++k) {
      const double mid = 0.5 * (lo + hi);
      (equation(lo) * equation(mid) <= 0.0 ? hi : lo) = mid;
    }
    const double beta = 0.5 * (lo + hi);
    c.frequencyTheory = beta * beta / twoPi * std::sqrt(ei / (theory.massPerLength * l * l * l * l));
  }
  c.tolerance = theory.tolerance;
  c.passed = c.relaxed;
  for (const CantileverQuantity& q : c.quantities)
    c.passed = c.passed && std::abs(q.relativeDifference()) <= theory.tolerance;
  return c;
}

}  // namespace mesochain::mdem
