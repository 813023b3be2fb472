#pragma once
/// \file
/// How a surface looks: the colours and the shininess the shader program takes.

#include <glm/glm.hpp>

#include "gdpn/scene/mesh.h"
#include "gdpn/scene/node.h"

namespace gdpn::render::detail {

/// How a shape looks: a Material node's values (or the file's, or the defaults).
struct Look {
  glm::vec3 ambient{0.2f}, diffuse{0.8f}, specular{0.0f}, emissive{0.0f};  ///< colours, 0..1
  float shininess = 0.2f;  ///< 0..1 (the shader's exponent is 128 times it)
  float alpha = 1.0f;      ///< opacity, 0..1
  bool unlit = false;      ///< emissive colour only
};

/// The look a Material node gives (the defaults when `material` is null).
Look lookOf(const scene::Node* material);
/// The look a mesh file's own material gives.
Look lookOf(const scene::MeshMaterial& material);
/// An overlay's look: flat `colour` (0..1) at opacity `alpha` (0..1), unlit.
Look overlay(glm::vec3 colour, float alpha);

}  // namespace gdpn::render::detail
