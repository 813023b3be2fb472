#pragma once
/// \file
/// The renderer's one shader program: lit (ambient, diffuse, specular, emissive, shininess)
/// or unlit surfaces, directional, point and spot lights, linear or exponential fog.

#include <epoxy/gl.h>

#include <map>
#include <string>

namespace gdpn::render::detail {

/// The most lights the program takes (u_kind, u_lcolor, ... have this many entries).
inline constexpr int kMaxLights = 8;

/// The program on the GPU and its uniforms' locations; needs a current context for its life.
class ShaderProgram {
 public:
  /// Compiles and links the program.
  ShaderProgram();
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;
  /// Draws use it from now on.
  void use() const;
  /// The location of uniform `name` ("u_proj", "u_kind[2]", ...), looked up once.
  GLint uniform(const std::string& name);

 private:
  GLuint id_ = 0;
  std::map<std::string, GLint> uniforms_;
};

}  // namespace gdpn::render::detail
