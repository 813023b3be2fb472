#include "gl_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

namespace gdpn::render::detail {

glm::mat4 placement(const core::Pose& pose, core::Vec3 scale) {
  const glm::mat4 t = glm::translate(glm::mat4(1.0f), gv(pose.position));
  const auto& q = pose.rotation;
  const double angle = 2 * std::acos(std::clamp(q.w, -1.0, 1.0));
  const double s = std::sqrt(std::max(0.0, 1 - q.w * q.w));
  glm::mat4 r(1.0f);
  if (s > 1e-12) r = glm::rotate(glm::mat4(1.0f), static_cast<float>(angle), glm::vec3(q.x / s, q.y / s, q.z / s));
  return glm::scale(t * r, gv(scale));
}

glm::mat4 alongZ(glm::vec3 dir) {
  dir = glm::normalize(dir);
  const glm::vec3 z(0, 0, 1);
  const float c = glm::dot(z, dir);
  if (c > 0.9999f) return glm::mat4(1.0f);
  if (c < -0.9999f) return glm::rotate(glm::mat4(1.0f), static_cast<float>(std::numbers::pi), glm::vec3(1, 0, 0));
  return glm::rotate(glm::mat4(1.0f), std::acos(c), glm::normalize(glm::cross(z, dir)));
}

}  // namespace gdpn::render::detail
