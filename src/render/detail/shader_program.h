#pragma once
/// \file
/// The renderer's shader programs: surfaces, lit (ambient, diffuse, specular, emissive,
/// shininess) or unlit, by directional, point and spot lights, in linear or exponential fog;
/// depth only, for the shadow map; the sky down to the horizon; the ground grid.

#include <epoxy/gl.h>

#include <map>
#include <string>

namespace gdpn::render::detail {

/// The most lights the program takes (u_kind, u_lcolor, ... have this many entries).
inline constexpr int kMaxLights = 8;

/// Which program.
enum class ProgramKind {
  surface,  ///< shapes, meshes and terrains, lit and fogged, with shadows
  depth,    ///< positions only: the shadow map's pass (no shading to pay for)
  sky,      ///< a screen-filling triangle at the far plane: sky above the horizon, haze below
  grid,     ///< the ground grid on a plane, fading with distance
};

/// A program on the GPU and its uniforms' locations; needs a current context for its life.
class ShaderProgram {
 public:
  /// Compiles and links the program of `kind`.
  explicit ShaderProgram(ProgramKind kind);
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
