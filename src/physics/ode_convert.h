#pragma once
/// \file
/// Conversions between gdpn's math types and ODE's arrays. Private to src/physics.

#include <ode/ode.h>

#include "gdpn/core/math.h"

namespace gdpn::physics {

/// Places ODE body `b` at `p` (world frame, metres).
inline void setPose(dBodyID b, const core::Pose& p) {
  dBodySetPosition(b, p.position.x, p.position.y, p.position.z);
  const dQuaternion q = {p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z};
  dBodySetQuaternion(b, q);
}

/// Where ODE body `b` is (world frame, metres).
inline core::Pose bodyPose(dBodyID b) {
  const dReal* p = dBodyGetPosition(b);
  const dReal* q = dBodyGetQuaternion(b);
  return {{p[0], p[1], p[2]}, {q[0], q[1], q[2], q[3]}};
}

/// The rotation matrix of `q`, as ODE's mass functions take it.
inline void rotationMatrix(const core::Quat& q, dMatrix3 r) {
  const dQuaternion dq = {q.w, q.x, q.y, q.z};
  dRfromQ(r, dq);
}

/// Three of ODE's numbers as a vector.
inline core::Vec3 v3(const dReal* v) { return {v[0], v[1], v[2]}; }

/// The box ODE keeps around geometry `g` (world frame, metres).
inline core::Aabb aabbOf(dGeomID g) {
  dReal a[6];
  dGeomGetAABB(g, a);
  return {{a[0], a[2], a[4]}, {a[1], a[3], a[5]}};
}

}  // namespace gdpn::physics
