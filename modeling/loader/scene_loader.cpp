#include "modeling/loader/scene_loader.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "modeling/geometry/natural_quadrics.h"
#include "modeling/loader/frame_precision.h"
#include "modeling/loader/object_registry.h"
#include "modeling/geometry/placed_exact_surface.h"
#include "modeling/geometry/unit_plane.h"
#include "modeling/geometry/primitive_bounds.h"
#include "modeling/scene/json_location.h"
#include "modeling/scene/scene_origin.h"
#include "modeling/scene/view_volume.h"
#include "modeling/scene/strict_json.h"
#include "modeling/support/bounded_file.h"

namespace qacc {
namespace {

using nlohmann::json;

// ---------------------------------------------------------------------------------------
// Sections.

Eigen::Vector3d nonNegativeVec3(const JsonNode& n) {
  const Eigen::Vector3d v = n.vec3();
  for (int i = 0; i < 3; ++i)
    if (v[i] < 0) n[std::size_t(i)].fail("expected a non-negative number");
  return v;
}

void readImage(const JsonNode& n, Scene& scene) {
  if (!n.isObject()) n.fail("expected an object with width, height, background");
  if (auto w = n.get("width")) scene.width = int(w->integer(1, kMaxImageSide));
  if (auto h = n.get("height")) scene.height = int(h->integer(1, kMaxImageSide));
  if (static_cast<long long>(scene.width) * scene.height > kMaxImagePixels)
    n.fail("image of " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
           " pixels exceeds the limit of " + std::to_string(kMaxImagePixels) + " pixels");
  if (auto b = n.get("background")) scene.background = b->color();
  n.finish();
}

Camera readCamera(const JsonNode& n) {
  if (!n.isObject()) n.fail("expected an object");
  Camera c;
  const std::string type = n.string("type", "perspective");
  if (type == "perspective") {
    c.type = Camera::Type::Perspective;
    if (auto h = n.get("height")) h->fail("'height' is for orthographic cameras; use 'fov_y_deg'");
    if (auto f = n.get("fov_y_deg")) {
      c.fov_y_deg = f->number();
      if (!(c.fov_y_deg > 0 && c.fov_y_deg < 180)) f->fail("field of view must be in (0, 180) degrees");
    }
  } else if (type == "orthographic") {
    c.type = Camera::Type::Orthographic;
    if (auto f = n.get("fov_y_deg")) f->fail("'fov_y_deg' is for perspective cameras; use 'height'");
    if (auto h = n.get("height")) c.height = h->positive();
  } else {
    n.at("type").fail("unknown camera type '" + type + "' (expected perspective or orthographic)");
  }
  c.eye = n.vec3("eye", c.eye);
  c.target = n.vec3("target", c.target);
  c.up = n.vec3("up", c.up);
  const Eigen::Vector3d view = c.target - c.eye;
  if (!(view.norm() > 0)) (n.has("target") ? n.at("target") : n).fail("target must differ from eye");
  if (!(c.up.norm() > 0)) n.at("up").fail("up must be a non-zero vector");
  if (view.normalized().cross(c.up.normalized()).norm() < 1e-9)
    (n.has("up") ? n.at("up") : n).fail("up is parallel to the view direction");
  if (auto nn = n.get("near")) c.near = nn->positive();
  if (auto ff = n.get("far")) c.far = ff->positive();
  if (!(c.near < c.far)) (n.has("far") ? n.at("far") : n).fail("near must be smaller than far");
  if (c.type == Camera::Type::Perspective && !(c.near > 0))
    n.fail("perspective cameras need near > 0");
  // Perspective window depth is 1 - near/w scaled: with far/near above kMaxFarNearRatio the
  // window-space quadrics lose the depth and the scale they need in double precision (near
  // 1e-5 filled the frame in the reference and blanked a vase in hw; near 1e-7 with far 3e7
  // lost a sphere of radius 1e6 in both). Refused rather than drawn wrong.
  if (c.type == Camera::Type::Perspective && c.far / c.near > kMaxFarNearRatio) {
    std::ostringstream m;
    m << "far / near is " << c.far / c.near << ", above the supported " << kMaxFarNearRatio
      << " (perspective depth precision): raise near or lower far";
    (n.has("near") ? n.at("near") : n).fail(m.str());
  }
  n.finish();
  return c;
}

std::vector<Light> readLights(const JsonNode& n, const Limits& limits) {
  std::vector<Light> lights;
  if (n.isArray() && n.size() > limits.max_lights)
    n.fail(Limits::exceeded("the scene", n.size(), "lights", limits.max_lights, "max-lights"));
  for (const JsonNode& l : n.elements()) {
    if (!l.isObject()) l.fail("expected a light object");
    Light light;
    const std::string type = l.at("type").string();
    if (type == "directional") {
      light.type = Light::Type::Directional;
      const JsonNode d = l.at("direction");
      light.direction = d.vec3();
      if (!(light.direction.norm() > 0)) d.fail("direction must be a non-zero vector");
      light.direction.normalize();
    } else if (type == "point") {
      light.type = Light::Type::Point;
      light.position = l.at("position").vec3();
    } else if (type == "ambient") {
      light.type = Light::Type::Ambient;
      light.color = {0.1, 0.1, 0.1};
    } else {
      l.at("type").fail("unknown light type '" + type + "' (expected directional, point or ambient)");
    }
    if (auto c = l.get("color")) light.color = nonNegativeVec3(*c);
    l.finish();
    lights.push_back(light);
  }
  return lights;
}

void readMaterials(const JsonNode& n, Scene& scene, std::map<std::string, int>& index, const Limits& limits) {
  if (!n.isObject()) n.fail("expected an object mapping names to materials");
  if (n.json().size() > limits.max_materials)
    n.fail(Limits::exceeded("the scene", n.json().size(), "materials", limits.max_materials, "max-materials"));
  for (auto it = n.json().begin(); it != n.json().end(); ++it) {
    const std::string name = it.key();
    const JsonNode m = n.at(name);
    if (name.empty()) m.fail("material name must not be empty");
    if (!m.isObject()) m.fail("expected a material object {color, specular, shininess}");
    Material mat;
    mat.name = name;
    if (auto c = m.get("color")) mat.color = c->color();
    if (auto s = m.get("specular")) mat.specular = s->nonNegative();
    if (auto s = m.get("shininess")) mat.shininess = s->positive();
    m.finish();
    if (name == "default") {
      scene.materials[0] = mat;  // redefines the default material
    } else {
      index[name] = int(scene.materials.size());
      scene.materials.push_back(mat);
    }
  }
  n.finish();
}

struct Placement {
  bool given = false;
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
};

Placement readTransform(const JsonNode& n) {
  if (!n.isObject()) n.fail("expected an object {translate, rotate_deg, scale}");
  Placement t;
  t.given = true;
  const Eigen::Vector3d translate = n.vec3("translate", Eigen::Vector3d::Zero());
  const Eigen::Vector3d rotate = n.vec3("rotate_deg", Eigen::Vector3d::Zero());
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  if (auto s = n.get("scale")) {
    if (s->json().is_number()) {
      const double k = s->number();
      if (k == 0) s->fail("scale must be non-zero (the transform would be singular)");
      scale = Eigen::Vector3d::Constant(k);
    } else {
      scale = s->vec3();
      for (int i = 0; i < 3; ++i)
        if (scale[i] == 0) (*s)[std::size_t(i)].fail("scale must be non-zero (the transform would be singular)");
    }
    const double det = scale.x() * scale.y() * scale.z();
    if (!(std::isfinite(det) && det != 0) || !std::isfinite(1.0 / det))
      s->fail("scale makes the transform singular or non-finite");
  }
  n.finish();
  t.M = placement(translate, rotate, scale);
  if (!t.M.allFinite() || !t.M.inverse().allFinite()) n.fail("transform is singular or non-finite");
  return t;
}

std::vector<HalfSpace> readClip(const JsonNode& n) {
  std::vector<HalfSpace> out;
  for (const JsonNode& c : n.elements()) {
    const Eigen::Vector4d p = c.vec4();
    if (p.head<3>().cwiseAbs().maxCoeff() == 0.0) c.fail("clip plane [a, b, c, d] needs a non-zero normal (a, b, c)");
    out.push_back(unitPlane(HalfSpace(p)));  // scale-free: 1e300 coefficients stay representable
  }
  return out;
}

bool primitiveFinite(const Primitive& p) {
  if (!p.quadric.Q.allFinite()) return false;
  for (const auto& h : p.clip)
    if (!h.p.allFinite()) return false;
  return true;
}

// What readObject and buildObject share: the type's builder called with the common keys
// read, then the object's clip, transform, material and solid flag applied.
struct BuiltObject {
  std::vector<Primitive> prims;
  int material = 0;
  std::string type, note;
  std::size_t model_cells = 0;
  Placement transform;
  std::vector<HalfSpace> clip;
};

// `origin` is the scene's origin for a top-level object (its placement is taken relative to
// it, scene_origin.h) and zero for the parts of another object. `clipWork` (top-level
// objects): the scene's clip work so far (Limits::max_clip_work), this object's added.
BuiltObject buildPrimitives(const JsonNode& o, int objectIndex, Scene& scene, const std::map<std::string, int>& materials,
                            const std::string& directory, const Limits& limits, const ViewVolume* worldView,
                            const Eigen::Vector3d& origin, const ScreenView* screen, std::size_t* clipWork) {
  if (!o.isObject()) o.fail("expected an object with a \"type\"");
  BuiltObject out;
  const JsonNode typeNode = o.at("type");
  out.type = typeNode.string();
  const ObjectBuilder* builder = findObjectBuilder(out.type);
  if (!builder) {
    std::string known;
    for (const auto& t : objectTypes()) known += (known.empty() ? "" : ", ") + t;
    typeNode.fail("unknown object type '" + out.type + "' (known types: " + known + ")");
  }
  if (auto nm = o.get("name")) nm->string();
  bool has_material = false;
  if (auto m = o.get("material")) {
    const std::string name = m->string();
    if (name != "default") {
      auto it = materials.find(name);
      if (it == materials.end()) m->fail("unknown material '" + name + "'");
      out.material = it->second;
    }
    has_material = true;
  }
  const bool solid = o.boolean("solid", false);
  if (auto t = o.get("transform")) out.transform = readTransform(*t);
  if (!origin.isZero()) {
    // Relative to the scene's origin: the translation loses the origin before any quadric is
    // formed, so the coefficients stay of the object's own size.
    out.transform.M.topRightCorner<3, 1>() -= origin;
    out.transform.given = true;
  }
  if (auto c = o.get("clip")) {
    out.clip = readClip(*c);
    // Refused before the builder makes pieces with them (each piece's bounds cost this).
    const std::size_t work = Limits::clipWork(out.clip.size());
    if (work > limits.max_clip_work)
      c->fail(Limits::exceeded("a piece with these " + std::to_string(out.clip.size()) + " clip planes", work,
                               "clip-polyhedron plane tests", limits.max_clip_work, "max-clip-work"));
  }

  ObjectContext ctx{scene, directory, out.material, solid, has_material, {}, limits};
  // Parts of a csg tree stay whole: culling is for top-level objects other than csg.
  std::optional<ViewVolume> localView;
  if (worldView && out.type != "csg") {
    localView = out.transform.given ? worldView->inFrame(out.transform.M) : *worldView;
    ctx.view = &*localView;
  }
  try {
    out.prims = (*builder)(o, ctx);
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {
    o.fail(std::string("cannot build ") + out.type + ": " + e.what());
  }
  o.finish();
  out.note = ctx.note;
  out.model_cells = ctx.model_cells;
  for (Primitive& p : out.prims) {
    // A plane listed twice (in "clip", or already the builder's) is added once: the pair
    // bounds nothing more, and the accelerator's cap logic lost the cap on such a tie (a
    // solid showed its inner wall, 29 dB, with unchanged coverage).
    for (const HalfSpace& h : out.clip) {
      bool listed = false;
      for (const HalfSpace& k : p.clip) listed = listed || (k.p == h.p && k.owns_boundary == h.owns_boundary);
      if (!listed) p.clip.push_back(h);
    }
    if (out.transform.given) p = p.transformed(out.transform.M);
    if (p.material == 0) p.material = out.material;
    p.solid = p.solid || solid;
    p.object = objectIndex;
    if (!primitiveFinite(p)) o.fail("object produces non-finite coefficients (sizes or scales too extreme)");
    if (p.quadric.Q.topLeftCorner<3, 4>().cwiseAbs().maxCoeff() == 0.0)
      o.fail("object degenerates to a constant (sizes or scales too extreme for double precision)");
  }
  // The scene's clip work so far, counted before the pieces' bounds are computed below.
  if (clipWork) {
    std::size_t work = *clipWork;
    for (const Primitive& p : out.prims) work = Limits::addSaturated(work, Limits::clipWork(p.clip.size()));
    if (work > limits.max_clip_work)
      o.fail(Limits::exceeded("the scene", work, "clip-polyhedron plane tests", limits.max_clip_work, "max-clip-work"));
    *clipWork = work;
  }
  // A top-level object's frame may give precision away (frame_precision.h): checked on the
  // pieces that reach the view.
  std::optional<FramePrecision> precision;
  if (screen) precision.emplace(out.transform.given ? out.transform.M : Eigen::Matrix4d::Identity(), *screen);
  if (ctx.view || precision) {
    // What the builder emitted beyond the view: a piece whose exact world bounds (padded,
    // primitive_bounds.h) miss the widened view volume cannot reach a pixel. The pieces kept
    // move to the front of the list, in their order.
    std::size_t kept = 0;
    auto keep = [&](Primitive& p) {
      if (&out.prims[kept] != &p) out.prims[kept] = std::move(p);
      ++kept;
    };
    for (Primitive& p : out.prims) {
      const PrimitiveBounds b = primitiveBounds(p);
      recordWorldBox(p, b);  // for each frame's setup (window_primitive.h)
      if (!b.bounded || b.empty) {
        keep(p);
        continue;
      }
      if (ctx.view && !worldView->mayContain(b.box)) continue;
      if (precision) {
        const double px = precision->pixels(b.box);
        if (px > kMaxFrameErrorPixels) {
          std::ostringstream m;
          m << "a piece of this object lies so far from its frame's origin that double precision leaves its surface "
            << px << " pixels uncertain (at most " << kMaxFrameErrorPixels
            << " supported): give its position with \"transform\": {\"translate\": ...} rather than in its own "
               "coordinates (docs/SCENES.md, scenes far from the world origin)";
          o.fail(m.str());
        }
      }
      keep(p);
    }
    out.prims.erase(out.prims.begin() + std::ptrdiff_t(kept), out.prims.end());
  }
  return out;
}

void readObject(const JsonNode& o, std::size_t index, Scene& scene, const std::map<std::string, int>& materials,
                const std::string& directory, const Limits& limits, const ViewVolume* view, const ScreenView& screen,
                std::size_t& clipWork) {
  const std::size_t exactBefore = scene.exact_surfaces.size();
  BuiltObject built =
      buildPrimitives(o, int(index), scene, materials, directory, limits, view, scene.origin, &screen, &clipWork);
  if (scene.primitives.size() + built.prims.size() > limits.max_primitives)
    o.fail(Limits::exceeded("the scene", scene.primitives.size() + built.prims.size(), "primitives",
                            limits.max_primitives, "max-primitives"));

  SceneObject so;
  so.type = built.type;
  so.first = scene.primitives.size();
  so.count = built.prims.size();
  so.material = built.material;
  so.note = built.note;
  so.model_cells = built.model_cells;
  if (scene.exact_surfaces.size() > exactBefore) {
    // The builder gave the object's true surface (exact_surface.h): place and clip it like the pieces.
    so.exact_surface = int(scene.exact_surfaces.size()) - 1;
    auto& es = scene.exact_surfaces.back();
    if (built.transform.given || !built.clip.empty())
      es = std::make_shared<PlacedExactSurface>(es, built.transform.given ? built.transform.M : Eigen::Matrix4d::Identity(),
                                                built.clip);
  }
  for (Primitive& p : built.prims) scene.primitives.push_back(std::move(p));
  scene.objects.push_back(so);
}

std::string stem(const std::string& file) {
  std::string base = file;
  const auto slash = base.find_last_of('/');
  if (slash != std::string::npos) base = base.substr(slash + 1);
  const auto dot = base.find_last_of('.');
  if (dot != std::string::npos && dot > 0) base = base.substr(0, dot);
  return base.empty() ? "scene" : base;
}

}  // namespace

std::vector<Primitive> buildObject(const JsonNode& o, ObjectContext& parent, int objectIndex) {
  std::map<std::string, int> materials;
  for (std::size_t i = 1; i < parent.scene.materials.size(); ++i) materials.emplace(parent.scene.materials[i].name, int(i));
  const std::size_t exactBefore = parent.scene.exact_surfaces.size();
  BuiltObject built = buildPrimitives(o, objectIndex, parent.scene, materials, parent.directory, parent.limits, nullptr,
                                      Eigen::Vector3d::Zero(), nullptr, nullptr);
  if (parent.scene.exact_surfaces.size() > exactBefore)
    o.fail("a '" + built.type + "' object has a non-quadric exact surface and cannot be a part of another object");
  return std::move(built.prims);
}

namespace {

// parseScene without the text positions of its errors.
Scene buildScene(const std::string& text, const std::string& file, const std::string& directory,
                 const Limits& limits, const ViewCulling& culling) {
  const json doc = parseStrictJson(text, file);
  const JsonNode root(doc, "", std::make_shared<const std::string>(file));
  if (!root.isObject()) root.fail("a scene must be a JSON object");

  Scene scene;
  scene.file = file;
  scene.name = stem(file);
  scene.materials = {Material{}};

  const JsonNode format = root.at("format");
  if (format.string() != "qacc-scene/1")
    format.fail("unsupported format '" + format.string() + "' (expected \"qacc-scene/1\")");
  if (auto n = root.get("name")) scene.name = n->string();
  if (auto d = root.get("description")) d->string();
  if (auto img = root.get("image")) readImage(*img, scene);
  scene.camera = readCamera(root.at("camera"));
  if (auto l = root.get("lights")) scene.lights = readLights(*l, limits);
  if (scene.lights.empty()) scene.lights = Scene::defaultLights(scene.camera);
  // Everything from here on is relative to the scene's origin (scene_origin.h).
  scene.origin = sceneOrigin(scene.camera);
  scene.camera.eye -= scene.origin;
  scene.camera.target -= scene.origin;
  for (Light& l : scene.lights)
    if (l.type == Light::Type::Point) l.position -= scene.origin;

  std::map<std::string, int> materials;
  if (auto m = root.get("materials")) readMaterials(*m, scene, materials, limits);

  const JsonNode objects = root.at("objects");
  const std::size_t n = objects.size();
  scene.objects.reserve(n);
  scene.primitives.reserve(n);  // at least one each; large scenes are mostly simple objects
  // The size the scene is rendered at: what view culling and the frame's precision are judged at.
  const int width = culling.width > 0 ? culling.width : scene.width;
  const int height = culling.height > 0 ? culling.height : scene.height;
  std::optional<ViewVolume> view;
  if (culling.enabled) view = ViewVolume::of(scene.camera, width, height);
  const ScreenView screen(scene.camera, width, height);
  std::size_t clipWork = 0;  // Limits::max_clip_work
  for (std::size_t i = 0; i < n; ++i)
    readObject(objects[i], i, scene, materials, directory, limits, view ? &*view : nullptr, screen, clipWork);
  root.finish();
  return scene;
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& file, const std::string& directory,
                 const Limits& limits, const ViewCulling& culling) {
  try {
    return buildScene(text, file, directory, limits, culling);
  } catch (const SceneError& e) {
    // An error in this scene's text gets the line and column of the value its path names.
    // Syntax errors carry theirs already; errors of the files a scene names (OBJ, PDB) are
    // about those files.
    if (e.file() != file || e.problem().rfind("JSON syntax error", 0) == 0) throw;
    throw SceneError(e.file(), e.jsonPath(), withTextPosition(e.problem(), text, e.jsonPath()));
  }
}

std::string readSceneText(const std::string& path, const Limits& limits) {
  try {
    return readFileBounded(path, limits.max_input_bytes, "scene file");
  } catch (const FileReadError& e) {
    throw SceneError(path, "/", e.what());
  }
}

std::string sceneDirectory(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

Scene loadScene(const std::string& path, const Limits& limits, const ViewCulling& view) {
  return parseScene(readSceneText(path, limits), path, sceneDirectory(path), limits, view);
}

}  // namespace qacc
