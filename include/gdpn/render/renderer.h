#pragma once
/// \file
/// Draws a scene with OpenGL 3.3 core: materials (ambient, diffuse, specular, emissive,
/// shininess, transparency, transparent shapes back to front), directional, point and spot
/// lights (all gathered before anything is drawn), fog, every shape type, meshes from files,
/// terrain with view-dependent level of detail, overlays for sensors and joints, markings
/// that show how parts work (a conveyor's moving arrows, a visible Region's beam), and a
/// highlight on a selection. The renderer only reads the scene, draws into whatever
/// framebuffer is bound (gdpn::platform makes contexts and offscreen targets), and knows
/// nothing of models, simulations or the IDE (the caller gives the model time and which
/// sensors are active, for the parts' markings).

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gdpn/core/math.h"
#include "gdpn/render/camera.h"
#include "gdpn/scene/node.h"

namespace gdpn::render {

/// What to draw besides the scene.
/// A point where two shapes touch, to be marked (a red dot with its normal).
struct ContactMark {
  core::Vec3 position;  ///< world frame, m
  core::Vec3 normal;    ///< unit, world frame
};

struct DrawOptions {
  int width = 1280;                    ///< pixels
  int height = 720;                    ///< pixels
  core::Vec3 background{0.62, 0.70, 0.80};  ///< colour where nothing is (fog colour when fogged)
  bool sensors = false;                ///< translucent sensor volumes and rays
  /// What shows people how the parts work (camera sensors see none of it, as they see no
  /// overlay): arrows on the top face of each Cube a Conveyor drives (scene::drivingConveyor),
  /// pointing where it carries things and moving at its speed; Regions marked `visible`, a
  /// ray as a red beam and a volume translucent red, green while active.
  bool markings = true;
  double time = 0;                     ///< model time, s: how far a conveyor's arrows have moved (speed times time)
  /// Whether sensor node `n` is active now (a Region holds something); null: none is.
  std::function<bool(const scene::Node& n)> active;
  bool joints = false;                 ///< joint axes
  std::vector<ContactMark> contacts;   ///< contact points to mark, over everything: a dot 3 cm across and its normal, 20 cm long
  std::vector<scene::NodeHandle> selection;  ///< nodes whose shapes get outlined
  bool shadows = true;                 ///< the first directional light casts shadows (near the camera's target)
  bool sky = true;                     ///< a sky down to the horizon where nothing is drawn (not in fog)
  bool grid = true;                    ///< a grid on the ground (the first level Plane, else z = 0; none over a Terrain): lines every 1 m and 10 m
  double lod_error = 2.0;              ///< terrain: the most a simplification may move a vertex on screen, pixels
};

/// What one draw did.
struct DrawStats {
  std::size_t triangles = 0;   ///< the scene's triangles sent to the GPU (not the sky's, the grid's or the shadow pass's)
  std::size_t draw_calls = 0;  ///< draw calls made for the scene (likewise)
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
  /// What the last draw could not draw: each Mesh or Terrain node whose file could not be
  /// read, as `file:line:col: error: ` where its file was named (when known), the node's type
  /// and path, and why. Empty when the last draw drew everything; a file is read once, so a
  /// later draw with the node in it fails alike, and one without it is clean.
  [[nodiscard]] const std::vector<std::string>& problems() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gdpn::render
