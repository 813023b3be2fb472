#pragma once
/// \file
/// Draws a scene with OpenGL 3.3 core: materials (ambient, diffuse, specular, emissive,
/// shininess, transparency, transparent shapes back to front), directional, point and spot
/// lights (all gathered before anything is drawn), fog, every shape type, meshes from files,
/// terrain with view-dependent level of detail, overlays for sensors and joints, and a
/// highlight on a selection. The renderer only reads the scene, draws into whatever
/// framebuffer is bound (gdpn::platform makes contexts and offscreen targets), and knows
/// nothing of models, simulations or the IDE.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "gdpn/core/math.h"
#include "gdpn/render/camera.h"
#include "gdpn/scene/node.h"

namespace gdpn::render {

/// What to draw besides the scene.
struct DrawOptions {
  int width = 1280;                    ///< pixels
  int height = 720;                    ///< pixels
  core::Vec3 background{0.62, 0.70, 0.80};  ///< colour where nothing is (fog colour when fogged)
  bool sensors = false;                ///< translucent sensor volumes and rays
  bool joints = false;                 ///< joint axes
  scene::NodeHandle selection = 0;     ///< a node whose shapes get outlined (0: none)
  bool shadows = true;                 ///< the first directional light casts shadows (near the camera's target)
  double lod_error = 2.0;              ///< terrain: the most a simplification may move a vertex on screen, pixels
};

/// What one draw did.
struct DrawStats {
  std::size_t triangles = 0;   ///< triangles sent to the GPU
  std::size_t draw_calls = 0;  ///< draw calls made
};

/// Draws scenes into the current framebuffer. Needs a current OpenGL 3.3 core context for its
/// whole life; keeps GPU copies of shapes, meshes and terrains between frames.
class Renderer {
 public:
  /// `model_dir`: where file fields (meshes, elevation files) are found.
  explicit Renderer(std::string model_dir);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  /// Draws `scene` seen by `camera` (world transforms as the scene holds them now).
  DrawStats draw(const scene::Scene& scene, const Camera& camera, const DrawOptions& options);
  /// Files that could not be read (each named once, with the reason).
  [[nodiscard]] const std::vector<std::string>& problems() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gdpn::render
