#include "raster/osmesa/osmesa_renderer.h"

#include <GL/osmesa.h>

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <omp.h>

#include "raster/osmesa/facet_csg_draw.h"
#ifdef QACC_HAVE_OPENCSG
#include "raster/osmesa/opencsg_glew.h"
#endif
#include "raster/pixel/shading.h"

namespace qacc {

namespace {

using FacetCsgDrawPtr = std::unique_ptr<FacetCsgDraw>;

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// GL 2.0 shader entry points, fetched through OSMesaGetProcAddress.
struct ShaderApi {
  using CreateShader = GLuint (*)(GLenum);
  using ShaderSource = void (*)(GLuint, GLsizei, const char* const*, const GLint*);
  using CompileShader = void (*)(GLuint);
  using GetShaderiv = void (*)(GLuint, GLenum, GLint*);
  using GetShaderInfoLog = void (*)(GLuint, GLsizei, GLsizei*, char*);
  using CreateProgram = GLuint (*)();
  using AttachShader = void (*)(GLuint, GLuint);
  using LinkProgram = void (*)(GLuint);
  using GetProgramiv = void (*)(GLuint, GLenum, GLint*);
  using UseProgram = void (*)(GLuint);
  using GetUniformLocation = GLint (*)(GLuint, const char*);
  using Uniform1i = void (*)(GLint, GLint);
  using Uniform3fv = void (*)(GLint, GLsizei, const GLfloat*);
  using Uniform1iv = void (*)(GLint, GLsizei, const GLint*);
  using DeleteShader = void (*)(GLuint);
  using DeleteProgram = void (*)(GLuint);
  CreateShader createShader = nullptr;
  ShaderSource shaderSource = nullptr;
  CompileShader compileShader = nullptr;
  GetShaderiv getShaderiv = nullptr;
  GetShaderInfoLog getShaderInfoLog = nullptr;
  CreateProgram createProgram = nullptr;
  AttachShader attachShader = nullptr;
  LinkProgram linkProgram = nullptr;
  GetProgramiv getProgramiv = nullptr;
  UseProgram useProgram = nullptr;
  GetUniformLocation getUniformLocation = nullptr;
  Uniform1i uniform1i = nullptr;
  Uniform3fv uniform3fv = nullptr;
  Uniform1iv uniform1iv = nullptr;
  DeleteShader deleteShader = nullptr;
  DeleteProgram deleteProgram = nullptr;

  template <typename F>
  static void get(F& f, const char* name) {
    f = reinterpret_cast<F>(OSMesaGetProcAddress(name));
  }
  bool load() {
    get(createShader, "glCreateShader");
    get(shaderSource, "glShaderSource");
    get(compileShader, "glCompileShader");
    get(getShaderiv, "glGetShaderiv");
    get(getShaderInfoLog, "glGetShaderInfoLog");
    get(createProgram, "glCreateProgram");
    get(attachShader, "glAttachShader");
    get(linkProgram, "glLinkProgram");
    get(getProgramiv, "glGetProgramiv");
    get(useProgram, "glUseProgram");
    get(getUniformLocation, "glGetUniformLocation");
    get(uniform1i, "glUniform1i");
    get(uniform3fv, "glUniform3fv");
    get(uniform1iv, "glUniform1iv");
    get(deleteShader, "glDeleteShader");
    get(deleteProgram, "glDeleteProgram");
    return createShader && shaderSource && compileShader && getShaderiv && getShaderInfoLog && createProgram &&
           attachShader && linkProgram && getProgramiv && useProgram && getUniformLocation && uniform1i &&
           uniform3fv && uniform1iv && deleteShader && deleteProgram;
  }
};

constexpr int kMaxLights = 16;

// The shading of raster/shading.h, per fragment. Material colour in gl_Color, (specular,
// shininess) in texture coordinate 0, world position and normal interpolated.
const char* kVertexShader = R"(#version 120
varying vec3 worldPos;
varying vec3 worldNormal;
varying vec3 matColor;
varying vec2 matSpec;
void main() {
  worldPos = gl_Vertex.xyz;
  worldNormal = gl_Normal;
  matColor = gl_Color.rgb;
  matSpec = gl_MultiTexCoord0.xy;
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
)";

const char* kFragmentShader = R"(#version 120
const int MAX_LIGHTS = 16;
uniform int lightCount;
uniform int lightType[MAX_LIGHTS];      // 0 ambient, 1 directional, 2 point
uniform vec3 lightVec[MAX_LIGHTS];      // direction (directional) or position (point)
uniform vec3 lightColor[MAX_LIGHTS];
uniform int orthographic;
uniform vec3 eye;
uniform vec3 forward;
varying vec3 worldPos;
varying vec3 worldNormal;
varying vec3 matColor;
varying vec2 matSpec;
void main() {
  vec3 V = orthographic != 0 ? -forward : normalize(eye - worldPos);
  vec3 N = normalize(worldNormal);
  if (dot(N, V) < 0.0) N = -N;
  vec3 outc = vec3(0.0);
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (i >= lightCount) break;
    if (lightType[i] == 0) { outc += lightColor[i] * matColor; continue; }
    vec3 L = lightType[i] == 1 ? -normalize(lightVec[i]) : normalize(lightVec[i] - worldPos);
    float ndl = dot(N, L);
    if (ndl <= 0.0) continue;
    vec3 H = normalize(L + V);
    float spec = matSpec.x * pow(max(0.0, dot(N, H)), matSpec.y);
    outc += lightColor[i] * (matColor * ndl + vec3(spec));
  }
  gl_FragColor = vec4(outc, 1.0);
}
)";

GLuint compile(const ShaderApi& api, GLenum type, const char* src, std::string& log) {
  const GLuint s = api.createShader(type);
  api.shaderSource(s, 1, &src, nullptr);
  api.compileShader(s);
  GLint ok = 0;
  api.getShaderiv(s, 0x8B81 /* GL_COMPILE_STATUS */, &ok);
  if (!ok) {
    char buf[2048] = {0};
    api.getShaderInfoLog(s, sizeof buf - 1, nullptr, buf);
    log = buf;
    api.deleteShader(s);
    return 0;
  }
  return s;
}

// Builds the per-pixel program; returns 0 with `why` filled when the context cannot.
GLuint perPixelProgram(const ShaderApi& api, bool apiLoaded, std::string& why) {
  if (!apiLoaded) {
    why = "per-pixel shading unavailable: the GL context has no GLSL entry points; fell back to Gouraud";
    return 0;
  }
  std::string log;
  const GLuint vs = compile(api, 0x8B31 /* GL_VERTEX_SHADER */, kVertexShader, log);
  const GLuint fs = vs ? compile(api, 0x8B30 /* GL_FRAGMENT_SHADER */, kFragmentShader, log) : 0;
  if (!vs || !fs) {
    why = "per-pixel shading unavailable (GLSL 1.20 compile failed: " + log + "); fell back to Gouraud";
    return 0;
  }
  const GLuint prog = api.createProgram();
  api.attachShader(prog, vs);
  api.attachShader(prog, fs);
  api.linkProgram(prog);
  GLint ok = 0;
  api.getProgramiv(prog, 0x8B82 /* GL_LINK_STATUS */, &ok);
  api.deleteShader(vs);
  api.deleteShader(fs);
  if (!ok) {
    api.deleteProgram(prog);
    why = "per-pixel shading unavailable (GLSL link failed); fell back to Gouraud";
    return 0;
  }
  return prog;
}

void loadMatrix(GLenum mode, const Eigen::Matrix4d& m) {
  glMatrixMode(mode);
  GLdouble a[16];
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a[c * 4 + r] = m(r, c);  // column-major
  glLoadMatrixd(a);
}

struct ContextGuard {
  OSMesaContext ctx = nullptr;
  ~ContextGuard() {
    if (ctx) OSMesaDestroyContext(ctx);
  }
};

// An OSMesa context on llvmpipe drawing into `rgba` (W x H float RGBA, rows bottom up) with
// a 24-bit depth buffer; the renderer's strings go into res.
void createContext(ContextGuard& guard, std::vector<float>& rgba, int W, int H, int threads, FacetRenderResult& res) {
  // Pin the software rasteriser before Mesa picks a driver (the pipe loader reads these
  // when the first context is created).
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  if (threads > 0) setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                         OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
  guard.ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!guard.ctx) guard.ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);  // stencil: OpenCSG
  if (!guard.ctx) throw std::runtime_error("OSMesa: cannot create a context");
  rgba.assign(std::size_t(W) * H * 4, 0.0f);
  if (!OSMesaMakeCurrent(guard.ctx, rgba.data(), GL_FLOAT, W, H))
    throw std::runtime_error("OSMesa: cannot bind a float RGBA buffer");
  OSMesaPixelStore(OSMESA_Y_UP, 1);
  auto str = [](GLenum e) {
    const GLubyte* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
  };
  res.gl_renderer = str(GL_RENDERER);
  res.gl_version = str(GL_VERSION);
  glGetError();
  res.glsl_version = str(0x8B8C /* GL_SHADING_LANGUAGE_VERSION */);
  glGetError();
}

// Per-vertex arrays of the triangle soup: positions, normals, colours (shaded per vertex
// for Gouraud, the material colour per pixel), (specular, shininess), id colours.
struct VertexArrays {
  std::size_t count = 0;
  std::vector<GLfloat> pos, nor, col, spec, idc;
};

// The id pass's colour of triangle t: its primitive + 1, or, for a triangle of an object
// with no primitive (an exact surface whose pieces view culling removed), the primitive
// count + 1 + its object.
std::uint32_t facetId(const Scene& scene, const TriangleMesh3& mesh, std::size_t t) {
  if (t >= mesh.primitive.size()) return 1u;
  if (mesh.primitive[t] >= 0) return std::uint32_t(mesh.primitive[t] + 1);
  const int object = t < mesh.object.size() ? mesh.object[t] : 0;
  return std::uint32_t(scene.primitives.size() + 1) + std::uint32_t(std::max(object, 0));
}

// Triangles in parallel (each writes its own three vertices: the arrays do not depend on the
// thread count).
VertexArrays vertexArrays(const Scene& scene, const TriangleMesh3& mesh, bool gouraud, int threads) {
  VertexArrays va;
  const std::size_t nv = mesh.triangles.size() * 3;
  va.count = nv;
  va.pos.resize(nv * 3);
  va.nor.resize(nv * 3);
  va.col.resize(nv * 3);
  va.spec.resize(nv * 2);
  va.idc.resize(nv * 3);
  const long triangles = long(mesh.triangles.size());
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (long ti = 0; ti < triangles; ++ti) {
    const std::size_t t = std::size_t(ti);
    const int mi = t < mesh.material.size() ? mesh.material[t] : 0;
    const Material& m = scene.materials[std::size_t(mi) < scene.materials.size() ? std::size_t(mi) : 0];
    const std::uint32_t id = facetId(scene, mesh, t);
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = t * 3 + std::size_t(k);
      const Eigen::Vector3d& p = mesh.positions[std::size_t(mesh.triangles[t][k])];
      const Eigen::Vector3d& n = mesh.normals[std::size_t(mesh.triangles[t][k])];
      for (int c = 0; c < 3; ++c) {
        va.pos[v * 3 + c] = GLfloat(p[c]);
        va.nor[v * 3 + c] = GLfloat(n[c]);
      }
      const Eigen::Vector3d c3 = gouraud ? shadeLinear(scene, m, p, n) : m.color;
      for (int c = 0; c < 3; ++c) va.col[v * 3 + c] = GLfloat(c3[c]);
      va.spec[v * 2] = GLfloat(m.specular);
      va.spec[v * 2 + 1] = GLfloat(m.shininess);
      va.idc[v * 3 + 0] = GLfloat((id >> 16) & 255) / 255.0f;
      va.idc[v * 3 + 1] = GLfloat((id >> 8) & 255) / 255.0f;
      va.idc[v * 3 + 2] = GLfloat(id & 255) / 255.0f;
    }
  }
  return va;
}

// The scene camera's matrices, a strict depth test, no culling, lighting, dithering nor
// blending, unclamped colours; the vertex arrays bound (colours bound by the passes).
void setFixedState(const Scene& scene, int W, int H, const VertexArrays& va) {
  glViewport(0, 0, W, H);
  glDepthRange(0.0, 1.0);
  loadMatrix(GL_PROJECTION, scene.camera.projection(double(W) / double(H)));
  loadMatrix(GL_MODELVIEW, scene.camera.view());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);  // equal depths keep the earlier triangle (scene order)
  glDisable(GL_CULL_FACE);
  glDisable(GL_LIGHTING);
  glDisable(GL_DITHER);
  glDisable(GL_BLEND);
  using ClampColor = void (*)(GLenum, GLenum);
  if (auto clampColor = reinterpret_cast<ClampColor>(OSMesaGetProcAddress("glClampColor"))) {
    clampColor(0x891A /* GL_CLAMP_VERTEX_COLOR */, GL_FALSE);  // keep linear radiance > 1 as is
    clampColor(0x891B /* GL_CLAMP_FRAGMENT_COLOR */, GL_FALSE);
  }
  glGetError();
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, va.pos.data());
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(GL_FLOAT, 0, va.nor.data());
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, va.spec.data());
}

// The per-pixel program in use with the scene's lights (the first kMaxLights) and camera.
void usePerPixelProgram(const ShaderApi& api, GLuint prog, const Scene& scene, FacetRenderResult& res) {
  api.useProgram(prog);
  GLint types[kMaxLights];
  std::vector<GLfloat> vecs(kMaxLights * 3, 0.0f), cols(kMaxLights * 3, 0.0f);
  const int nl = std::min<int>(kMaxLights, int(scene.lights.size()));
  for (int i = 0; i < nl; ++i) {
    const Light& l = scene.lights[std::size_t(i)];
    types[i] = l.type == Light::Type::Ambient ? 0 : (l.type == Light::Type::Directional ? 1 : 2);
    const Eigen::Vector3d v = l.type == Light::Type::Point ? l.position : l.direction;
    for (int c = 0; c < 3; ++c) {
      vecs[std::size_t(i) * 3 + c] = GLfloat(v[c]);
      cols[std::size_t(i) * 3 + c] = GLfloat(l.color[c]);
    }
  }
  for (int i = nl; i < kMaxLights; ++i) types[i] = 0;
  api.uniform1i(api.getUniformLocation(prog, "lightCount"), nl);
  api.uniform1iv(api.getUniformLocation(prog, "lightType"), kMaxLights, types);
  api.uniform3fv(api.getUniformLocation(prog, "lightVec"), kMaxLights, vecs.data());
  api.uniform3fv(api.getUniformLocation(prog, "lightColor"), kMaxLights, cols.data());
  api.uniform1i(api.getUniformLocation(prog, "orthographic"), scene.camera.type == Camera::Type::Orthographic);
  const Eigen::Vector3f eye = scene.camera.eye.cast<float>(), fwd = scene.camera.forward().cast<float>();
  api.uniform3fv(api.getUniformLocation(prog, "eye"), 1, eye.data());
  api.uniform3fv(api.getUniformLocation(prog, "forward"), 1, fwd.data());
  if (int(scene.lights.size()) > kMaxLights)
    res.note = "per-pixel shading uses the first " + std::to_string(kMaxLights) + " lights";
}

// The colour pass read back: sRGB colours top row first, and the depth buffer (GL rows).
void readColour(const Scene& scene, const std::vector<float>& rgba, int W, int H, std::vector<float>& depth,
                FacetRenderResult& res) {
  depth.assign(std::size_t(W) * H, 1.0f);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  res.fb = FrameBuffer(W, H, toSrgb8(scene.background));
  for (int y = 0; y < H; ++y) {
    const int gy = H - 1 - y;  // GL row 0 is the bottom row
    for (int x = 0; x < W; ++x) {
      const std::size_t g = std::size_t(gy) * W + x, i = std::size_t(y) * W + x;
      const float* c = &rgba[g * 4];
      const auto s = toSrgb8(Eigen::Vector3d(c[0], c[1], c[2]));
      for (int k = 0; k < 3; ++k) res.fb.color.data[i * 3 + k] = s[k];
    }
  }
}

// The id pass read back: primitive, object and depth per pixel from the id colours;
// pixels without an id keep the background colour.
void readIds(const Scene& scene, const std::vector<float>& rgba, const std::vector<float>& depth, int W, int H,
             FacetRenderResult& res) {
  for (int y = 0; y < H; ++y) {
    const int gy = H - 1 - y;
    for (int x = 0; x < W; ++x) {
      const std::size_t g = std::size_t(gy) * W + x, i = std::size_t(y) * W + x;
      const float* c = &rgba[g * 4];
      const std::uint32_t id = (std::uint32_t(std::lround(c[0] * 255.0f)) << 16) |
                               (std::uint32_t(std::lround(c[1] * 255.0f)) << 8) | std::uint32_t(std::lround(c[2] * 255.0f));
      if (id == 0) continue;
      const std::size_t prim = std::size_t(id) - 1, nprim = scene.primitives.size();
      if (prim < nprim) {
        res.fb.primitive[i] = int(prim);
        res.fb.object[i] = scene.primitives[prim].object;
      } else if (prim - nprim < scene.objects.size()) {
        res.fb.object[i] = int(prim - nprim);  // an object without primitives (facetId)
      } else {
        continue;
      }
      res.fb.depth[i] = double(depth[g]);
    }
  }
  // Pixels the id pass found empty but the colour pass drew cannot exist (same geometry,
  // same depth test); pixels without an id keep the background colour for consistency.
  const std::array<std::uint8_t, 3> bg8 = toSrgb8(scene.background);
  for (std::size_t i = 0; i < res.fb.pixels(); ++i)
    if (res.fb.object[i] < 0)
      for (int k = 0; k < 3; ++k) res.fb.color.data[i * 3 + k] = bg8[k];
}

// One pass over the scene: every triangle, or, with csg objects, through OpenCSG
// (facet_csg_draw.h), the GLSL program `prog` (0: none) unbound around OpenCSG's passes.
// `colours` is the colour array of the pass.
void drawScene(std::size_t count, const FacetCsgDrawPtr& csg, const ShaderApi& api, GLuint prog,
               const VertexArrays& va, const std::vector<GLfloat>& colours) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
#ifdef QACC_HAVE_OPENCSG
  if (csg) {
    const std::function<void()> bind = [&] {
      glEnableClientState(GL_VERTEX_ARRAY);
      glVertexPointer(3, GL_FLOAT, 0, va.pos.data());
      glEnableClientState(GL_NORMAL_ARRAY);
      glNormalPointer(GL_FLOAT, 0, va.nor.data());
      glEnableClientState(GL_TEXTURE_COORD_ARRAY);
      glTexCoordPointer(2, GL_FLOAT, 0, va.spec.data());
      glEnableClientState(GL_COLOR_ARRAY);
      glColorPointer(3, GL_FLOAT, 0, colours.data());
    };
    csg->draw(bind, [&] { if (prog) api.useProgram(0); }, [&] { if (prog) api.useProgram(prog); });
    glFinish();
    return;
  }
#else
  (void)csg;
  (void)api;
  (void)prog;
  (void)va;
  (void)colours;
#endif
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(count));
  glFinish();
}

}  // namespace

void prepareFacetRenderer() {}

FacetRenderResult renderFacets(const Scene& scene, const TriangleMesh3& mesh, const FacetRenderOptions& options) {
  const auto tSetup = Clock::now();
  const int W = scene.width, H = scene.height;
  FacetRenderResult res;
  res.triangles = mesh.size();
  ContextGuard guard;
  std::vector<float> rgba;
  createContext(guard, rgba, W, H, options.threads, res);
  res.context_ms = msSince(tSetup);
  const auto tUpload = Clock::now();

  ShaderApi api;
  const bool apiLoaded = api.load();
  GLuint prog = 0;
  res.shading_used = FacetShading::Gouraud;
  if (options.shading == FacetShading::PerPixel) {
    prog = perPixelProgram(api, apiLoaded, res.note);
    if (prog) res.shading_used = FacetShading::PerPixel;
  }
  const VertexArrays va = vertexArrays(scene, mesh, res.shading_used == FacetShading::Gouraud, options.threads);
  FacetCsgDrawPtr csg;
  if (!scene.csg_trees.empty()) {
#ifdef QACC_HAVE_OPENCSG
    if (!loadGlewForOpenCsg()) throw std::runtime_error("OSMesa: a GL function OpenCSG needs is missing");
    csg = std::make_unique<FacetCsgDraw>(scene, mesh, options.csg_box_pruning);
    res.csg_pruning = csg->pruning().line();
#else
    throw std::invalid_argument(facetCsgMissingMessage());
#endif
  }
  setFixedState(scene, W, H, va);
  if (prog) usePerPixelProgram(api, prog, scene, res);
  glColorPointer(3, GL_FLOAT, 0, va.col.data());
  glShadeModel(GL_SMOOTH);
  const Eigen::Vector3d bgLinear = scene.background;
  glClearColor(GLfloat(bgLinear.x()), GLfloat(bgLinear.y()), GLfloat(bgLinear.z()), 0.0f);
  glClearDepth(1.0);
  if (va.count >= 3) {  // warm-up: llvmpipe compiles the state's shaders at the first draw
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
  }
  res.upload_ms = msSince(tUpload);

  // Colour pass.
  const auto tDraw = Clock::now();
  drawScene(va.count, csg, api, prog, va, va.col);
  res.draw_ms = msSince(tDraw);
  if (glGetError() != GL_NO_ERROR) throw std::runtime_error("OSMesa: GL error while drawing facets");
  const auto tRead = Clock::now();
  std::vector<float> depth;
  readColour(scene, rgba, W, H, depth, res);
  res.readback_ms = msSince(tRead);

  // Id pass: flat colours = primitive index + 1, no lighting, same depth test.
  const auto tId = Clock::now();
  if (prog) api.useProgram(0);
  glShadeModel(GL_FLAT);
  glColorPointer(3, GL_FLOAT, 0, va.idc.data());
  glClearColor(0, 0, 0, 0);
  drawScene(va.count, csg, api, 0, va, va.idc);
  readIds(scene, rgba, depth, W, H, res);
  res.id_pass_ms = msSince(tId);
  if (prog) api.deleteProgram(prog);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  return res;
}

}  // namespace qacc
