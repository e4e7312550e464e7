#pragma once
// Shared set-up for the mdem tests: a straight filament of bricks along z.
#include "mdem/scene.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem::testing {

// Brick of a collapsed tube (nm, ag) and moduli (MPa): Y = 1 TPa, G = 0.4 TPa.
inline constexpr double kH = 0.8, kW = 2.4, kL = 2.0, kMass = 0.01;
inline constexpr double kYoung = 1.0e6, kShear = 0.4e6;

inline Scene filament(int count, const Vec3& start = Vec3::Zero(),
                      const Vec3& direction = Vec3::UnitZ(),
                      const Vec3& thicknessAxis = Vec3::UnitX()) {
  Scene s;
  ElementType t;
  t.name = "brick";
  t.shape = Shape::Brick;
  t.thickness = kH, t.width = kW, t.length = kL, t.mass = kMass;
  s.elementTypes.push_back(t);
  BondType b;
  b.name = "cnt";
  b.fromModuli = true;
  b.youngModulus = kYoung, b.shearModulus = kShear;
  s.bondTypes.push_back(b);
  FilamentSpec f;
  f.count = count, f.start = start, f.direction = direction, f.thicknessAxis = thicknessAxis;
  addFilament(s, f);
  s.effects = {"bonds"};
  return s;
}

// Cantilever: element 0 fully fixed.
inline Scene cantilever(int count) {
  Scene s = filament(count);
  FixedDofs f;
  f.element = 0;
  f.fixed.fill(true);
  s.boundary.fixed.push_back(f);
  return s;
}

// Section of the bricks: A = h w, I_x = h w^3/12, I_y = w h^3/12, J = I_x + I_y.
inline double area() { return kH * kW; }
inline double inertiaX() { return kH * kW * kW * kW / 12.0; }
inline double inertiaY() { return kW * kH * kH * kH / 12.0; }
inline double polar() { return inertiaX() + inertiaY(); }

}  // namespace mesochain::mdem::testing
