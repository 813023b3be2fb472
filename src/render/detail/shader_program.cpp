#include "shader_program.h"

namespace gdpn::render::detail {

namespace {

constexpr const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_model_view;
uniform mat4 u_proj;
uniform mat3 u_normal;
uniform mat4 u_shadow;      // view space to the shadow map's [0, 1] cube
uniform float u_shadow_offset;  // m along the normal: a surface does not shadow itself
out vec3 v_pos;
out vec3 v_normal;
out vec4 v_shadow;
void main() {
  vec4 p = u_model_view * vec4(a_pos, 1.0);
  v_pos = p.xyz;
  v_normal = u_normal * a_normal;
  float ln = length(v_normal);
  v_shadow = u_shadow * vec4(p.xyz + (ln > 0.0 ? v_normal / ln : vec3(0.0)) * u_shadow_offset, 1.0);
  gl_Position = u_proj * p;
}
)";

constexpr const char* kFragment = R"(#version 330 core
in vec3 v_pos;
in vec3 v_normal;
in vec4 v_shadow;
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
uniform int u_shadow_light;         // the light that casts shadows, -1 none
uniform sampler2DShadow u_shadow_map;
// how much of the shadowing light reaches this point: 0 in full shadow, 1 in full light
float lit() {
  vec3 s = v_shadow.xyz / v_shadow.w;
  if (s.x <= 0.0 || s.x >= 1.0 || s.y <= 0.0 || s.y >= 1.0 || s.z >= 1.0) return 1.0;
  return texture(u_shadow_map, s);  // linear filtering compares 2 x 2 texels: soft edges
}
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
      if (i == u_shadow_light) k *= lit();
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

constexpr const char* kDepthVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
uniform mat4 u_model_view;
uniform mat4 u_proj;
void main() { gl_Position = u_proj * (u_model_view * vec4(a_pos, 1.0)); }
)";

constexpr const char* kDepthFragment = R"(#version 330 core
void main() {}
)";

// the sky: a triangle covering the screen at the far plane, drawn after the opaque items where
// nothing is (depth test LEQUAL); each pixel's ray gives its elevation above the horizon
constexpr const char* kSkyVertex = R"(#version 330 core
uniform mat4 u_inverse;     // clip space to world space
out vec3 v_ray;
void main() {
  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  vec4 far = u_inverse * vec4(p, 1.0, 1.0);
  vec4 near = u_inverse * vec4(p, -1.0, 1.0);
  v_ray = far.xyz / far.w - near.xyz / near.w;
  gl_Position = vec4(p, 1.0, 1.0);
}
)";

constexpr const char* kSkyFragment = R"(#version 330 core
in vec3 v_ray;
out vec4 o_color;
uniform vec3 u_zenith, u_horizon, u_below;
void main() {
  float e = normalize(v_ray).z;  // sine of the elevation (z is up)
  vec3 c = e >= 0.0 ? mix(u_horizon, u_zenith, pow(clamp(e, 0.0, 1.0), 0.6))
                    : mix(u_horizon, u_below, clamp(-e * 6.0, 0.0, 1.0));
  o_color = vec4(c, 1.0);
}
)";

// the grid: lines every metre, stronger every ten, anti-aliased by their screen width and
// faded where they would crowd into a grey haze (and with distance)
constexpr const char* kGridVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
uniform mat4 u_model;       // the unit plane to the world
uniform mat4 u_view_proj;
out vec3 v_world;
void main() {
  vec4 w = u_model * vec4(a_pos, 1.0);
  v_world = w.xyz;
  gl_Position = u_view_proj * w;
}
)";

constexpr const char* kGridFragment = R"(#version 330 core
in vec3 v_world;
out vec4 o_color;
uniform vec3 u_eye;         // world frame, m
uniform float u_fade;       // m: the distance at which the grid is gone
float lines(vec2 p, float spacing) {
  vec2 q = p / spacing;
  vec2 w = fwidth(q);
  vec2 g = abs(fract(q - 0.5) - 0.5) / max(w, vec2(1e-6));
  float line = 1.0 - min(min(g.x, g.y), 1.0);
  // a line narrower than a pixel apart from the next turns to haze: fade it out
  return line * (1.0 - smoothstep(0.15, 0.5, max(w.x, w.y)));
}
void main() {
  float minor = lines(v_world.xy, 1.0), major = lines(v_world.xy, 10.0);
  float d = length(v_world - u_eye);
  float a = max(0.10 * minor, 0.30 * major) * (1.0 - smoothstep(0.3 * u_fade, u_fade, d));
  if (a <= 0.003) discard;
  o_color = vec4(vec3(0.12), a);
}
)";

GLuint compile(GLenum kind, const char* text) {
  const GLuint s = glCreateShader(kind);
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  return s;
}

}  // namespace

ShaderProgram::ShaderProgram(ProgramKind kind) {
  const char* vertex = kVertex;
  const char* fragment = kFragment;
  switch (kind) {
    case ProgramKind::surface: break;
    case ProgramKind::depth:
      vertex = kDepthVertex;
      fragment = kDepthFragment;
      break;
    case ProgramKind::sky:
      vertex = kSkyVertex;
      fragment = kSkyFragment;
      break;
    case ProgramKind::grid:
      vertex = kGridVertex;
      fragment = kGridFragment;
      break;
  }
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex), fs = compile(GL_FRAGMENT_SHADER, fragment);
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(id_); }

void ShaderProgram::use() const { glUseProgram(id_); }

GLint ShaderProgram::uniform(const std::string& name) {
  auto it = uniforms_.find(name);
  if (it == uniforms_.end()) it = uniforms_.emplace(name, glGetUniformLocation(id_, name.c_str())).first;
  return it->second;
}

}  // namespace gdpn::render::detail
