#include "gdpn/render/renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gdpn/scene/actions.h"
#include "gdpn/scene/mesh.h"
#include "gdpn/scene/terrain.h"
#include "gdpn/scene/types.h"

namespace gdpn::render {

using core::Vec3;
using scene::Node;
using scene::NodeKind;
namespace field = scene::field;

namespace {

constexpr int kMaxLights = 8;

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_model_view;
uniform mat4 u_proj;
uniform mat3 u_normal;
out vec3 v_pos;
out vec3 v_normal;
void main() {
  vec4 p = u_model_view * vec4(a_pos, 1.0);
  v_pos = p.xyz;
  v_normal = u_normal * a_normal;
  gl_Position = u_proj * p;
}
)";

const char* kFragment = R"(#version 330 core
in vec3 v_pos;
in vec3 v_normal;
out vec4 o_color;
uniform vec3 u_ambient, u_diffuse, u_specular, u_emissive;
uniform float u_shininess, u_alpha;
uniform int u_unlit;
uniform int u_two_sided;    // light the back of a face as its front
uniform int u_lights;
uniform int u_kind[8];      // 0 directional, 1 point, 2 spot
uniform vec3 u_lcolor[8];   // colour times intensity
uniform vec3 u_lpos[8];     // view space
uniform vec3 u_ldir[8];     // view space, where it shines
uniform float u_lcos[8];    // cosine of a spot's half-angle
uniform int u_fog;          // 0 none, 1 linear, 2 exponential
uniform vec3 u_fog_color;
uniform float u_fog_visibility;
void main() {
  vec3 c = u_emissive;
  if (u_unlit == 0) {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing && u_two_sided != 0) n = -n;
    vec3 v = normalize(-v_pos);
    c += 0.25 * u_ambient;
    float exponent = max(1.0, 128.0 * u_shininess);
    for (int i = 0; i < u_lights; ++i) {
      vec3 l;
      float k = 1.0;
      if (u_kind[i] == 0) {
        l = normalize(-u_ldir[i]);
      } else {
        l = normalize(u_lpos[i] - v_pos);
        if (u_kind[i] == 2) {
          float s = dot(-l, normalize(u_ldir[i]));
          k = smoothstep(u_lcos[i], u_lcos[i] + 0.02, s);
        }
      }
      float nl = max(dot(n, l), 0.0);
      vec3 h = normalize(l + v);
      float spec = nl > 0.0 ? pow(max(dot(n, h), 0.0), exponent) : 0.0;
      c += k * u_lcolor[i] * (u_diffuse * nl + u_specular * spec);
    }
  }
  if (u_fog != 0) {
    float d = length(v_pos);
    float f = u_fog == 1 ? clamp(1.0 - d / u_fog_visibility, 0.0, 1.0) : exp(-4.605 * d / u_fog_visibility);
    c = mix(u_fog_color, c, f);
  }
  o_color = vec4(clamp(c, 0.0, 1.0), u_alpha);
}
)";

GLuint compile(GLenum kind, const char* text) {
  const GLuint s = glCreateShader(kind);
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  return s;
}

glm::vec3 gv(Vec3 v) { return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)}; }
glm::vec3 gv(const std::array<double, 3>& v) { return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])}; }

/// Vertices (position, normal) and triangles on the GPU.
struct Gpu {
  GLuint vao = 0, vbo = 0, ibo = 0;
  GLsizei count = 0;  // indices
  void upload(const std::vector<float>& interleaved, const std::vector<std::uint32_t>& indices) {
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)), interleaved.data(),
                 GL_STATIC_DRAW);
    glGenBuffers(1, &ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                 indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glBindVertexArray(0);
    count = static_cast<GLsizei>(indices.size());
  }
  void release() {
    if (vao != 0) glDeleteVertexArrays(1, &vao);
    if (vbo != 0) glDeleteBuffers(1, &vbo);
    if (ibo != 0) glDeleteBuffers(1, &ibo);
    vao = vbo = ibo = 0;
  }
};

/// A mesh of one size and that size: what primitive shapes are drawn from, stretched to each
/// node's extent.
struct UnitShape {
  Gpu gpu;
  Vec3 extent;  // the mesh's size along x, y, z
  /// `at` scaled so that the mesh takes up `size` (m along x, y, z, as scene::shapeExtent gives it).
  [[nodiscard]] glm::mat4 fit(const glm::mat4& at, Vec3 size) const {
    return glm::scale(at, gv(Vec3{size.x / extent.x, size.y / extent.y, size.z / extent.z}));
  }
};

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

/// A cube of edge 1.
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
  Gpu g;
  g.upload(b.v, b.i);
  return {g, {1, 1, 1}};
}

/// A sphere of radius 1.
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
  Gpu g;
  g.upload(b.v, b.i);
  return {g, {2, 2, 2}};
}

/// A cylinder (top radius 1) or cone (top radius 0) of radius 1 and height 1 along z.
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
  Gpu g;
  g.upload(b.v, b.i);
  return {g, {2, 2, 1}};
}

Gpu unitPlane() {
  // "endless" ground: a 2 km square
  ShapeBuilder b;
  const glm::vec3 n(0, 0, 1);
  b.quad(b.vertex({-1000, -1000, 0}, n), b.vertex({1000, -1000, 0}, n), b.vertex({1000, 1000, 0}, n),
         b.vertex({-1000, 1000, 0}, n));
  Gpu g;
  g.upload(b.v, b.i);
  return g;
}

/// How a shape looks: a Material node's values (or the file's, or the defaults).
struct Look {
  glm::vec3 ambient{0.2f}, diffuse{0.8f}, specular{0.0f}, emissive{0.0f};
  float shininess = 0.2f, alpha = 1.0f;
  bool unlit = false;
};

Look lookOf(const Node* m) {
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

/// A terrain on the GPU: chunks of 64 x 64 cells sharing one vertex buffer, an index buffer
/// per level of detail (every 2^l-th vertex) with skirts that hide the cracks between levels.
struct TerrainGpu {
  static constexpr int kCells = 64;
  static constexpr int kSide = kCells + 1;
  static constexpr int kLevels = 7;  // steps 1, 2, ..., 64
  static constexpr int kPerChunk = kSide * kSide + 4 * kSide;
  struct Chunk {
    glm::vec3 lo, hi;                       // bounding box in the terrain's frame
    std::array<float, kLevels> error{};     // the most a level moves a vertex, m
  };
  GLuint vao = 0, vbo = 0;
  std::array<GLuint, kLevels> ibo{};
  std::array<GLsizei, kLevels> count{};
  std::vector<Chunk> chunks;
  int cx = 0, cy = 0;
  float cell = 1.0f;

  bool build(const scene::HeightGrid& grid, double width, double depth, double hscale) {
    const int nx = grid.nx, ny = grid.ny;
    if (nx < 2 || ny < 2) return false;
    cx = (nx - 2) / kCells + 1;
    cy = (ny - 2) / kCells + 1;
    const double sx = width / (nx - 1), sy = depth / (ny - 1);
    cell = static_cast<float>(std::max(sx, sy));
    auto H = [&](int i, int j) {
      i = std::clamp(i, 0, nx - 1);
      j = std::clamp(j, 0, ny - 1);
      return grid.height[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)] * hscale;
    };
    auto P = [&](int i, int j) {
      return glm::vec3(static_cast<float>(-width / 2 + std::min(i, nx - 1) * sx),
                       static_cast<float>(depth / 2 - std::min(j, ny - 1) * sy), static_cast<float>(H(i, j)));
    };
    auto N = [&](int i, int j) {
      const double dx = (H(i + 1, j) - H(i - 1, j)) / (2 * sx), dy = (H(i, j - 1) - H(i, j + 1)) / (2 * sy);
      return glm::normalize(glm::vec3(static_cast<float>(-dx), static_cast<float>(-dy), 1.0f));
    };
    std::vector<float> v;
    v.reserve(static_cast<std::size_t>(cx * cy) * kPerChunk * 6);
    for (int by = 0; by < cy; ++by) {
      for (int bx = 0; bx < cx; ++bx) {
        Chunk c;
        c.lo = glm::vec3(1e30f);
        c.hi = glm::vec3(-1e30f);
        const int i0 = bx * kCells, j0 = by * kCells;
        for (int j = 0; j < kSide; ++j) {
          for (int i = 0; i < kSide; ++i) {
            const glm::vec3 p = P(i0 + i, j0 + j), n = N(i0 + i, j0 + j);
            v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
            c.lo = glm::min(c.lo, p);
            c.hi = glm::max(c.hi, p);
          }
        }
        const float skirt = (c.hi.z - c.lo.z) * 0.1f + cell;
        for (int e = 0; e < 4; ++e) {
          for (int k = 0; k < kSide; ++k) {
            const int i = e == 0 ? k : e == 1 ? k : e == 2 ? 0 : kCells;
            const int j = e == 0 ? 0 : e == 1 ? kCells : k;
            glm::vec3 p = P(i0 + i, j0 + j);
            p.z -= skirt;
            const glm::vec3 n = N(i0 + i, j0 + j);
            v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
          }
        }
        c.lo.z -= skirt;
        // each level's error: the largest height difference between a dropped vertex and
        // the level's (bilinear) surface over it
        for (int l = 1; l < kLevels; ++l) {
          const int s = 1 << l;
          float worst = 0;
          for (int j = 0; j < kSide; ++j) {
            for (int i = 0; i < kSide; ++i) {
              if (i % s == 0 && j % s == 0) continue;
              const int a = (i / s) * s, b = (j / s) * s;
              const int a1 = std::min(a + s, kCells), b1 = std::min(b + s, kCells);
              const double fx = a1 > a ? static_cast<double>(i - a) / (a1 - a) : 0.0;
              const double fy = b1 > b ? static_cast<double>(j - b) / (b1 - b) : 0.0;
              const double h = (1 - fx) * (1 - fy) * H(i0 + a, j0 + b) + fx * (1 - fy) * H(i0 + a1, j0 + b) +
                               (1 - fx) * fy * H(i0 + a, j0 + b1) + fx * fy * H(i0 + a1, j0 + b1);
              worst = std::max(worst, static_cast<float>(std::abs(h - H(i0 + i, j0 + j))));
            }
          }
          c.error[static_cast<std::size_t>(l)] = std::max(worst, c.error[static_cast<std::size_t>(l - 1)]);
        }
        chunks.push_back(c);
      }
    }
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    for (int l = 0; l < kLevels; ++l) {
      const int s = 1 << l;
      std::vector<std::uint32_t> idx;
      auto at = [](int i, int j) { return static_cast<std::uint32_t>(j * kSide + i); };
      auto skirtAt = [](int e, int k) { return static_cast<std::uint32_t>(kSide * kSide + e * kSide + k); };
      for (int j = 0; j < kCells; j += s) {
        for (int i = 0; i < kCells; i += s) {
          idx.insert(idx.end(), {at(i, j + s), at(i + s, j + s), at(i + s, j), at(i, j + s), at(i + s, j), at(i, j)});
        }
      }
      for (int k = 0; k < kCells; k += s) {
        // north (j = 0), south (j = kCells), west (i = 0), east (i = kCells): both windings,
        // a skirt is seen from either side
        const std::array<std::pair<std::uint32_t, std::uint32_t>, 4> top = {
            std::pair{at(k, 0), at(k + s, 0)}, std::pair{at(k, kCells), at(k + s, kCells)},
            std::pair{at(0, k), at(0, k + s)}, std::pair{at(kCells, k), at(kCells, k + s)}};
        for (int e = 0; e < 4; ++e) {
          const auto [a, b] = top[static_cast<std::size_t>(e)];
          const auto c = skirtAt(e, k + s), d = skirtAt(e, k);
          idx.insert(idx.end(), {a, b, c, a, c, d, a, c, b, a, d, c});
        }
      }
      glGenBuffers(1, &ibo[static_cast<std::size_t>(l)]);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo[static_cast<std::size_t>(l)]);
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * sizeof(std::uint32_t)), idx.data(),
                   GL_STATIC_DRAW);
      count[static_cast<std::size_t>(l)] = static_cast<GLsizei>(idx.size());
    }
    glBindVertexArray(0);
    return true;
  }
  void release() {
    if (vao != 0) glDeleteVertexArrays(1, &vao);
    if (vbo != 0) glDeleteBuffers(1, &vbo);
    for (auto b : ibo) {
      if (b != 0) glDeleteBuffers(1, &b);
    }
  }
};

/// One thing to draw.
struct Item {
  const Gpu* gpu = nullptr;
  const TerrainGpu* terrain = nullptr;
  glm::mat4 model{1.0f};
  Look look;
  const Node* node = nullptr;
  float depth = 0;  // view-space distance, for sorting transparent items
};

glm::mat4 placement(const core::Pose& pose, Vec3 scale) {
  const glm::mat4 t = glm::translate(glm::mat4(1.0f), gv(pose.position));
  const auto& q = pose.rotation;
  const double angle = 2 * std::acos(std::clamp(q.w, -1.0, 1.0));
  const double s = std::sqrt(std::max(0.0, 1 - q.w * q.w));
  glm::mat4 r(1.0f);
  if (s > 1e-12) r = glm::rotate(glm::mat4(1.0f), static_cast<float>(angle), glm::vec3(q.x / s, q.y / s, q.z / s));
  return glm::scale(t * r, gv(scale));
}

/// A rotation taking +z to `dir`.
glm::mat4 alongZ(glm::vec3 dir) {
  dir = glm::normalize(dir);
  const glm::vec3 z(0, 0, 1);
  const float c = glm::dot(z, dir);
  if (c > 0.9999f) return glm::mat4(1.0f);
  if (c < -0.9999f) return glm::rotate(glm::mat4(1.0f), static_cast<float>(std::numbers::pi), glm::vec3(1, 0, 0));
  return glm::rotate(glm::mat4(1.0f), std::acos(c), glm::normalize(glm::cross(z, dir)));
}

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

struct Renderer::Impl {
  std::string dir;
  GLuint program = 0;
  std::map<std::string, GLint> uniforms;
  UnitShape cube, sphere, cylinder, cone;
  Gpu plane;
  struct MeshGpu {
    std::vector<Gpu> parts;
    std::vector<int> materials;
    std::shared_ptr<const scene::MeshData> data;
  };
  std::map<std::string, MeshGpu> meshes;  // by path
  std::map<std::string, TerrainGpu> terrains;  // by path and size
  std::set<std::string> failed;
  std::vector<std::string> problems;

  GLint u(const std::string& name) {
    auto it = uniforms.find(name);
    if (it == uniforms.end()) it = uniforms.emplace(name, glGetUniformLocation(program, name.c_str())).first;
    return it->second;
  }

  Impl() {
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertex), fs = compile(GL_FRAGMENT_SHADER, kFragment);
    program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    cube = unitCube();
    sphere = unitSphere();
    cylinder = unitRound(false);
    cone = unitRound(true);
    plane = unitPlane();
  }
  ~Impl() {
    for (Gpu* g : {&cube.gpu, &sphere.gpu, &cylinder.gpu, &cone.gpu, &plane}) g->release();
    for (auto& [k, m] : meshes) {
      for (auto& p : m.parts) p.release();
    }
    for (auto& [k, t] : terrains) t.release();
    glDeleteProgram(program);
  }

  void problem(const std::string& key, const std::string& text) {
    if (failed.insert(key).second) problems.push_back(text);
  }

  const MeshGpu* mesh(const Node& n) {
    const std::string file = n.text(field::Mesh::File);
    const std::string path = (std::filesystem::path(dir) / file).string();
    if (auto it = meshes.find(path); it != meshes.end()) return &it->second;
    if (failed.count(path) != 0) return nullptr;
    std::string why;
    auto data = file.empty() ? nullptr : scene::loadMesh(path, why);
    if (!data) {
      problem(path, "cannot read the mesh file '" + file + "': " + why);
      return nullptr;
    }
    MeshGpu m;
    m.data = data;
    for (const auto& part : data->parts) {
      std::vector<float> v;
      for (std::size_t k = 0; k + 2 < part.positions.size(); k += 3) {
        v.insert(v.end(), {part.positions[k], part.positions[k + 1], part.positions[k + 2], part.normals[k],
                           part.normals[k + 1], part.normals[k + 2]});
      }
      Gpu g;
      g.upload(v, part.indices);
      m.parts.push_back(g);
      m.materials.push_back(part.material);
    }
    return &(meshes[path] = std::move(m));
  }

  const TerrainGpu* terrain(const Node& n) {
    const std::string file = n.text(field::Terrain::File);
    const std::string path = (std::filesystem::path(dir) / file).string();
    const double width = n.number(field::Terrain::Width), depth = n.number(field::Terrain::Depth),
                 height_scale = n.number(field::Terrain::HeightScale);
    const std::string key =
        path + "|" + std::to_string(width) + "|" + std::to_string(depth) + "|" + std::to_string(height_scale);
    if (auto it = terrains.find(key); it != terrains.end()) return &it->second;
    if (failed.count(key) != 0) return nullptr;
    std::string why;
    auto grid = scene::loadHeightGrid(path, why);
    TerrainGpu t;
    if (!grid || !t.build(*grid, width, depth, height_scale)) {
      problem(key, "cannot read the elevation file '" + file + "': " + (grid ? "too few samples" : why));
      return nullptr;
    }
    return &(terrains[key] = t);
  }

  /// Collects what to draw below `n`, with `material` in effect.
  void collect(const Node& n, const Node* material, const DrawOptions& opt, std::vector<Item>& items) {
    const glm::mat4 at = placement(n.world, n.world_scale);
    auto add = [&](const Gpu& g, glm::mat4 model, Look look) { items.push_back({&g, nullptr, model, look, &n, 0}); };
    // a primitive: its unit mesh stretched to the node's extent
    auto primitive = [&](const UnitShape& shape, Look look) { add(shape.gpu, shape.fit(at, scene::shapeExtent(n)), look); };
    switch (n.kind()) {
      case NodeKind::Cube: primitive(cube, lookOf(material)); break;
      case NodeKind::Sphere: primitive(sphere, lookOf(material)); break;
      case NodeKind::Cylinder: primitive(cylinder, lookOf(material)); break;
      case NodeKind::Cone: primitive(cone, lookOf(material)); break;
      case NodeKind::Plane: add(plane, at * alongZ(gv(n.vec3(field::Plane::Normal))), lookOf(material)); break;
      case NodeKind::Mesh:
        if (const MeshGpu* m = mesh(n)) {
          const auto part = static_cast<long>(n.number(field::Mesh::Part));
          for (std::size_t i = 0; i < m->parts.size(); ++i) {
            if (part >= 0 && static_cast<std::size_t>(part) != i) continue;
            // a Material in the scene wins; otherwise the file's own
            Look look = lookOf(material);
            const int mi = m->materials[i];
            if (material == nullptr && mi >= 0 && static_cast<std::size_t>(mi) < m->data->materials.size()) {
              look = lookOf(m->data->materials[static_cast<std::size_t>(mi)]);
            }
            add(m->parts[i], glm::scale(at, gv(n.vec3(field::Mesh::Scale))), look);
          }
        }
        break;
      case NodeKind::Terrain:
        if (const TerrainGpu* g = terrain(n)) items.push_back({nullptr, g, at, lookOf(material), &n, 0});
        break;
      case NodeKind::Region:
        if (!opt.sensors) break;
        {
          const Look look = overlay({1.0f, 0.85f, 0.1f}, 0.3f);
          switch (n.choice<scene::RegionShape>(field::Region::Shape)) {
            case scene::RegionShape::Box: primitive(cube, look); break;
            case scene::RegionShape::Sphere: primitive(sphere, look); break;
            case scene::RegionShape::Cylinder: primitive(cylinder, look); break;
            case scene::RegionShape::Cone: primitive(cone, look); break;
            case scene::RegionShape::Ray: ray(at, static_cast<float>(n.number(field::Region::Length)), look, n, items); break;
          }
        }
        break;
      case NodeKind::RangeFinder:
        if (opt.sensors) {
          ray(at, static_cast<float>(n.number(field::RangeFinder::Length)), overlay({1.0f, 0.2f, 0.2f}, 0.8f), n, items);
        }
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
      case NodeKind::Conveyor:
      case NodeKind::GradientField:
      case NodeKind::GradientSensor:
      case NodeKind::KeyboardSensor:
      case NodeKind::MouseSensor:
      case NodeKind::TimeSensor: break;
    }
    const Node* inner = material;
    for (const auto& child : n.children()) {
      if (child->kind() == NodeKind::Material) inner = child.get();
      collect(*child, inner, opt, items);
    }
  }

  /// A joint's axes (as many as its kind has) and its anchor.
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
    items.push_back({&sphere.gpu, nullptr, glm::scale(anchor, glm::vec3(0.03f)), overlay({0.1f, 0.9f, 0.3f}, 1.0f), &n, 0});
  }

  void ray(const glm::mat4& at, float length, const Look& look, const Node& n, std::vector<Item>& items) {
    // along +x from the sensor's origin: a thin cylinder turned from z to x
    const glm::mat4 m = at * alongZ({1, 0, 0}) * glm::translate(glm::mat4(1.0f), {0, 0, length / 2}) *
                        glm::scale(glm::mat4(1.0f), glm::vec3(0.005f, 0.005f, length));
    items.push_back({&cylinder.gpu, nullptr, m, look, &n, 0});
  }

  void setLook(const Look& l) {
    glUniform3fv(u("u_ambient"), 1, glm::value_ptr(l.ambient));
    glUniform3fv(u("u_diffuse"), 1, glm::value_ptr(l.diffuse));
    glUniform3fv(u("u_specular"), 1, glm::value_ptr(l.specular));
    glUniform3fv(u("u_emissive"), 1, glm::value_ptr(l.emissive));
    glUniform1f(u("u_shininess"), l.shininess);
    glUniform1f(u("u_alpha"), l.alpha);
    glUniform1i(u("u_unlit"), l.unlit ? 1 : 0);
  }

  void setModel(const glm::mat4& view, const glm::mat4& model) {
    const glm::mat4 mv = view * model;
    const glm::mat3 normal = glm::transpose(glm::inverse(glm::mat3(mv)));
    glUniformMatrix4fv(u("u_model_view"), 1, GL_FALSE, glm::value_ptr(mv));
    glUniformMatrix3fv(u("u_normal"), 1, GL_FALSE, glm::value_ptr(normal));
  }

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

Renderer::Renderer(std::string model_dir) : impl_(std::make_unique<Impl>()) { impl_->dir = std::move(model_dir); }
Renderer::~Renderer() = default;

const std::vector<std::string>& Renderer::problems() const { return impl_->problems; }

DrawStats Renderer::draw(const scene::Scene& scene, const Camera& cam, const DrawOptions& opt) {
  Impl& r = *impl_;
  DrawStats stats;
  const Node& root = scene.root();
  // the looks of the whole scene first: lights and fog
  struct Light {
    int kind;
    glm::vec3 colour, pos, dir;
    float cos;
  };
  std::vector<Light> lights;
  const Node* fog = nullptr;
  const glm::mat4 view = glm::lookAt(gv(cam.eye), gv(cam.target), gv(cam.up));
  const glm::mat4 proj = glm::perspective(static_cast<float>(cam.fov * std::numbers::pi / 180.0),
                                          static_cast<float>(opt.width) / static_cast<float>(std::max(1, opt.height)),
                                          static_cast<float>(cam.near), static_cast<float>(cam.far));
  std::vector<const Node*> todo{&root};
  while (!todo.empty()) {
    const Node* n = todo.back();
    todo.pop_back();
    if (n->kind() == NodeKind::Light && lights.size() < static_cast<std::size_t>(kMaxLights)) {
      Light l;
      l.kind = shaderKind(n->choice<scene::LightKind>(field::Light::Kind));
      l.colour = gv(n->vec3(field::Light::Color)) * static_cast<float>(n->number(field::Light::Intensity));
      l.pos = glm::vec3(view * glm::vec4(gv(n->world.apply(n->vec3(field::Light::Location))), 1.0f));
      l.dir = glm::mat3(view) * gv(n->world.rotation.rotate(n->vec3(field::Light::Direction)));
      l.cos = static_cast<float>(std::cos(n->number(field::Light::Cutoff) * std::numbers::pi / 180.0));
      lights.push_back(l);
    }
    if (n->kind() == NodeKind::Fog && fog == nullptr) fog = n;
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

  glUseProgram(r.program);
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
  // opaque first, then the transparent ones from the farthest to the nearest, not writing depth
  std::vector<Item*> clear;
  for (auto& it : items) {
    if (it.look.alpha < 1.0f) {
      it.depth = -(view * it.model * glm::vec4(0, 0, 0, 1)).z;
      clear.push_back(&it);
      continue;
    }
    r.setLook(it.look);
    r.drawItem(it, view, proj, cam, opt, stats);
  }
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
  if (opt.selection != 0) {
    if (const Node* sel = scene.resolve(opt.selection)) {
      glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
      glDepthFunc(GL_LEQUAL);
      glEnable(GL_POLYGON_OFFSET_LINE);
      glPolygonOffset(-1.0f, -1.0f);
      r.setLook(overlay({1.0f, 0.55f, 0.0f}, 1.0f));
      for (const auto& it : items) {
        for (const Node* p = it.node; p != nullptr; p = p->parent()) {
          if (p != sel) continue;
          r.drawItem(it, view, proj, cam, opt, stats);
          break;
        }
      }
      glDisable(GL_POLYGON_OFFSET_LINE);
      glDepthFunc(GL_LESS);
      glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    }
  }
  glBindVertexArray(0);
  return stats;
}

Camera cameraOf(const Node& camera, double t) {
  Camera c;
  c.eye = camera.world.apply(camera.vec3(field::Camera::Position));
  c.target = camera.world.apply(camera.vec3(field::Camera::Target));
  c.up = camera.world.rotation.rotate(camera.vec3(field::Camera::Up));
  c.fov = camera.number(field::Camera::Fov);
  if (camera.choice<scene::CameraKind>(field::Camera::Kind) == scene::CameraKind::Orbit) {
    const double angle = camera.number(field::Camera::Speed) * t * std::numbers::pi / 180.0;
    c.eye = c.target + core::Quat::axisAngle(c.up.normalized(), angle).rotate(c.eye - c.target);
  }
  const double distance = (c.eye - c.target).length();
  c.far = std::max(2000.0, distance * 10);
  return c;
}

Camera framing(const scene::Scene& scene) {
  const core::Aabb box = scene::boundingBox(scene.root());
  Camera c;
  if (box.empty()) return c;
  const Vec3 centre = (box.lo + box.hi) * 0.5;
  const double radius = std::max(0.5, (box.hi - box.lo).length() * 0.5);
  const double distance = radius / std::sin(c.fov * std::numbers::pi / 360.0);
  c.target = centre;
  c.eye = centre + Vec3{0.6, -0.7, 0.45}.normalized() * distance;
  c.far = std::max(2000.0, distance * 10);
  return c;
}

Camera chooseCamera(const scene::Scene& scene, const std::string& path, double t, std::string& error) {
  error.clear();
  if (!path.empty()) {
    const Node* n = scene.find(path);
    if (n == nullptr || n->kind() != NodeKind::Camera) {
      error = "no Camera node at '" + path + "'";
      return framing(scene);
    }
    return cameraOf(*n, t);
  }
  std::vector<const Node*> todo{&scene.root()};
  while (!todo.empty()) {
    const Node* n = todo.back();
    todo.pop_back();
    if (n->kind() == NodeKind::Camera) return cameraOf(*n, t);
    for (auto it = n->children().rbegin(); it != n->children().rend(); ++it) todo.push_back(it->get());
  }
  return framing(scene);
}

}  // namespace gdpn::render
