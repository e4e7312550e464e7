#pragma once
// Rigid elements of the mesoscopic distinct element method: bricks (collapsed tubes) and
// cylinders, each with 6 degrees of freedom. Plain data, structure of arrays, so that kernels
// and OpenMP loops run over contiguous vectors. Units: mdem/units.hpp (nm, ag, ns).
//
// Body frame: z along the element length L; for a brick x along the thickness h and y along the
// width w. The principal axes of inertia are the body axes.
#include <string>
#include <vector>

#include "mdem/quaternion.hpp"

namespace mesochain::mdem {

enum class Shape { Brick, Cylinder };

// One kind of element (from a model file or a scene).
struct ElementType {
  std::string name;
  Shape shape = Shape::Brick;
  double thickness = 0.0;  // h, nm (brick)
  double width = 0.0;      // w, nm (brick)
  double radius = 0.0;     // nm (cylinder)
  double length = 0.0;     // L, nm
  double mass = 0.0;       // ag

  double volume() const;
  // Principal moments of inertia of a homogeneous solid about its centre (ag nm^2):
  // brick  I = m/12 (w^2+L^2, h^2+L^2, h^2+w^2);
  // cylinder I = (m/12 (3 r^2 + L^2), same, m r^2 / 2).
  Vec3 principalInertia() const;
  // Radius of the element's outer surface for contacts and gaps (nm): a cylinder's radius, half a
  // brick's thickness.
  double contactRadius() const { return shape == Shape::Cylinder ? radius : 0.5 * thickness; }
  // Half extents along body x, y, z (nm), for visualisation.
  Vec3 halfExtents() const;
};

// State of all elements. Velocities are world-frame; the angular state is the body-frame
// angular momentum pi = I omega_body (the variable of the rotation integrator).
struct Bodies {
  std::vector<int> type;        // index into the element types
  std::vector<Vec3> position;   // nm
  std::vector<Quat> orientation;
  std::vector<Vec3> velocity;   // nm/ns
  std::vector<Vec3> angularMomentumBody;  // ag nm^2 / ns
  std::vector<double> mass;     // ag
  std::vector<Vec3> inertia;    // principal moments, ag nm^2
  std::vector<Vec3> force;      // pN, world
  std::vector<Vec3> torque;     // pN nm, world
  // Probes: initial position and the accumulated rotation integral of omega_world dt (rad),
  // which measures rotations of any size about a fixed axis without wrapping.
  std::vector<Vec3> initialPosition;
  std::vector<Vec3> accumulatedRotation;

  int size() const { return static_cast<int>(position.size()); }
  // Appends one element at rest.
  void add(int typeIndex, const ElementType& t, const Vec3& x, const Quat& q);

  Vec3 angularVelocityBody(int i) const { return angularMomentumBody[i].cwiseQuotient(inertia[i]); }
  Vec3 angularVelocityWorld(int i) const { return rotate(orientation[i], angularVelocityBody(i)); }
  // Sets the body angular momentum from a world-frame angular velocity.
  void setAngularVelocityWorld(int i, const Vec3& omega);
};

// Inertia scaling ([run] mass_scale and rotational_inertia_scale, docs/scene-file.md): every
// element's mass becomes massScale times its type's (types[type[i]]) and its principal moments
// massScale * rotationalScale times the type's. Velocities and angular velocities are kept (the
// body angular momentum is rescaled). Scaling every inertia by s slows every vibration by sqrt(s)
// and lengthens the critical step by sqrt(s) (density scaling, Thornton, Geotechnique 50, 43
// (2000)); scaling the moments alone slows the rotational vibrations only (O'Sullivan & Bray,
// Eng. Comput. 21, 278 (2004)). Both are standard devices of quasi-static DEM. Idempotent, and
// elements that already have the target inertia are left bit for bit as they are.
void scaleInertia(Bodies& bodies, const std::vector<ElementType>& types, double massScale, double rotationalScale);

}  // namespace mesochain::mdem
