#include "look.h"

#include "gl_math.h"

namespace gdpn::render::detail {

namespace field = scene::field;

Look lookOf(const scene::Node* m) {
  Look l;
  if (m == nullptr) return l;
  l.ambient = gv(m->vec3(field::Material::Ambient));
  l.diffuse = gv(m->vec3(field::Material::Diffuse));
  l.specular = gv(m->vec3(field::Material::Specular));
  l.emissive = gv(m->vec3(field::Material::Emissive));
  l.shininess = static_cast<float>(m->number(field::Material::Shininess));
  l.alpha = static_cast<float>(1.0 - m->number(field::Material::Transparency));
  return l;
}

Look lookOf(const scene::MeshMaterial& m) {
  Look l;
  l.ambient = gv(m.ambient);
  l.diffuse = gv(m.diffuse);
  l.specular = gv(m.specular);
  l.emissive = gv(m.emissive);
  l.shininess = static_cast<float>(m.shininess);
  l.alpha = static_cast<float>(1.0 - m.transparency);
  return l;
}

Look overlay(glm::vec3 colour, float alpha) {
  Look l;
  l.emissive = colour;
  l.alpha = alpha;
  l.unlit = true;
  return l;
}

}  // namespace gdpn::render::detail
