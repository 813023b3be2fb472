#pragma once
/// \file
/// Small 3D math in double precision: vectors, quaternions, rigid poses, boxes and rays.
/// World frame: metres, right-handed, Z up.

#include <array>
#include <cmath>

namespace gdpn::core {

/// A 3D vector (metres, or whatever the field says).
struct Vec3 {
  double x = 0, y = 0, z = 0;

  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3 operator*(double s, Vec3 a) { return a * s; }
  friend Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
  friend bool operator==(const Vec3&, const Vec3&) = default;
  /// Component-wise product.
  [[nodiscard]] Vec3 times(Vec3 b) const { return {x * b.x, y * b.y, z * b.z}; }
  [[nodiscard]] double dot(Vec3 b) const { return x * b.x + y * b.y + z * b.z; }
  [[nodiscard]] Vec3 cross(Vec3 b) const { return {y * b.z - z * b.y, z * b.x - x * b.z, x * b.y - y * b.x}; }
  [[nodiscard]] double length() const { return std::sqrt(dot(*this)); }
  /// This vector scaled to length 1 (the zero vector stays zero).
  [[nodiscard]] Vec3 normalized() const {
    const double l = length();
    return l > 0 ? *this * (1.0 / l) : *this;
  }
};

/// A unit quaternion: a rotation.
struct Quat {
  double w = 1, x = 0, y = 0, z = 0;

  /// The rotation by `angle_rad` radians about `axis` (any length but zero).
  static Quat axisAngle(Vec3 axis, double angle_rad);
  friend Quat operator*(Quat a, Quat b);
  friend bool operator==(const Quat&, const Quat&) = default;
  /// `v` rotated by this rotation.
  [[nodiscard]] Vec3 rotate(Vec3 v) const;
  /// The inverse rotation.
  [[nodiscard]] Quat conjugate() const { return {w, -x, -y, -z}; }
  /// Axis (unit) and angle (radians, 0..pi) of this rotation.
  [[nodiscard]] std::pair<Vec3, double> toAxisAngle() const;
};

/// A rigid placement: rotate, then translate. Scale is carried separately by the scene.
struct Pose {
  Vec3 position;  ///< metres
  Quat rotation;  ///< orientation

  /// This pose followed by `local` expressed in it (parent * child).
  [[nodiscard]] Pose operator*(const Pose& local) const {
    return {position + rotation.rotate(local.position), rotation * local.rotation};
  }
  /// A point given in this pose's frame, in the outer frame.
  [[nodiscard]] Vec3 apply(Vec3 p) const { return position + rotation.rotate(p); }
  /// The inverse placement.
  [[nodiscard]] Pose inverse() const {
    const Quat r = rotation.conjugate();
    return {r.rotate(-position), r};
  }
};

/// An axis-aligned box; empty when lo > hi.
struct Aabb {
  Vec3 lo{1, 1, 1};   ///< minimum corner
  Vec3 hi{-1, -1, -1};///< maximum corner

  [[nodiscard]] bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  /// Grows the box to hold `p`.
  void add(Vec3 p);
  /// Grows the box to hold `b`.
  void add(const Aabb& b);
  /// The box around this box placed by `pose` (its eight corners transformed).
  [[nodiscard]] Aabb transformed(const Pose& pose) const;
};

/// A ray: origin + t * direction, t >= 0.
struct Ray {
  Vec3 origin;     ///< metres
  Vec3 direction;  ///< unit length
};

/// Distance along `ray` to where it enters `box`, or -1 when it misses.
double intersect(const Ray& ray, const Aabb& box);

/// Degrees to radians.
inline double radians(double degrees) { return degrees * (M_PI / 180.0); }
/// Radians to degrees.
inline double degrees(double radians) { return radians * (180.0 / M_PI); }

}  // namespace gdpn::core
