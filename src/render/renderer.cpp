#include "gdpn/render/renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gdpn/scene/actions.h"
#include "detail/gl_math.h"
#include "detail/gpu_cache.h"
#include "detail/look.h"
#include "detail/shader_program.h"
#include "detail/terrain_gpu.h"
#include "detail/unit_shapes.h"

namespace gdpn::render {

using detail::alongZ;
using detail::GpuCache;
using detail::GpuMesh;
using detail::gv;
using detail::kMaxLights;
using detail::Look;
using detail::lookOf;
using detail::overlay;
using detail::placement;
using detail::ShaderProgram;
using detail::TerrainGpu;
using detail::UnitShape;
using detail::unitChevron;
using detail::unitCube;
using detail::unitPlane;
using detail::unitRound;
using detail::unitSphere;
using scene::Node;
using scene::NodeKind;
namespace field = scene::field;

namespace {

/// One thing to draw.
struct Item {
  const GpuMesh* gpu = nullptr;
  const TerrainGpu* terrain = nullptr;
  glm::mat4 model{1.0f};
  Look look;
  const Node* node = nullptr;
  float depth = 0;  // view-space distance, for sorting transparent items
  bool decal = false;  // lies on a surface: drawn pulled towards the eye, casting no shadow
};

/// How many of its axes a joint of `kind` uses (axis1, then axis2).
int axesOf(scene::JointKind kind) {
  switch (kind) {
    case scene::JointKind::Ball:
    case scene::JointKind::Fixed: return 0;
    case scene::JointKind::Hinge:
    case scene::JointKind::Slider: return 1;
    case scene::JointKind::Universal:
    case scene::JointKind::Hinge2: return 2;
  }
  return 0;
}

/// The shader's number for a light of `kind` (u_kind).
int shaderKind(scene::LightKind kind) {
  switch (kind) {
    case scene::LightKind::Directional: return 0;
    case scene::LightKind::Point: return 1;
    case scene::LightKind::Spot: return 2;
  }
  return 0;
}

/// The shader's number for fog of `kind` (u_fog; 0 is none).
int shaderKind(scene::FogKind kind) {
  switch (kind) {
    case scene::FogKind::Linear: return 1;
    case scene::FogKind::Exponential: return 2;
  }
  return 0;
}

}  // namespace

/// The depth texture the shadowing light sees, and the framebuffer that draws into it.
struct ShadowMap {
  static constexpr int kSize = 1024;  ///< texels on a side
  GLuint fbo = 0, texture = 0;
  /// Makes the texture and framebuffer the first time (needs a current context).
  void ensure() {
    if (fbo != 0) return;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, kSize, kSize, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
  }
  void release() {
    if (fbo != 0) glDeleteFramebuffers(1, &fbo);
    if (texture != 0) glDeleteTextures(1, &texture);
    fbo = texture = 0;
  }
};

struct Renderer::Impl {
  ShaderProgram program{detail::ProgramKind::surface}, depth{detail::ProgramKind::depth};
  ShaderProgram sky{detail::ProgramKind::sky}, grid{detail::ProgramKind::grid};
  ShaderProgram* active = &program;  // the one in use, whose uniforms u() finds
  GLuint empty_vao = 0;              // for the sky's triangle, which has no vertex buffer
  ShadowMap shadow;
  UnitShape cube = unitCube(), sphere = unitSphere(), cylinder = unitRound(false), cone = unitRound(true);
  GpuMesh plane = unitPlane(), chevron = unitChevron();
  GpuCache files;
  std::vector<std::string> problems;  // of the last draw

  explicit Impl(std::string model_dir) : files(std::move(model_dir)) { glGenVertexArrays(1, &empty_vao); }
  ~Impl() {
    for (GpuMesh* g : {&cube.gpu, &sphere.gpu, &cylinder.gpu, &cone.gpu, &plane, &chevron}) g->release();
    shadow.release();
    glDeleteVertexArrays(1, &empty_vao);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  /// Makes `p` the program in use.
  void use(ShaderProgram& p) {
    p.use();
    active = &p;
  }
  /// The location of the program's uniform `name` (-1, which GL ignores, when it has none).
  GLint u(const std::string& name) { return active->uniform(name); }

  /// Collects what to draw below `n`, with `material` in effect.
  void collect(const Node& n, const Node* material, const DrawOptions& opt, std::vector<Item>& items) {
    if (n.is_template) return;  // kept to be copied, not drawn
    const glm::mat4 at = placement(n.world, n.world_scale);
    switch (n.kind()) {
      case NodeKind::Cube: primitive(cube, n, at, lookOf(material), items); break;
      case NodeKind::Sphere: primitive(sphere, n, at, lookOf(material), items); break;
      case NodeKind::Cylinder: primitive(cylinder, n, at, lookOf(material), items); break;
      case NodeKind::Cone: primitive(cone, n, at, lookOf(material), items); break;
      case NodeKind::Plane:
        items.push_back({&plane, nullptr, at * alongZ(gv(n.vec3(field::Plane::Normal))), lookOf(material), &n, 0});
        break;
      case NodeKind::Mesh: mesh(n, at, material, items); break;
      case NodeKind::Terrain: {
        std::string why;
        if (const TerrainGpu* g = files.terrain(n, why)) {
          items.push_back({nullptr, g, at, lookOf(material), &n, 0});
        } else {
          problem(n, n.fieldLoc(field::Terrain::File), why);
        }
        break;
      }
      case NodeKind::Region:
        // a visible one in its own colours; the others with the sensor volumes
        if (opt.markings && n.flag(field::Region::Visible)) {
          region(n, at, markingLook(n, opt), items);
        } else if (opt.sensors) {
          region(n, at, overlay({1.0f, 0.85f, 0.1f}, 0.3f), items);
        }
        break;
      case NodeKind::Conveyor:
        if (opt.markings) belt(n, opt.time, items);
        break;
      case NodeKind::RangeFinder:
        if (opt.sensors) {
          const float length = static_cast<float>(n.number(field::RangeFinder::Length));
          ray(n, at, length, overlay({1.0f, 0.2f, 0.2f}, 0.8f), items);
        }
        break;
      case NodeKind::ColorCamera:
      case NodeKind::DepthCamera:
        if (opt.sensors) frustum(n, at, items);
        break;
      case NodeKind::LaserScan:
        if (opt.sensors) fan(n, at, items);
        break;
      case NodeKind::Joint:
        if (opt.joints) joint(n, at, items);
        break;
      // nothing of their own to draw: lights and fog are gathered before, a Material colours
      // the shapes after it, the rest is physics, sensing and grouping
      case NodeKind::Group:
      case NodeKind::Transform:
      case NodeKind::Material:
      case NodeKind::Light:
      case NodeKind::Camera:
      case NodeKind::Fog:
      case NodeKind::World:
      case NodeKind::Body:
      case NodeKind::GradientField:
      case NodeKind::GradientSensor:
      case NodeKind::KeyboardSensor:
      case NodeKind::MouseSensor:
      case NodeKind::Imu:
      case NodeKind::Gps:
      case NodeKind::Contact:
      case NodeKind::ForceTorque:
      case NodeKind::TimeSensor: break;
    }
    const Node* inner = material;
    for (const auto& child : n.children()) {
      if (child->kind() == NodeKind::Material && !child->is_template) inner = child.get();
      collect(*child, inner, opt, items);
    }
  }

  /// Node `n` could not be drawn, `why`: a problem of this draw, at `loc` (where its file
  /// field was written; the node's own place when that is unknown).
  void problem(const Node& n, const core::SourceLoc& loc, const std::string& why) {
    const core::SourceLoc& at = loc.line > 0 ? loc : n.loc;
    problems.push_back((at.line > 0 ? at.str() + ": error: " : std::string()) + n.type().name + " '" + n.path() +
                       "' cannot be drawn: " + why);
  }

  /// Primitive `n` (a shape, or a Region's volume) placed `at`: `shape` stretched to its extent.
  static void primitive(const UnitShape& shape, const Node& n, const glm::mat4& at, const Look& look,
                        std::vector<Item>& items) {
    items.push_back({&shape.gpu, nullptr, shape.fit(at, scene::shapeExtent(n)), look, &n, 0});
  }

  /// Mesh node `n`'s parts (or the one part it names), in `material` or else the file's own.
  void mesh(const Node& n, const glm::mat4& at, const Node* material, std::vector<Item>& items) {
    std::string why;
    const GpuCache::MeshGpu* m = files.mesh(n, why);
    if (m == nullptr) {
      problem(n, n.fieldLoc(field::Mesh::File), why);
      return;
    }
    const auto part = static_cast<long>(n.number(field::Mesh::Part));
    for (std::size_t i = 0; i < m->parts.size(); ++i) {
      if (part >= 0 && static_cast<std::size_t>(part) != i) continue;
      // a Material in the scene wins; otherwise the file's own
      Look look = lookOf(material);
      const int mi = m->materials[i];
      if (material == nullptr && mi >= 0 && static_cast<std::size_t>(mi) < m->data->materials.size()) {
        look = lookOf(m->data->materials[static_cast<std::size_t>(mi)]);
      }
      items.push_back({&m->parts[i], nullptr, glm::scale(at, gv(n.vec3(field::Mesh::Scale))), look, &n, 0});
    }
  }

  /// Region `n`'s volume, or its ray, in `look`.
  void region(const Node& n, const glm::mat4& at, const Look& look, std::vector<Item>& items) {
    switch (n.choice<scene::RegionShape>(field::Region::Shape)) {
      case scene::RegionShape::Box: primitive(cube, n, at, look, items); break;
      case scene::RegionShape::Sphere: primitive(sphere, n, at, look, items); break;
      case scene::RegionShape::Cylinder: primitive(cylinder, n, at, look, items); break;
      case scene::RegionShape::Cone: primitive(cone, n, at, look, items); break;
      case scene::RegionShape::Ray: ray(n, at, static_cast<float>(n.number(field::Region::Length)), look, items); break;
    }
  }

  /// How visible Region `n` looks: a ray as a red beam, a volume translucent red; bright
  /// green and more opaque while it is active.
  static Look markingLook(const Node& n, const DrawOptions& opt) {
    const bool ray = n.choice<scene::RegionShape>(field::Region::Shape) == scene::RegionShape::Ray;
    if (opt.active && opt.active(n)) return overlay({0.1f, 1.0f, 0.25f}, ray ? 1.0f : 0.4f);
    return overlay({0.95f, 0.08f, 0.05f}, ray ? 0.9f : 0.25f);
  }

  /// Conveyor `n`'s arrows, if it drives the shapes beside it (scene::drivingConveyor, the
  /// physics' rule): on the top face of each Cube among them, moved on by its speed over
  /// `time` (s).
  void belt(const Node& n, double time, std::vector<Item>& items) {
    const Node* parent = n.parent();
    if (parent == nullptr || scene::drivingConveyor(*parent) != &n) return;
    using F = field::Conveyor;
    const double speed = n.number(F::Speed);
    // where the belt carries things, in the world (as the physics turns `direction`)
    const core::Vec3 carries = n.world.rotation.rotate(n.vec3(F::Direction)) * (speed < 0 ? -1.0 : 1.0);
    if (carries.length() == 0) return;
    for (const auto& shape : parent->children()) {
      if (shape->kind() == NodeKind::Cube && !shape->is_template) arrows(n, *shape, carries, std::abs(speed) * time, items);
    }
  }

  /// Arrows of conveyor `n` on the top face of Cube `box` (the face most turned towards +z),
  /// pointing along `carries` (world frame) as laid in that face, `moved` m along it.
  void arrows(const Node& n, const Node& box, core::Vec3 carries, double moved, std::vector<Item>& items) {
    const core::Vec3 scale = box.world_scale;
    const glm::vec3 size = glm::abs(gv(scene::shapeExtent(box).times(scale)));
    // the top face: the axis of the box's frame whose direction is most upwards
    const core::Quat& q = box.world.rotation;
    const glm::vec3 up = gv(q.conjugate().rotate({0, 0, 1}));
    int axis = 2;
    for (int a = 0; a < 2; ++a) {
      if (std::abs(up[a]) > std::abs(up[axis])) axis = a;
    }
    glm::vec3 normal(0.0f);
    normal[axis] = up[axis] < 0 ? -1.0f : 1.0f;
    // the direction laid in the face (none when the belt runs across it)
    glm::vec3 along = gv(q.conjugate().rotate(carries));
    along[axis] = 0;
    if (glm::length(along) < 1e-6f * glm::length(gv(carries))) return;
    along = glm::normalize(along);
    // the face's chord through its centre along the arrows, and across them
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    const auto chord = [&](float di, float dj) {
      constexpr float kEndless = std::numeric_limits<float>::infinity();
      return std::min(di == 0 ? kEndless : size[i] / std::abs(di), dj == 0 ? kEndless : size[j] / std::abs(dj));
    };
    const float length = chord(along[i], along[j]), across = chord(along[j], along[i]);
    // an arrow 60 % as wide as the face, 45 % of that long, one every 1.6 widths; at most
    // kMaxArrows on a face (a long belt spaces them wider)
    constexpr int kMaxArrows = 64;
    float width = 0.6f * across, deep = 0.45f * width;
    if (deep > 0.8f * length) {
      width *= 0.8f * length / deep;
      deep = 0.8f * length;
    }
    const float spacing = std::max(1.6f * width, length / kMaxArrows);
    if (!(deep > 0.0f) || !(spacing > 0.0f)) return;
    const auto offset = static_cast<float>(std::fmod(moved, static_cast<double>(spacing)));
    // the face's frame: x along the arrows, z out of the face, y across
    glm::mat4 face(1.0f);
    face[0] = glm::vec4(along, 0.0f);
    face[1] = glm::vec4(glm::cross(normal, along), 0.0f);
    face[2] = glm::vec4(normal, 0.0f);
    face[3] = glm::vec4(0.5f * size[axis] * normal, 1.0f);
    const glm::mat4 on = placement(box.world, {1, 1, 1}) * face;
    // the arrows whose centres lie within the face, their whole length on it
    const float reach = 0.5f * (length - deep);
    Look look;
    look.ambient = look.diffuse = {0.95f, 0.78f, 0.15f};
    const auto first = static_cast<int>(std::ceil((-reach - offset) / spacing));
    const auto last = static_cast<int>(std::floor((reach - offset) / spacing));
    for (int k = first; k <= last; ++k) {
      const float x = offset + static_cast<float>(k) * spacing;
      items.push_back({&chevron, nullptr, glm::scale(glm::translate(on, {x, 0, 0}), {deep, width, 1}), look, &n, 0, true});
    }
  }

  /// Joint `n`'s axes (as many as its kind uses) and its anchor.
  void joint(const Node& n, const glm::mat4& at, std::vector<Item>& items) {
    const glm::mat4 anchor = glm::translate(at, gv(n.vec3(field::Joint::Anchor)));
    const glm::mat4 axis = glm::scale(glm::mat4(1.0f), glm::vec3(0.01f, 0.01f, 0.6f));
    const int axes = axesOf(n.choice<scene::JointKind>(field::Joint::Kind));
    if (axes >= 1) {
      items.push_back({&cylinder.gpu, nullptr, anchor * alongZ(gv(n.vec3(field::Joint::Axis1))) * axis,
                       overlay({0.1f, 0.9f, 0.3f}, 1.0f), &n, 0});
    }
    if (axes >= 2) {
      items.push_back({&cylinder.gpu, nullptr, anchor * alongZ(gv(n.vec3(field::Joint::Axis2))) * axis,
                       overlay({0.2f, 0.5f, 1.0f}, 1.0f), &n, 0});
    }
    items.push_back(
        {&sphere.gpu, nullptr, glm::scale(anchor, glm::vec3(0.03f)), overlay({0.1f, 0.9f, 0.3f}, 1.0f), &n, 0});
  }

  /// A contact point: a red dot 3 cm across and its normal, 20 cm long.
  void contact(const ContactMark& c, std::vector<Item>& items) {
    const Look look = overlay({0.95f, 0.1f, 0.1f}, 1.0f);
    const glm::mat4 at = glm::translate(glm::mat4(1.0f), gv(c.position));
    items.push_back({&sphere.gpu, nullptr, glm::scale(at, glm::vec3(0.015f)), look, nullptr, 0});
    const glm::mat4 along = at * alongZ(gv(c.normal)) * glm::translate(glm::mat4(1.0f), {0, 0, 0.1f}) *
                            glm::scale(glm::mat4(1.0f), glm::vec3(0.004f, 0.004f, 0.2f));
    items.push_back({&cylinder.gpu, nullptr, along, look, nullptr, 0});
  }

  /// Sensor `n`'s ray, `length` m along its +x.
  void ray(const Node& n, const glm::mat4& at, float length, const Look& look, std::vector<Item>& items,
           glm::vec3 direction = {1, 0, 0}) {
    // along `direction` (+x) from the sensor's origin: a thin cylinder turned from z to it
    const glm::mat4 m = at * alongZ(direction) * glm::translate(glm::mat4(1.0f), {0, 0, length / 2}) *
                        glm::scale(glm::mat4(1.0f), glm::vec3(0.005f, 0.005f, length));
    items.push_back({&cylinder.gpu, nullptr, m, look, &n, 0});
  }

  /// Camera sensor `n`'s view: its axis and the four edges of its picture, out to 1 m along
  /// the axis (or to `far` when nearer).
  void frustum(const Node& n, const glm::mat4& at, std::vector<Item>& items) {
    using F = field::ColorCamera;
    const Look look = overlay({0.2f, 0.6f, 1.0f}, 0.8f);
    const double reach = std::min(1.0, n.number(F::Far));
    const double x = std::tan(n.number(F::Fov) * std::numbers::pi / 360.0);
    const double y = x * n.number(F::Height) / n.number(F::Width);
    ray(n, at, static_cast<float>(reach), look, items);
    for (const double sy : {-1.0, 1.0}) {
      for (const double sz : {-1.0, 1.0}) {
        const glm::vec3 edge{1.0f, static_cast<float>(sy * x), static_cast<float>(sz * y)};
        ray(n, at, static_cast<float>(reach) * glm::length(edge), look, items, glm::normalize(edge));
      }
    }
  }

  /// LaserScan `n`'s rays at their full length, at most 36 of them evenly through the fan.
  void fan(const Node& n, const glm::mat4& at, std::vector<Item>& items) {
    using F = field::LaserScan;
    const Look look = overlay({1.0f, 0.2f, 0.2f}, 0.5f);
    const auto count = static_cast<std::int64_t>(n.number(F::Count));
    const double lo = n.number(F::MinAngle), hi = n.number(F::MaxAngle);
    // as the scan: a whole turn leaves out the repeated last ray
    const bool turn = hi - lo >= 360.0 - 1e-9;
    const double step = count < 2 ? 0.0 : (hi - lo) / static_cast<double>(turn ? count : count - 1);
    const std::int64_t every = std::max<std::int64_t>(1, (count + 35) / 36);
    const auto length = static_cast<float>(n.number(F::Length));
    for (std::int64_t i = 0; i < count; i += every) {
      const double a = (lo + step * static_cast<double>(i)) * std::numbers::pi / 180.0;
      ray(n, at, length, look, items, {static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0.0f});
    }
  }

  /// Sets the program's surface uniforms to `l`.
  void setLook(const Look& l) {
    glUniform3fv(u("u_ambient"), 1, glm::value_ptr(l.ambient));
    glUniform3fv(u("u_diffuse"), 1, glm::value_ptr(l.diffuse));
    glUniform3fv(u("u_specular"), 1, glm::value_ptr(l.specular));
    glUniform3fv(u("u_emissive"), 1, glm::value_ptr(l.emissive));
    glUniform1f(u("u_shininess"), l.shininess);
    glUniform1f(u("u_alpha"), l.alpha);
    glUniform1i(u("u_unlit"), l.unlit ? 1 : 0);
  }

  /// Sets the program's model-view and normal matrices for an item placed by `model`.
  void setModel(const glm::mat4& view, const glm::mat4& model) {
    const glm::mat4 mv = view * model;
    const glm::mat3 normal = glm::transpose(glm::inverse(glm::mat3(mv)));
    glUniformMatrix4fv(u("u_model_view"), 1, GL_FALSE, glm::value_ptr(mv));
    glUniformMatrix3fv(u("u_normal"), 1, GL_FALSE, glm::value_ptr(normal));
  }

  /// Where nothing opaque was drawn, the sky (`sky`: no fog hides it); then, when `height` is
  /// set (m), the ground grid on the level plane there, over the ground and under what stands
  /// on it. Leaves another program in use.
  void ground(const Camera& cam, const glm::mat4& view, const glm::mat4& proj, const DrawOptions& opt, bool with_sky,
              std::optional<double> height) {
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    if (with_sky && opt.sky) {
      use(sky);
      const glm::mat4 inverse = glm::inverse(proj * view);
      glUniformMatrix4fv(u("u_inverse"), 1, GL_FALSE, glm::value_ptr(inverse));
      glUniform3f(u("u_zenith"), 0.36f, 0.52f, 0.76f);
      glUniform3f(u("u_horizon"), 0.80f, 0.85f, 0.90f);
      glUniform3f(u("u_below"), 0.50f, 0.52f, 0.55f);
      glBindVertexArray(empty_vao);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    if (height && opt.grid) {
      use(grid);
      const glm::vec3 eye = gv(cam.eye);
      // the unit plane (a 2 km square) under the eye: the lines come from world positions
      const glm::mat4 model =
          glm::translate(glm::mat4(1.0f), glm::vec3(std::floor(eye.x), std::floor(eye.y), static_cast<float>(*height)));
      const float above = std::abs(eye.z - static_cast<float>(*height));
      glUniformMatrix4fv(u("u_model"), 1, GL_FALSE, glm::value_ptr(model));
      glUniformMatrix4fv(u("u_view_proj"), 1, GL_FALSE, glm::value_ptr(proj * view));
      glUniform3fv(u("u_eye"), 1, glm::value_ptr(eye));
      glUniform1f(u("u_fade"), std::min(950.0f, 40.0f + 20.0f * above));
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(-1.0f, -4.0f);  // over the ground plane it lies on
      glBindVertexArray(plane.vao);
      glDrawElements(GL_TRIANGLES, plane.count, GL_UNSIGNED_INT, nullptr);
      glDisable(GL_POLYGON_OFFSET_FILL);
      glDisable(GL_BLEND);
    }
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
  }

  /// Draws `it` (a terrain chunk by chunk, each at its level of detail), counting into `stats`.
  void drawItem(const Item& it, const glm::mat4& view, const glm::mat4& proj, const Camera& cam,
                const DrawOptions& opt, DrawStats& stats) {
    setModel(view, it.model);
    // a terrain's skirts hang below its edges and keep the surface's normals
    glUniform1i(u("u_two_sided"), it.terrain != nullptr ? 0 : 1);
    if (it.gpu != nullptr) {
      glBindVertexArray(it.gpu->vao);
      glDrawElements(GL_TRIANGLES, it.gpu->count, GL_UNSIGNED_INT, nullptr);
      stats.triangles += static_cast<std::size_t>(it.gpu->count) / 3;
      ++stats.draw_calls;
      return;
    }
    // terrain: each chunk in view at the coarsest level whose error stays under lod_error pixels
    const TerrainGpu& t = *it.terrain;
    glBindVertexArray(t.vao);
    const glm::mat4 clip = proj * view * it.model;
    const double pixels_per_radian = opt.height / (2.0 * std::tan(cam.fov * std::numbers::pi / 360.0));
    const glm::vec3 eye = glm::vec3(glm::inverse(it.model) * glm::vec4(gv(cam.eye), 1.0f));
    const glm::vec3 scale(glm::length(glm::vec3(it.model[0])), glm::length(glm::vec3(it.model[1])),
                          glm::length(glm::vec3(it.model[2])));
    for (std::size_t c = 0; c < t.chunks.size(); ++c) {
      const auto& ch = t.chunks[c];
      // outside the view when every corner is beyond one clipping plane
      bool outside = false;
      for (int side = 0; side < 6 && !outside; ++side) {
        bool all = true;
        for (int k = 0; k < 8 && all; ++k) {
          const glm::vec4 p = clip * glm::vec4((k & 1) ? ch.hi.x : ch.lo.x, (k & 2) ? ch.hi.y : ch.lo.y,
                                               (k & 4) ? ch.hi.z : ch.lo.z, 1.0f);
          const float w = p.w, v = p[side / 2];
          all = (side % 2 == 0) ? v < -w : v > w;
        }
        outside = all;
      }
      if (outside) continue;
      const glm::vec3 nearest = glm::clamp(eye, ch.lo, ch.hi);
      const float distance = std::max(1e-3f, glm::length((eye - nearest) * scale));
      int level = 0;
      for (int l = TerrainGpu::kLevels - 1; l > 0; --l) {
        if (static_cast<double>(ch.error[static_cast<std::size_t>(l)] * scale.z / distance) * pixels_per_radian <=
            opt.lod_error) {
          level = l;
          break;
        }
      }
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, t.ibo[static_cast<std::size_t>(level)]);
      glDrawElementsBaseVertex(GL_TRIANGLES, t.count[static_cast<std::size_t>(level)], GL_UNSIGNED_INT, nullptr,
                               static_cast<GLint>(c * TerrainGpu::kPerChunk));
      stats.triangles += static_cast<std::size_t>(t.count[static_cast<std::size_t>(level)]) / 3;
      ++stats.draw_calls;
    }
  }
};

Renderer::Renderer(std::string model_dir) : impl_(std::make_unique<Impl>(std::move(model_dir))) {}
Renderer::~Renderer() = default;

const std::vector<std::string>& Renderer::problems() const { return impl_->problems; }

DrawStats Renderer::draw(const scene::Scene& scene, const Camera& cam, const DrawOptions& opt) {
  Impl& r = *impl_;
  r.problems.clear();
  DrawStats stats;
  const Node& root = scene.root();
  // the looks of the whole scene first: lights and fog
  struct Light {
    int kind;
    glm::vec3 colour, pos, dir;
    float cos;
    glm::vec3 world_dir{0.0f};  // where it shines, world frame
  };
  std::vector<Light> lights;
  const Node* fog = nullptr;
  bool terrain = false;           // the scene has its own ground: no grid
  std::optional<double> ground;   // the height of the first level ground plane, m
  const glm::mat4 view = glm::lookAt(gv(cam.eye), gv(cam.target), gv(cam.up));
  const glm::mat4 proj = glm::perspective(static_cast<float>(cam.fov * std::numbers::pi / 180.0),
                                          static_cast<float>(opt.width) / static_cast<float>(std::max(1, opt.height)),
                                          static_cast<float>(cam.near), static_cast<float>(cam.far));
  std::vector<const Node*> todo{&root};
  while (!todo.empty()) {
    const Node* n = todo.back();
    todo.pop_back();
    if (n->is_template) continue;
    if (n->kind() == NodeKind::Light && lights.size() < static_cast<std::size_t>(kMaxLights)) {
      Light l;
      l.kind = shaderKind(n->choice<scene::LightKind>(field::Light::Kind));
      l.colour = gv(n->vec3(field::Light::Color)) * static_cast<float>(n->number(field::Light::Intensity));
      l.pos = glm::vec3(view * glm::vec4(gv(n->world.apply(n->vec3(field::Light::Location))), 1.0f));
      l.dir = glm::mat3(view) * gv(n->world.rotation.rotate(n->vec3(field::Light::Direction)));
      l.cos = static_cast<float>(std::cos(n->number(field::Light::Cutoff) * std::numbers::pi / 180.0));
      l.world_dir = gv(n->world.rotation.rotate(n->vec3(field::Light::Direction)));
      lights.push_back(l);
    }
    if (n->kind() == NodeKind::Fog && fog == nullptr) fog = n;
    if (n->kind() == NodeKind::Terrain) terrain = true;
    if (n->kind() == NodeKind::Plane && !ground) {
      const core::Vec3 up = n->world.rotation.rotate(n->vec3(field::Plane::Normal));
      if (up.z > 0.999 * std::sqrt(up.x * up.x + up.y * up.y + up.z * up.z)) ground = n->world.apply({0, 0, 0}).z;
    }
    for (auto it = n->children().rbegin(); it != n->children().rend(); ++it) todo.push_back(it->get());
  }
  if (lights.empty()) {
    // no light in the scene: a headlight, as viewers do
    lights.push_back({0, glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(0, 0, -1), 0.0f});
  }
  const glm::vec3 background = fog != nullptr ? gv(fog->vec3(field::Fog::Color)) : gv(opt.background);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);

  r.use(r.program);
  glUniformMatrix4fv(r.u("u_proj"), 1, GL_FALSE, glm::value_ptr(proj));
  glUniform1i(r.u("u_lights"), static_cast<GLint>(lights.size()));
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const std::string k = "[" + std::to_string(i) + "]";
    glUniform1i(r.u("u_kind" + k), lights[i].kind);
    glUniform3fv(r.u("u_lcolor" + k), 1, glm::value_ptr(lights[i].colour));
    glUniform3fv(r.u("u_lpos" + k), 1, glm::value_ptr(lights[i].pos));
    glUniform3fv(r.u("u_ldir" + k), 1, glm::value_ptr(lights[i].dir));
    glUniform1f(r.u("u_lcos" + k), lights[i].cos);
  }
  glUniform1i(r.u("u_fog"), fog == nullptr ? 0 : shaderKind(fog->choice<scene::FogKind>(field::Fog::Kind)));
  glUniform3fv(r.u("u_fog_color"), 1, glm::value_ptr(background));
  glUniform1f(r.u("u_fog_visibility"),
              fog != nullptr ? static_cast<float>(std::max(1e-6, fog->number(field::Fog::Visibility))) : 1.0f);

  std::vector<Item> items;
  r.collect(root, nullptr, opt, items);
  // shadows of the first directional light: the scene drawn from it into a depth map that
  // covers a square about the camera's target, as wide as the target is far from the eye
  int shadowing = -1;
  for (std::size_t i = 0; i < lights.size() && opt.shadows; ++i) {
    if (lights[i].kind == 0 && glm::length(lights[i].world_dir) > 0.0f) {
      shadowing = static_cast<int>(i);
      break;
    }
  }
  glUniform1i(r.u("u_shadow_light"), shadowing);
  glUniform1i(r.u("u_shadow_map"), 1);
  if (shadowing >= 0) {
    const glm::vec3 centre = gv(cam.target);
    const float reach = std::clamp(1.5f * glm::length(gv(cam.eye) - centre), 2.0f, 400.0f);
    const glm::vec3 dir = glm::normalize(lights[static_cast<std::size_t>(shadowing)].world_dir);
    const glm::vec3 up = std::abs(dir.z) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    const glm::mat4 light_view = glm::lookAt(centre - dir * (2.0f * reach), centre, up);
    const glm::mat4 light_proj = glm::ortho(-reach, reach, -reach, reach, 0.0f, 4.0f * reach);
    GLint framebuffer = 0, viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    r.shadow.ensure();
    glBindFramebuffer(GL_FRAMEBUFFER, r.shadow.fbo);
    glViewport(0, 0, ShadowMap::kSize, ShadowMap::kSize);
    glClear(GL_DEPTH_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);  // against shadow acne: surfaces do not shadow themselves
    r.use(r.depth);
    glUniformMatrix4fv(r.u("u_proj"), 1, GL_FALSE, glm::value_ptr(light_proj));
    DrawStats depth_pass;
    for (const auto& it : items) {
      // planes bound the world below: they take shadows and cast none worth a full-map fill
      // markings lying on a surface neither
      const bool plane = it.node != nullptr && it.node->kind() == NodeKind::Plane;
      if (it.look.alpha >= 1.0f && !it.look.unlit && !plane && !it.decal) {
        r.drawItem(it, light_view, light_proj, cam, opt, depth_pass);
      }
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    r.use(r.program);
    // view space -> light clip space -> the map's [0, 1] cube
    const glm::mat4 bias = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    const glm::mat4 to_map = bias * light_proj * light_view * glm::inverse(view);
    glUniformMatrix4fv(r.u("u_shadow"), 1, GL_FALSE, glm::value_ptr(to_map));
    // two texels along the normal: the 3 x 3 samples of a sloped surface stay in front of it
    glUniform1f(r.u("u_shadow_offset"), 2.0f * (2.0f * reach / static_cast<float>(ShadowMap::kSize)));
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, r.shadow.texture);
    glActiveTexture(GL_TEXTURE0);
  }
  // opaque first, from the nearest to the farthest so that hidden pixels fail the depth test
  // before they are shaded, planes and terrains (which fill the screen behind everything) last;
  // then the transparent ones from the farthest to the nearest, not writing depth
  std::vector<Item*> solid, clear;
  for (auto& it : items) {
    it.depth = -(view * it.model * glm::vec4(0, 0, 0, 1)).z;
    (it.look.alpha < 1.0f ? clear : solid).push_back(&it);
  }
  const auto behind = [](const Item* it) {
    return it->terrain != nullptr || (it->node != nullptr && it->node->kind() == NodeKind::Plane);
  };
  std::stable_sort(solid.begin(), solid.end(), [&](const Item* a, const Item* b) {
    const bool ba = behind(a), bb = behind(b);
    return ba != bb ? bb : a->depth < b->depth;
  });
  for (const Item* it : solid) {
    r.setLook(it->look);
    // a decal over the surface it lies on
    if (it->decal) {
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(-1.0f, -4.0f);
    }
    r.drawItem(*it, view, proj, cam, opt, stats);
    if (it->decal) glDisable(GL_POLYGON_OFFSET_FILL);
  }
  r.ground(cam, view, proj, opt, fog == nullptr, terrain ? std::nullopt : ground.has_value() ? ground : 0.0);
  r.use(r.program);
  std::stable_sort(clear.begin(), clear.end(), [](const Item* a, const Item* b) { return a->depth > b->depth; });
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  // a closed shape: its far side first, then its near side
  glEnable(GL_CULL_FACE);
  for (const Item* it : clear) {
    r.setLook(it->look);
    glCullFace(GL_FRONT);
    r.drawItem(*it, view, proj, cam, opt, stats);
    glCullFace(GL_BACK);
    r.drawItem(*it, view, proj, cam, opt, stats);
  }
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);

  // the selection: its shapes outlined over everything else drawn
  std::vector<const Node*> selected;
  for (const auto h : opt.selection) {
    if (const Node* n = scene.resolve(h)) selected.push_back(n);
  }
  if (!selected.empty()) {
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(-1.0f, -1.0f);
    r.setLook(overlay({1.0f, 0.55f, 0.0f}, 1.0f));
    for (const auto& it : items) {
      for (const Node* p = it.node; p != nullptr; p = p->parent()) {
        if (std::find(selected.begin(), selected.end(), p) == selected.end()) continue;
        r.drawItem(it, view, proj, cam, opt, stats);
        break;
      }
    }
    glDisable(GL_POLYGON_OFFSET_LINE);
    glDepthFunc(GL_LESS);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
  // contact points last, seen through what hides them (most lie under the bodies they hold)
  if (!opt.contacts.empty()) {
    std::vector<Item> marks;
    for (const auto& c : opt.contacts) r.contact(c, marks);
    glDisable(GL_DEPTH_TEST);
    for (const auto& it : marks) {
      r.setLook(it.look);
      r.drawItem(it, view, proj, cam, opt, stats);
    }
    glEnable(GL_DEPTH_TEST);
  }
  glBindVertexArray(0);
  return stats;
}

}  // namespace gdpn::render
