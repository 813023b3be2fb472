#include "unit_shapes.h"

#include <cmath>
#include <numbers>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "gl_math.h"

namespace gdpn::render::detail {

namespace {

/// Builds interleaved vertices for the unit shapes.
struct ShapeBuilder {
  std::vector<float> v;
  std::vector<std::uint32_t> i;
  std::uint32_t vertex(glm::vec3 p, glm::vec3 n) {
    v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
    return static_cast<std::uint32_t>(v.size() / 6 - 1);
  }
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) { i.insert(i.end(), {a, b, c, a, c, d}); }
};

}  // namespace

glm::mat4 UnitShape::fit(const glm::mat4& at, core::Vec3 size) const {
  return glm::scale(at, gv(core::Vec3{size.x / extent.x, size.y / extent.y, size.z / extent.z}));
}

UnitShape unitCube() {
  ShapeBuilder b;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      glm::vec3 n(0.0f);
      n[axis] = static_cast<float>(sign);
      glm::vec3 u(0.0f), w(0.0f);
      u[(axis + 1) % 3] = 1.0f;
      w[(axis + 2) % 3] = 1.0f;
      if (sign < 0) std::swap(u, w);
      const glm::vec3 c = 0.5f * n;
      const auto a = b.vertex(c - 0.5f * u - 0.5f * w, n), bb = b.vertex(c + 0.5f * u - 0.5f * w, n),
                 cc = b.vertex(c + 0.5f * u + 0.5f * w, n), d = b.vertex(c - 0.5f * u + 0.5f * w, n);
      b.quad(a, bb, cc, d);
    }
  }
  GpuMesh g;
  g.upload(b.v, b.i);
  return {g, {1, 1, 1}};
}

UnitShape unitSphere() {
  ShapeBuilder b;
  constexpr int kSlices = 48, kStacks = 24;
  for (int s = 0; s <= kStacks; ++s) {
    const double phi = std::numbers::pi * s / kStacks;
    for (int k = 0; k <= kSlices; ++k) {
      const double th = 2 * std::numbers::pi * k / kSlices;
      const glm::vec3 n(static_cast<float>(std::sin(phi) * std::cos(th)), static_cast<float>(std::sin(phi) * std::sin(th)),
                        static_cast<float>(std::cos(phi)));
      b.vertex(n, n);
    }
  }
  for (int s = 0; s < kStacks; ++s) {
    for (int k = 0; k < kSlices; ++k) {
      const auto a = static_cast<std::uint32_t>(s * (kSlices + 1) + k);
      const auto c = static_cast<std::uint32_t>((s + 1) * (kSlices + 1) + k);
      b.quad(a, c, c + 1, a + 1);
    }
  }
  GpuMesh g;
  g.upload(b.v, b.i);
  return {g, {2, 2, 2}};
}

UnitShape unitRound(bool cone) {
  ShapeBuilder b;
  constexpr int kSlices = 48;
  const float top = cone ? 0.0f : 1.0f;
  const float slope = cone ? 1.0f : 0.0f;  // outward normal tilts up by the radius change
  for (int k = 0; k < kSlices; ++k) {
    const double t0 = 2 * std::numbers::pi * k / kSlices, t1 = 2 * std::numbers::pi * (k + 1) / kSlices;
    const glm::vec3 d0(static_cast<float>(std::cos(t0)), static_cast<float>(std::sin(t0)), 0.0f);
    const glm::vec3 d1(static_cast<float>(std::cos(t1)), static_cast<float>(std::sin(t1)), 0.0f);
    const glm::vec3 n0 = glm::normalize(d0 + glm::vec3(0, 0, slope)), n1 = glm::normalize(d1 + glm::vec3(0, 0, slope));
    const auto a = b.vertex(d0 + glm::vec3(0, 0, -0.5f), n0), c = b.vertex(d1 + glm::vec3(0, 0, -0.5f), n1);
    const auto e = b.vertex(top * d1 + glm::vec3(0, 0, 0.5f), n1), f = b.vertex(top * d0 + glm::vec3(0, 0, 0.5f), n0);
    b.quad(a, c, e, f);
    // caps
    const auto bc = b.vertex({0, 0, -0.5f}, {0, 0, -1}), b0 = b.vertex(d0 + glm::vec3(0, 0, -0.5f), {0, 0, -1}),
               b1 = b.vertex(d1 + glm::vec3(0, 0, -0.5f), {0, 0, -1});
    b.i.insert(b.i.end(), {bc, b1, b0});
    if (!cone) {
      const auto tc = b.vertex({0, 0, 0.5f}, {0, 0, 1}), t0v = b.vertex(d0 + glm::vec3(0, 0, 0.5f), {0, 0, 1}),
                 t1v = b.vertex(d1 + glm::vec3(0, 0, 0.5f), {0, 0, 1});
      b.i.insert(b.i.end(), {tc, t0v, t1v});
    }
  }
  GpuMesh g;
  g.upload(b.v, b.i);
  return {g, {2, 2, 1}};
}

GpuMesh unitPlane() {
  // "endless" ground: a 2 km square
  ShapeBuilder b;
  b.v.reserve(4 * 6);  // the four corners up front: GCC 12 sees a false overflow in growing from empty
  const glm::vec3 n(0, 0, 1);
  b.quad(b.vertex({-1000, -1000, 0}, n), b.vertex({1000, -1000, 0}, n), b.vertex({1000, 1000, 0}, n),
         b.vertex({-1000, 1000, 0}, n));
  GpuMesh g;
  g.upload(b.v, b.i);
  return g;
}

GpuMesh unitChevron() {
  // ">" as two parallelograms meeting along the x axis: the outer edge through the tip at
  // (0.5, 0), the inner edge through the notch 0.45 behind it
  constexpr float kArm = 0.45f;
  ShapeBuilder b;
  b.v.reserve(6 * 6);
  const glm::vec3 n(0, 0, 1);
  const auto back_left = b.vertex({-0.5f, 0.5f, 0}, n), back_left_in = b.vertex({-0.5f + kArm, 0.5f, 0}, n);
  const auto tip = b.vertex({0.5f, 0, 0}, n), notch = b.vertex({0.5f - kArm, 0, 0}, n);
  const auto back_right_in = b.vertex({-0.5f + kArm, -0.5f, 0}, n), back_right = b.vertex({-0.5f, -0.5f, 0}, n);
  b.quad(back_left, notch, tip, back_left_in);
  b.quad(notch, back_right, back_right_in, tip);
  GpuMesh g;
  g.upload(b.v, b.i);
  return g;
}

}  // namespace gdpn::render::detail
