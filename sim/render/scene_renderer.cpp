#include "sim/render/scene_renderer.h"

#include "sim/render/link_mesh.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>


#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

// LeakSanitizer (DASHBED_SANITIZE builds): libOSMesa (Mesa 22) keeps about 200 bytes per
// context it ever made current after OSMesaDestroyContext; the amount does not grow with
// frames. This hook, which LSan reads at exit, limits the report to other code. It is defined
// here so that every program rendering gets it; unused without sanitizers.
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }

namespace dashbed::render {

namespace {

// ---- shaders (GLSL 3.30; Mesa's llvmpipe offers a 4.5 compatibility context) ----
//
// One source compiled in variants by prepending #defines; llvmpipe executes both sides of a
// branch on a uniform, so features are chosen at compile time:
//   PIXEL_LIGHTING  lighting per fragment (robot meshes: curved, small on screen); otherwise
//                   per vertex, which is exact for the diffuse light of flat faces (boxes,
//                   floor) under directional lights and much cheaper for large areas
//   SHADOWS         the key light is shadowed (shadow map; coordinates per vertex, exact for
//                   the orthographic light)
//   FLOOR           the floor: grid lines (GRID) and a fade into the background with distance
//   FLAT            unlit colour (region volumes and edges)
// Light model: ambient (a little more from the sky) + fill + key (Lambert) + Blinn-Phong
// highlight of the key light.

constexpr const char* kCommonShaderCode = R"(
uniform float u_specular;
uniform float u_shininess;
uniform vec3 u_eye_W;
uniform vec3 u_key_W;
uniform vec3 u_fill_W;

// light leaving a surface of colour `albedo`: rgb without the key light, rgb of the key light
void shade(vec3 albedo, vec3 p_W, vec3 n, out vec3 unkeyed, out vec3 keyed) {
  float key = max(dot(n, u_key_W), 0.0);
  float fill = max(dot(n, u_fill_W), 0.0);
  vec3 h = normalize(u_key_W + normalize(u_eye_W - p_W));
  float highlight = key > 0.0 ? u_specular * pow(max(dot(n, h), 0.0), u_shininess) : 0.0;
  unkeyed = albedo * (0.34 + 0.08 * n.z + 0.18 * fill);
  keyed = albedo * (0.54 * key) + vec3(highlight);
}
)";

constexpr const char* kVertexShaderBody = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;  // per vertex (robot links) or one value per draw
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_proj;
uniform mat4 u_light_view_proj;
uniform float u_shadow_offset;
out vec3 v_position_W;
out vec3 v_normal_W;
out vec3 v_unkeyed;
out vec3 v_keyed;
out vec3 v_shadow_coord;
out vec4 v_color;
void main() {
  vec4 p_W = u_model * vec4(a_position, 1.0);
  vec3 n = normalize(u_normal_matrix * a_normal);
  v_position_W = p_W.xyz;
  v_normal_W = n;
  v_color = a_color;
#if !defined(PIXEL_LIGHTING) && !defined(FLAT)
  shade(a_color.rgb, p_W.xyz, n, v_unkeyed, v_keyed);
#endif
#ifdef SHADOWS
  // offset along the normal by about a texel so that lit surfaces do not shadow themselves
  v_shadow_coord = (u_light_view_proj * vec4(p_W.xyz + n * u_shadow_offset, 1.0)).xyz * 0.5 + 0.5;
#endif
  gl_Position = u_view_proj * p_W;
}
)";

constexpr const char* kFragmentShaderBody = R"(
in vec3 v_position_W;
in vec3 v_normal_W;
in vec3 v_unkeyed;
in vec3 v_keyed;
in vec3 v_shadow_coord;
in vec4 v_color;
uniform sampler2DShadow u_shadow_map;
uniform float u_shadow_bias;
uniform vec3 u_background;
uniform vec2 u_floor_centre;
uniform vec2 u_floor_fade;
out vec4 frag_color;

void main() {
#ifdef FLAT
  frag_color = v_color;
#else
#ifdef PIXEL_LIGHTING
  vec3 unkeyed, keyed;
  shade(v_color.rgb, v_position_W, normalize(gl_FrontFacing ? v_normal_W : -v_normal_W), unkeyed, keyed);
#else
  vec3 unkeyed = v_unkeyed, keyed = v_keyed;
#endif
#ifdef SHADOWS
  // one bilinear depth comparison (2x2 PCF); beyond the far plane nothing casts a shadow
  float visibility = texture(u_shadow_map, vec3(v_shadow_coord.xy, min(v_shadow_coord.z - u_shadow_bias, 1.0)));
  vec3 color = unkeyed + keyed * visibility;
#else
  vec3 color = unkeyed + keyed;
#endif
#ifdef FLOOR
#ifdef GRID
  // anti-aliased lines about one pixel wide every 0.5 m, faded out where cells get tiny
  vec2 cell = v_position_W.xy * 2.0;
  vec2 w = max(fwidth(cell), vec2(1e-6));
  vec2 d = abs(fract(cell - 0.5) - 0.5) / w;
  float line = (1.0 - clamp(min(d.x, d.y) - 0.5, 0.0, 1.0)) * (1.0 - clamp(8.0 * max(w.x, w.y) - 1.0, 0.0, 1.0));
  color *= 1.0 - 0.10 * line;
#endif
  color = mix(color, u_background, smoothstep(u_floor_fade.x, u_floor_fade.y, length(v_position_W.xy - u_floor_centre)));
#endif
  frag_color = vec4(color, v_color.a);
#endif
}
)";

constexpr const char* kDepthVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_light_view_proj;
void main() { gl_Position = u_light_view_proj * u_model * vec4(a_position, 1.0); }
)";

constexpr const char* kDepthFragmentShader = R"(#version 330 core
void main() {}
)";

// ---- geometry ----

using Vertex = MeshVertex;  // colours used by meshes uploaded with them (robot links)
using CpuMesh = TriangleMesh;

struct GpuMesh {
  GLuint vao = 0;
  GLuint vbo = 0;
  GLuint ibo = 0;
  GLsizei index_count = 0;
  bool has_colors = false;
};

// One draw: a mesh placed in W, coloured by its vertices or by `rgba`.
struct DrawItem {
  int mesh = 0;
  Eigen::Affine3d X_WM = Eigen::Affine3d::Identity();  // includes scale
  Eigen::Vector4f rgba = Eigen::Vector4f::Ones();
  float specular = 0.1f;
  float shininess = 24.0f;
};

// The visual geometry of one robot link: all its visual meshes merged, in the link frame,
// coloured per vertex (one draw per link), and a low-polygon stand-in that casts its shadow.
struct LinkGeometry {
  int link = 0;
  int mesh = 0;
  int shadow_mesh = 0;  // the link's collision primitives (its visual mesh if it has none)
};

Eigen::Affine3d boxTransform(const core::Pose& X_WB, const Eigen::Vector3d& size) {
  Eigen::Affine3d X(X_WB.matrix());
  X.scale(size);
  return X;
}

Eigen::Vector4f rgbaOf(const core::Color& c, double alpha = 1.0) {
  return Eigen::Vector4d(c.r, c.g, c.b, alpha).cast<float>();
}

Eigen::Matrix4f toGl(const Eigen::Matrix4d& m) { return m.cast<float>(); }

GLuint compileShader(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("SceneRenderer: shader compilation failed: ") + log);
  }
  return shader;
}

GLuint linkProgram(const std::string& vertex_source, const std::string& fragment_source) {
  const GLuint vs = compileShader(GL_VERTEX_SHADER, vertex_source.c_str());
  const GLuint fs = compileShader(GL_FRAGMENT_SHADER, fragment_source.c_str());
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(program, sizeof(log), nullptr, log);
    glDeleteProgram(program);
    throw std::runtime_error(std::string("SceneRenderer: shader link failed: ") + log);
  }
  return program;
}

// A linked shading variant and its uniform locations (-1 for those it does not use).
struct SurfaceProgram {
  GLuint id = 0;
  GLint model = -1, normal_matrix = -1, view_proj = -1, specular = -1, shininess = -1, eye = -1, key = -1, fill = -1,
        shadow_map = -1, light_view_proj = -1, shadow_offset = -1, shadow_bias = -1, background = -1,
        floor_centre = -1, floor_fade = -1;
};

SurfaceProgram makeSurfaceProgram(const std::string& defines) {
  SurfaceProgram p;
  const std::string header = "#version 330 core\n" + defines + kCommonShaderCode;
  p.id = linkProgram(header + kVertexShaderBody, header + kFragmentShaderBody);
  const auto at = [&](const char* name) { return glGetUniformLocation(p.id, name); };
  p.model = at("u_model");
  p.normal_matrix = at("u_normal_matrix");
  p.view_proj = at("u_view_proj");
  p.specular = at("u_specular");
  p.shininess = at("u_shininess");
  p.eye = at("u_eye_W");
  p.key = at("u_key_W");
  p.fill = at("u_fill_W");
  p.shadow_map = at("u_shadow_map");
  p.light_view_proj = at("u_light_view_proj");
  p.shadow_offset = at("u_shadow_offset");
  p.shadow_bias = at("u_shadow_bias");
  p.background = at("u_background");
  p.floor_centre = at("u_floor_centre");
  p.floor_fade = at("u_floor_fade");
  return p;
}

GpuMesh uploadMesh(const CpuMesh& cpu, bool with_colors) {
  GpuMesh mesh;
  mesh.has_colors = with_colors;
  glGenVertexArrays(1, &mesh.vao);
  glBindVertexArray(mesh.vao);
  glGenBuffers(1, &mesh.vbo);
  glBindBuffer(GL_ARRAY_BUFFER, mesh.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cpu.vertices.size() * sizeof(Vertex)), cpu.vertices.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &mesh.ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(cpu.indices.size() * sizeof(std::uint32_t)),
               cpu.indices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<const void*>(0));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, normal)));
  // without the array, attribute 2 takes the current value set per draw (glVertexAttrib4fv)
  if (with_colors) {
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, color)));
  }
  glBindVertexArray(0);
  mesh.index_count = static_cast<GLsizei>(cpu.indices.size());
  return mesh;
}

// A depth texture for a shadow map, read with bilinear depth comparison (2x2 PCF).
GLuint createDepthTexture(GLsizei size) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

GLuint createDepthFramebuffer(GLuint depth_texture) {
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_texture, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("SceneRenderer: the shadow-map framebuffer is incomplete");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return fbo;
}

enum class CubeFaces { kAll, kTop, kAllButTop };

// A unit cube centred at the origin, four vertices per face so the faces shade flat; `faces`
// selects all faces, only the top (+z) one, or the other five.
CpuMesh unitCube(CubeFaces faces = CubeFaces::kAll) {
  CpuMesh cube;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      const bool top = axis == 2 && sign == 1;
      if ((faces == CubeFaces::kTop && !top) || (faces == CubeFaces::kAllButTop && top)) continue;
      // face normal n = sign * e_axis; u, v span the face with u x v = n (counter-clockwise)
      Eigen::Vector3f n = Eigen::Vector3f::Zero();
      n[axis] = static_cast<float>(sign);
      Eigen::Vector3f u = Eigen::Vector3f::Zero();
      u[(axis + 1) % 3] = 1.0f;
      const Eigen::Vector3f v = n.cross(u);
      const auto base = static_cast<std::uint32_t>(cube.vertices.size());
      const float corners[4][2] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
      for (const auto& c : corners) {
        const Eigen::Vector3f p = 0.5f * n + c[0] * u + c[1] * v;
        cube.vertices.push_back({{p.x(), p.y(), p.z()}, {n.x(), n.y(), n.z()}, {1.0f, 1.0f, 1.0f, 1.0f}});
      }
      for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) cube.indices.push_back(base + i);
    }
  }
  return cube;
}

// The twelve edges of the unit cube as line-segment index pairs.
CpuMesh unitCubeEdges() {
  CpuMesh edges;
  for (int corner = 0; corner < 8; ++corner) {
    edges.vertices.push_back({{(corner & 1) ? 0.5f : -0.5f, (corner & 2) ? 0.5f : -0.5f, (corner & 4) ? 0.5f : -0.5f},
                              {0.0f, 0.0f, 1.0f},
                              {1.0f, 1.0f, 1.0f, 1.0f}});
  }
  for (std::uint32_t a = 0; a < 8; ++a) {
    for (std::uint32_t bit : {1u, 2u, 4u}) {
      if (!(a & bit)) {
        edges.indices.push_back(a);
        edges.indices.push_back(a | bit);
      }
    }
  }
  return edges;
}

// A flat upward-facing rectangle [x0, x1] x [y0, y1] at height z, appended to `mesh`.
void appendFloorRect(CpuMesh& mesh, double x0, double y0, double x1, double y1, double z) {
  if (x1 <= x0 || y1 <= y0) return;
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  const double xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
  for (int k = 0; k < 4; ++k) {
    mesh.vertices.push_back({{static_cast<float>(xs[k]), static_cast<float>(ys[k]), static_cast<float>(z)},
                             {0.0f, 0.0f, 1.0f},
                             {1.0f, 1.0f, 1.0f, 1.0f}});
  }
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

// A closed convex stand-in for a collision primitive in its own frame (normals unused: the
// shadow pass writes depth only). Cylinders along z with 16 sides, spheres with 8 x 16 facets.
// Every face is moved inwards by `inset` [m] (at most to half the size), so that the stand-in
// stays inside the visual surface it approximates and never shadows that surface itself.
CpuMesh primitiveMesh(const core::CollisionShape& shape, double inset) {
  const auto shrink = [&](double half_extent) { return std::max(0.5 * half_extent, half_extent - inset); };
  CpuMesh mesh;
  const auto add = [&](const Eigen::Vector3d& p) {
    mesh.vertices.push_back({{static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())},
                             {0.0f, 0.0f, 1.0f},
                             {1.0f, 1.0f, 1.0f, 1.0f}});
  };
  const auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  };
  constexpr double kTwoPi = 6.283185307179586;
  switch (shape.type) {
    case core::ShapeType::kBox: {
      mesh = unitCube();
      for (Vertex& v : mesh.vertices) {
        for (int k = 0; k < 3; ++k) v.position[k] *= static_cast<float>(2.0 * shrink(0.5 * shape.size[k]));
      }
      break;
    }
    case core::ShapeType::kCylinder: {
      constexpr int kSides = 16;
      const double r = shrink(shape.size.x()), h = shrink(0.5 * shape.size.z());
      add({0.0, 0.0, -h});  // 0: bottom centre
      add({0.0, 0.0, h});   // 1: top centre
      for (int i = 0; i < kSides; ++i) {
        const double a = kTwoPi * i / kSides;
        add({r * std::cos(a), r * std::sin(a), -h});  // 2 + 2i
        add({r * std::cos(a), r * std::sin(a), h});   // 3 + 2i
      }
      for (int i = 0; i < kSides; ++i) {
        const std::uint32_t b0 = 2 + 2 * i, t0 = b0 + 1, b1 = 2 + 2 * ((i + 1) % kSides), t1 = b1 + 1;
        triangle(b0, b1, t1);  // counter-clockwise seen from outside
        triangle(b0, t1, t0);
        triangle(0, b1, b0);
        triangle(1, t0, t1);
      }
      break;
    }
    case core::ShapeType::kSphere: {
      constexpr int kRings = 8, kSegments = 16;
      const double r = shrink(shape.size.x());
      for (int i = 0; i <= kRings; ++i) {
        const double polar = 0.5 * kTwoPi * i / kRings;
        for (int j = 0; j < kSegments; ++j) {
          const double a = kTwoPi * j / kSegments;
          add({r * std::sin(polar) * std::cos(a), r * std::sin(polar) * std::sin(a), r * std::cos(polar)});
        }
      }
      for (int i = 0; i < kRings; ++i) {
        for (int j = 0; j < kSegments; ++j) {
          const std::uint32_t a = i * kSegments + j, b = i * kSegments + (j + 1) % kSegments;
          triangle(a, a + kSegments, b + kSegments);
          triangle(a, b + kSegments, b);
        }
      }
      break;
    }
  }
  return mesh;
}
// Releases the calling thread's current OSMesa context when it goes out of scope, so that a
// renderer is bound to a thread only while it works and can move between threads.
struct ReleaseContextOnExit {
  ReleaseContextOnExit() = default;
  ReleaseContextOnExit(const ReleaseContextOnExit&) = delete;
  ReleaseContextOnExit& operator=(const ReleaseContextOnExit&) = delete;
  ~ReleaseContextOnExit() { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }
};

}  // namespace

struct SceneRenderer::Impl {
  const core::World& world;
  const core::RobotSet& robots;
  RenderSettings settings;

  OSMesaContext context = nullptr;
  std::vector<std::uint8_t> color_buffer;  // RGBA, bottom row first (OSMesa's default)
  int width = 0;
  int height = 0;

  SurfaceProgram mesh_program;         // robot links, lit per fragment
  SurfaceProgram box_program;          // objects and fixture tops, lit per vertex
  SurfaceProgram unshadowed_box_program;  // the other faces of fixtures
  SurfaceProgram floor_program;        // the floor where shadows can fall
  SurfaceProgram outer_floor_program;  // the rest of the floor, without shadow look-ups
  SurfaceProgram flat_program;         // region volumes and edges
  GLuint depth_program = 0;
  GLint depth_model = -1;
  GLint depth_light_view_proj = -1;

  std::vector<GpuMesh> meshes;
  int cube_mesh = -1;
  int cube_top_mesh = -1;    // the top face of the unit cube
  int cube_sides_mesh = -1;  // its other five faces
  int cube_edges_mesh = -1;
  int floor_mesh = -1;
  int outer_floor_mesh = -1;
  std::vector<std::vector<LinkGeometry>> robot_links;  // per robot
  std::vector<DrawItem> fixture_items;
  struct RegionItem {
    Eigen::Affine3d X_WM;
    Eigen::Vector4f rgba;
  };
  std::vector<RegionItem> regions;

  // the key light (and its shadow map) and the fill light, fixed per world; unit vectors
  // pointing towards the lights
  Eigen::Vector3d key_W = Eigen::Vector3d(-0.45, -0.6, 1.0).normalized();
  Eigen::Vector3d fill_W = Eigen::Vector3d(0.7, 0.5, 0.35).normalized();
  Eigen::Matrix4d light_view_proj = Eigen::Matrix4d::Identity();
  double shadow_offset = 0.0;
  double shadow_bias = 0.0;
  GLuint static_shadow_texture = 0;  // the fixtures' depth, drawn once
  GLuint static_shadow_fbo = 0;
  GLuint shadow_texture = 0;  // per frame: a copy of the static map plus robots and objects
  GLuint shadow_fbo = 0;

  // multisampled target, resolved into the OSMesa buffer
  GLuint msaa_fbo = 0;
  GLuint msaa_color = 0;
  GLuint msaa_depth = 0;

  Eigen::AlignedBox3d bounds;   // worldBounds
  Eigen::AlignedBox3d far_box;  // bounds with the floor's extent, for the clip planes
  Eigen::Vector2d floor_centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d floor_fade = Eigen::Vector2d::Zero();  // fade start and end radius [m]

  Impl(const core::World& w, const core::RobotSet& r, const RenderSettings& s) : world(w), robots(r), settings(s) {}

  void createContext();
  void makeCurrent(int w, int h);
  void createPrograms();
  void loadMeshes();
  void buildStaticScene();
  void createShadowMaps();
  void ensureMsaaTarget();
  void releaseMsaaTarget();
  void collectMovingItems(const SceneState& state, std::vector<DrawItem>& robot_items,
                          std::vector<DrawItem>& object_items, std::vector<DrawItem>& shadow_items) const;
  void drawDepth(const std::vector<DrawItem>& items);
  void drawShadowPass(const std::vector<DrawItem>& moving);
  void setFrameUniforms(const SurfaceProgram& program, const Eigen::Matrix4f& view_proj, const Camera& camera);
  void drawItem(const SurfaceProgram& program, const DrawItem& item, GLenum primitive = GL_TRIANGLES);
  Image readImage();
};

void SceneRenderer::Impl::createContext() {
  const int attributes[] = {OSMESA_FORMAT,       OSMESA_RGBA, OSMESA_DEPTH_BITS,           24,
                            OSMESA_STENCIL_BITS, 0,           OSMESA_PROFILE,              OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3,  OSMESA_CONTEXT_MINOR_VERSION, 3,
                            0};
  context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context) {
    throw std::runtime_error("SceneRenderer: OSMesa could not create an OpenGL 3.3 context (needs Mesa's "
                             "libOSMesa with llvmpipe, Mesa >= 20)");
  }
  makeCurrent(64, 64);
}

void SceneRenderer::Impl::makeCurrent(int w, int h) {
  if (w != width || h != height) {
    color_buffer.assign(static_cast<std::size_t>(w) * h * 4, 0);
    width = w;
    height = h;
  }
  if (!OSMesaMakeCurrent(context, color_buffer.data(), GL_UNSIGNED_BYTE, w, h)) {
    throw std::runtime_error("SceneRenderer: OSMesaMakeCurrent failed for " + std::to_string(w) + "x" +
                             std::to_string(h));
  }
}

void SceneRenderer::Impl::createPrograms() {
  const std::string shadows = settings.shadows ? "#define SHADOWS\n" : "";
  const std::string grid = settings.floor_grid ? "#define GRID\n" : "";
  mesh_program = makeSurfaceProgram("#define PIXEL_LIGHTING\n" + shadows);
  box_program = makeSurfaceProgram(shadows);
  unshadowed_box_program = makeSurfaceProgram("");
  floor_program = makeSurfaceProgram("#define FLOOR\n" + shadows + grid);
  outer_floor_program = makeSurfaceProgram("#define FLOOR\n" + grid);
  flat_program = makeSurfaceProgram("#define FLAT\n");
  depth_program = linkProgram(kDepthVertexShader, kDepthFragmentShader);
  depth_model = glGetUniformLocation(depth_program, "u_model");
  depth_light_view_proj = glGetUniformLocation(depth_program, "u_light_view_proj");
}

void SceneRenderer::Impl::loadMeshes() {
  cube_mesh = static_cast<int>(meshes.size());
  meshes.push_back(uploadMesh(unitCube(), false));
  cube_top_mesh = static_cast<int>(meshes.size());
  meshes.push_back(uploadMesh(unitCube(CubeFaces::kTop), false));
  cube_sides_mesh = static_cast<int>(meshes.size());
  meshes.push_back(uploadMesh(unitCube(CubeFaces::kAllButTop), false));
  cube_edges_mesh = static_cast<int>(meshes.size());
  meshes.push_back(uploadMesh(unitCubeEdges(), false));

  // each mesh file is read once; each link of each model becomes one vertex-coloured mesh,
  // shared by the robots using that model
  std::map<std::filesystem::path, CpuMesh> file_meshes;
  std::map<std::pair<const core::RobotModel*, int>, LinkGeometry> link_geometry;
  for (const core::PlacedRobot& robot : robots.robots()) {
    std::vector<LinkGeometry> links;
    const std::vector<core::LinkModel>& model_links = robot.model->links();
    for (std::size_t l = 0; l < model_links.size(); ++l) {
      const core::LinkModel& link = model_links[l];
      if (link.visuals.empty()) continue;
      const auto key = std::make_pair(robot.model, static_cast<int>(l));
      auto found = link_geometry.find(key);
      if (found == link_geometry.end()) {
        LinkGeometry geometry;
        geometry.link = static_cast<int>(l);
        const CpuMesh link_mesh = linkVisualMesh(link, file_meshes);
        geometry.mesh = static_cast<int>(meshes.size());
        meshes.push_back(uploadMesh(link_mesh, true));
        // the collision primitives envelop the visuals closely and have a tenth of their
        // triangles, which makes the shadow pass cheap
        if (link.collisions.empty()) {
          geometry.shadow_mesh = geometry.mesh;
        } else {
          CpuMesh proxy;
          for (const core::CollisionShape& shape : link.collisions) {
            appendPlaced(proxy, primitiveMesh(shape, 0.004), Eigen::Affine3d(shape.X_LS.matrix()), Eigen::Vector4f::Ones());
          }
          geometry.shadow_mesh = static_cast<int>(meshes.size());
          meshes.push_back(uploadMesh(proxy, false));
        }
        found = link_geometry.emplace(key, geometry).first;
      }
      links.push_back(found->second);
    }
    robot_links.push_back(std::move(links));
  }
}

void SceneRenderer::Impl::buildStaticScene() {
  bounds = worldBounds(world);
  for (const core::FixtureSpec& fixture : world.fixtures) {
    for (const core::Box& box : fixture.boxes) {
      DrawItem item;
      item.mesh = cube_mesh;
      item.X_WM = boxTransform(box.X_WB, box.size);
      item.rgba = rgbaOf(fixture.color);
      item.specular = 0.08f;
      item.shininess = 16.0f;
      fixture_items.push_back(item);
    }
  }

  // the floor (z = 0): a square around the scene that fades into the background before its
  // edge, split into the part where shadows can fall (the scene's footprint and its shadow
  // cast by the key light from the top of the scene) and the frame around it
  const Eigen::Vector3d centre = bounds.center();
  const double radius = 0.5 * bounds.sizes().head<2>().norm();
  floor_centre = centre.head<2>();
  floor_fade = {radius + 0.8, radius + 4.0};
  const double half = floor_fade.y() + 0.5;
  const Eigen::Vector2d shadow_shift = -key_W.head<2>() / key_W.z() * std::max(bounds.max().z(), 0.0);
  Eigen::AlignedBox2d inner(bounds.min().head<2>(), bounds.max().head<2>());
  inner.extend(inner.min() + shadow_shift);
  inner.extend(inner.max() + shadow_shift);
  inner.min() -= Eigen::Vector2d::Constant(0.1);
  inner.max() += Eigen::Vector2d::Constant(0.1);
  const Eigen::Vector2d lo = centre.head<2>() - Eigen::Vector2d::Constant(half);
  const Eigen::Vector2d hi = centre.head<2>() + Eigen::Vector2d::Constant(half);
  inner = inner.intersection(Eigen::AlignedBox2d(lo, hi));
  CpuMesh floor, outer;
  appendFloorRect(floor, inner.min().x(), inner.min().y(), inner.max().x(), inner.max().y(), 0.0);
  appendFloorRect(outer, lo.x(), lo.y(), hi.x(), inner.min().y(), 0.0);
  appendFloorRect(outer, lo.x(), inner.max().y(), hi.x(), hi.y(), 0.0);
  appendFloorRect(outer, lo.x(), inner.min().y(), inner.min().x(), inner.max().y(), 0.0);
  appendFloorRect(outer, inner.max().x(), inner.min().y(), hi.x(), inner.max().y(), 0.0);
  floor_mesh = static_cast<int>(meshes.size());
  meshes.push_back(uploadMesh(floor, false));
  outer_floor_mesh = static_cast<int>(meshes.size());
  meshes.push_back(uploadMesh(outer, false));
  far_box = bounds;
  far_box.extend(Eigen::Vector3d(lo.x(), lo.y(), 0.0));
  far_box.extend(Eigen::Vector3d(hi.x(), hi.y(), 0.0));

  if (settings.show_regions) {
    for (const core::Region& region : world.regions) {
      if (!region.fixture.empty()) continue;  // bins show their own region
      core::Color color{0.2, 0.55, 0.95};
      for (const core::ObjectSpec& object : world.objects) {
        if (world.goalRegionOf(object) == &region) {
          color = object.color;
          break;
        }
      }
      core::Pose X_WC = region.X_WR;
      X_WC.translation() += region.X_WR.linear() * Eigen::Vector3d(0.0, 0.0, 0.5 * region.size.z());
      regions.push_back({boxTransform(X_WC, region.size), rgbaOf(color)});
    }
  }
}

void SceneRenderer::Impl::createShadowMaps() {
  // an orthographic light frustum around the scene (plus a margin for parts that move out
  // of worldBounds) seen from the key light's direction
  const Eigen::Vector3d forward = -key_W;
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = up.transpose();
  view.block<1, 3>(2, 0) = -forward.transpose();
  Eigen::AlignedBox3d box = bounds;
  box.extend(bounds.min() - Eigen::Vector3d(0.3, 0.3, 0.0));
  box.extend(bounds.max() + Eigen::Vector3d(0.3, 0.3, 0.3));
  box.extend(Eigen::Vector3d(bounds.min().x(), bounds.min().y(), 0.0));
  Eigen::AlignedBox3d light_box;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
    light_box.extend((view * p.homogeneous()).head<3>());
  }
  const Eigen::Vector3d lo = light_box.min(), hi = light_box.max();
  Eigen::Matrix4d ortho = Eigen::Matrix4d::Identity();
  ortho(0, 0) = 2.0 / (hi.x() - lo.x());
  ortho(0, 3) = -(hi.x() + lo.x()) / (hi.x() - lo.x());
  ortho(1, 1) = 2.0 / (hi.y() - lo.y());
  ortho(1, 3) = -(hi.y() + lo.y()) / (hi.y() - lo.y());
  // the light looks along its -z: near = -hi.z, far = -lo.z (with a little room)
  const double near_z = -hi.z() - 0.1, far_z = -lo.z() + 0.1;
  ortho(2, 2) = -2.0 / (far_z - near_z);
  ortho(2, 3) = -(far_z + near_z) / (far_z - near_z);
  light_view_proj = ortho * view;
  // a texel's size sets the normal offset; a small constant depth bias (2 mm) does the rest
  const double texel_m = std::max(hi.x() - lo.x(), hi.y() - lo.y()) / settings.shadow_map_size;
  shadow_offset = 1.5 * texel_m;
  shadow_bias = 0.002 / (far_z - near_z);

  static_shadow_texture = createDepthTexture(settings.shadow_map_size);
  static_shadow_fbo = createDepthFramebuffer(static_shadow_texture);
  shadow_texture = createDepthTexture(settings.shadow_map_size);
  shadow_fbo = createDepthFramebuffer(shadow_texture);
  glBindFramebuffer(GL_FRAMEBUFFER, static_shadow_fbo);
  glViewport(0, 0, settings.shadow_map_size, settings.shadow_map_size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glClear(GL_DEPTH_BUFFER_BIT);
  drawDepth(fixture_items);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void SceneRenderer::Impl::releaseMsaaTarget() {
  if (msaa_fbo) glDeleteFramebuffers(1, &msaa_fbo);
  if (msaa_color) glDeleteRenderbuffers(1, &msaa_color);
  if (msaa_depth) glDeleteRenderbuffers(1, &msaa_depth);
  msaa_fbo = msaa_color = msaa_depth = 0;
}

void SceneRenderer::Impl::ensureMsaaTarget() {
  releaseMsaaTarget();
  glGenRenderbuffers(1, &msaa_color);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_color);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, settings.msaa_samples, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &msaa_depth);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, settings.msaa_samples, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &msaa_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("SceneRenderer: the multisample framebuffer is incomplete");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void SceneRenderer::Impl::collectMovingItems(const SceneState& state, std::vector<DrawItem>& robot_items,
                                             std::vector<DrawItem>& object_items,
                                             std::vector<DrawItem>& shadow_items) const {
  for (std::size_t r = 0; r < robot_links.size(); ++r) {
    for (const LinkGeometry& link : robot_links[r]) {
      DrawItem item;
      item.mesh = link.mesh;
      item.X_WM = Eigen::Affine3d(state.link_poses[r][link.link].matrix());
      item.specular = 0.30f;
      item.shininess = 40.0f;
      robot_items.push_back(item);
      item.mesh = link.shadow_mesh;
      shadow_items.push_back(item);
    }
  }
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    DrawItem item;
    item.mesh = cube_mesh;
    item.X_WM = boxTransform(state.object_poses[o], world.objects[o].size);
    item.rgba = rgbaOf(world.objects[o].color);
    item.specular = 0.15f;
    item.shininess = 24.0f;
    object_items.push_back(item);
    shadow_items.push_back(item);
  }
}

void SceneRenderer::Impl::drawDepth(const std::vector<DrawItem>& items) {
  glUseProgram(depth_program);
  const Eigen::Matrix4f light = toGl(light_view_proj);
  glUniformMatrix4fv(depth_light_view_proj, 1, GL_FALSE, light.data());
  // slope-scaled offset keeps lit surfaces from shadowing themselves (acne); the faces
  // turned towards the light give the same shadow as the whole mesh, and culling the others
  // makes this pass several times faster on llvmpipe
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  for (const DrawItem& item : items) {
    const Eigen::Matrix4f model = item.X_WM.matrix().cast<float>();
    glUniformMatrix4fv(depth_model, 1, GL_FALSE, model.data());
    glBindVertexArray(meshes[item.mesh].vao);
    glDrawElements(GL_TRIANGLES, meshes[item.mesh].index_count, GL_UNSIGNED_INT, nullptr);
  }
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void SceneRenderer::Impl::drawShadowPass(const std::vector<DrawItem>& moving) {
  const GLsizei n = settings.shadow_map_size;
  glCopyImageSubData(static_shadow_texture, GL_TEXTURE_2D, 0, 0, 0, 0, shadow_texture, GL_TEXTURE_2D, 0, 0, 0, 0, n, n,
                     1);
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo);
  glViewport(0, 0, n, n);
  drawDepth(moving);
}

void SceneRenderer::Impl::setFrameUniforms(const SurfaceProgram& program, const Eigen::Matrix4f& view_proj,
                                           const Camera& camera) {
  glUseProgram(program.id);
  const Eigen::Vector3f eye = camera.eye.cast<float>(), key = key_W.cast<float>(), fill = fill_W.cast<float>();
  const Eigen::Matrix4f light = toGl(light_view_proj);
  const core::Color& bg = settings.background;
  glUniformMatrix4fv(program.view_proj, 1, GL_FALSE, view_proj.data());
  glUniform3fv(program.eye, 1, eye.data());
  glUniform3fv(program.key, 1, key.data());
  glUniform3fv(program.fill, 1, fill.data());
  glUniformMatrix4fv(program.light_view_proj, 1, GL_FALSE, light.data());
  glUniform1f(program.shadow_offset, static_cast<float>(shadow_offset));
  glUniform1f(program.shadow_bias, static_cast<float>(shadow_bias));
  glUniform1i(program.shadow_map, 0);
  glUniform3f(program.background, static_cast<float>(bg.r), static_cast<float>(bg.g), static_cast<float>(bg.b));
  glUniform2f(program.floor_centre, static_cast<float>(floor_centre.x()), static_cast<float>(floor_centre.y()));
  glUniform2f(program.floor_fade, static_cast<float>(floor_fade.x()), static_cast<float>(floor_fade.y()));
}

void SceneRenderer::Impl::drawItem(const SurfaceProgram& program, const DrawItem& item, GLenum primitive) {
  const Eigen::Matrix4f model = item.X_WM.matrix().cast<float>();
  const Eigen::Matrix3f normal = item.X_WM.linear().inverse().transpose().cast<float>();
  glUniformMatrix4fv(program.model, 1, GL_FALSE, model.data());
  glUniformMatrix3fv(program.normal_matrix, 1, GL_FALSE, normal.data());
  glUniform1f(program.specular, item.specular);
  glUniform1f(program.shininess, item.shininess);
  const GpuMesh& mesh = meshes[item.mesh];
  if (!mesh.has_colors) glVertexAttrib4fv(2, item.rgba.data());
  glBindVertexArray(mesh.vao);
  glDrawElements(primitive, mesh.index_count, GL_UNSIGNED_INT, nullptr);
}

Image SceneRenderer::Impl::readImage() {
  glFinish();
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  // OSMesa's buffer holds the bottom row first
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* src = color_buffer.data() + static_cast<std::size_t>(height - 1 - y) * width * 4;
    std::uint8_t* dst = image.pixel(0, y);
    for (int x = 0; x < width; ++x) {
      dst[3 * x] = src[4 * x];
      dst[3 * x + 1] = src[4 * x + 1];
      dst[3 * x + 2] = src[4 * x + 2];
    }
  }
  return image;
}

SceneRenderer::SceneRenderer(const core::World& world, const core::RobotSet& robots, RenderSettings settings)
    : settings_(settings) {
  if (settings.shadow_map_size < 64 || settings.shadow_map_size > 8192) {
    throw std::invalid_argument("RenderSettings: shadow_map_size must be in [64, 8192] (got " +
                                std::to_string(settings.shadow_map_size) + ")");
  }
  if (settings.msaa_samples != 0 && settings.msaa_samples != 4) {
    throw std::invalid_argument("RenderSettings: msaa_samples must be 0 or 4 (got " +
                                std::to_string(settings.msaa_samples) + ")");
  }
  impl_ = std::make_unique<Impl>(world, robots, settings);
  try {
    const ReleaseContextOnExit release;
    impl_->createContext();
    impl_->createPrograms();
    impl_->loadMeshes();
    impl_->buildStaticScene();
    if (settings.shadows) impl_->createShadowMaps();
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
      throw std::runtime_error("SceneRenderer: OpenGL error " + std::to_string(error) + " during set-up");
    }
  } catch (...) {
    if (impl_->context) OSMesaDestroyContext(impl_->context);
    throw;
  }
}

SceneRenderer::~SceneRenderer() {
  // destroying the context frees its buffers, textures and programs; it is not current in
  // any thread (render and the constructor release it)
  if (impl_ && impl_->context) OSMesaDestroyContext(impl_->context);
}

Image SceneRenderer::render(const SceneState& state, const Camera& camera, const std::vector<Overlay>& overlays) {
  validateCamera(camera);
  Impl& s = *impl_;
  if (state.link_poses.size() != s.robots.size() || state.object_poses.size() != s.world.objects.size()) {
    throw std::invalid_argument("SceneRenderer::render: the scene state has " +
                                std::to_string(state.link_poses.size()) + " robots and " +
                                std::to_string(state.object_poses.size()) + " objects, the world " +
                                std::to_string(s.robots.size()) + " and " + std::to_string(s.world.objects.size()));
  }
  for (std::size_t r = 0; r < s.robots.size(); ++r) {
    if (state.link_poses[r].size() != s.robots[r].model->links().size()) {
      throw std::invalid_argument("SceneRenderer::render: robot " + std::to_string(r) + " has " +
                                  std::to_string(state.link_poses[r].size()) + " link poses, its model " +
                                  std::to_string(s.robots[r].model->links().size()) + " links");
    }
  }
  const bool resized = camera.width != s.width || camera.height != s.height;
  const ReleaseContextOnExit release;
  s.makeCurrent(camera.width, camera.height);
  if (s.settings.msaa_samples > 0 && (resized || !s.msaa_fbo)) s.ensureMsaaTarget();

  std::vector<DrawItem> robot_items, object_items, shadow_items;
  s.collectMovingItems(state, robot_items, object_items, shadow_items);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  if (s.settings.shadows) s.drawShadowPass(shadow_items);

  // clip planes hugging the scene keep depth precision where it matters
  double near_m = 1e300, far_m = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const double d = depthInCamera(camera, s.far_box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
    near_m = std::min(near_m, d);
    far_m = std::max(far_m, d);
  }
  far_m = std::max(1.0, 1.05 * far_m + 0.1);
  near_m = std::clamp(0.9 * near_m, std::max(0.01, far_m * 1e-4), 1.0);
  const Eigen::Matrix4f view_proj = toGl(projectionMatrix(camera, near_m, far_m) * viewMatrix(camera));

  glBindFramebuffer(GL_FRAMEBUFFER, s.settings.msaa_samples > 0 ? s.msaa_fbo : 0);
  glViewport(0, 0, camera.width, camera.height);
  const core::Color& bg = s.settings.background;
  glClearColor(static_cast<float>(bg.r), static_cast<float>(bg.g), static_cast<float>(bg.b), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, s.shadow_texture);

  // near to far, so that the depth test rejects hidden fragments before they are shaded:
  // robots, objects, fixtures, then the floor behind everything
  s.setFrameUniforms(s.mesh_program, view_proj, camera);
  for (const DrawItem& item : robot_items) s.drawItem(s.mesh_program, item);
  s.setFrameUniforms(s.box_program, view_proj, camera);
  for (const DrawItem& item : object_items) s.drawItem(s.box_program, item);
  // fixtures stand upright (yaw only) and everything that casts shadows on them is above
  // them: only their top faces receive shadows, the others (such as the large sides of a
  // table) skip the shadow-map look-up
  for (DrawItem item : s.fixture_items) {
    item.mesh = s.cube_top_mesh;
    s.drawItem(s.box_program, item);
  }
  s.setFrameUniforms(s.unshadowed_box_program, view_proj, camera);
  for (DrawItem item : s.fixture_items) {
    item.mesh = s.cube_sides_mesh;
    s.drawItem(s.unshadowed_box_program, item);
  }
  DrawItem floor;
  floor.rgba = Eigen::Vector4f(0.78f, 0.79f, 0.80f, 1.0f);
  floor.specular = 0.0f;
  floor.mesh = s.floor_mesh;
  s.setFrameUniforms(s.floor_program, view_proj, camera);
  s.drawItem(s.floor_program, floor);
  floor.mesh = s.outer_floor_mesh;
  s.setFrameUniforms(s.outer_floor_program, view_proj, camera);
  s.drawItem(s.outer_floor_program, floor);

  // goal regions: translucent volumes without depth writes, then their edges
  if (!s.regions.empty()) {
    s.setFrameUniforms(s.flat_program, view_proj, camera);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    for (const auto& region : s.regions) {
      DrawItem volume;
      volume.mesh = s.cube_mesh;
      volume.X_WM = region.X_WM;
      volume.rgba = region.rgba;
      volume.rgba[3] = 0.15f;
      s.drawItem(s.flat_program, volume);
      volume.mesh = s.cube_edges_mesh;
      volume.rgba[3] = 0.8f;
      s.drawItem(s.flat_program, volume, GL_LINES);
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
  glBindVertexArray(0);

  if (s.settings.msaa_samples > 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, s.msaa_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, camera.width, camera.height, 0, 0, camera.width, camera.height, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    throw std::runtime_error("SceneRenderer: OpenGL error " + std::to_string(error) + " while rendering");
  }
  Image image = s.readImage();
  drawOverlays(image, camera, overlays);
  return image;
}

}  // namespace dashbed::render
