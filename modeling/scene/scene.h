// A loaded scene: image, camera, lights, materials and the flat list of primitives that
// every renderer consumes (design §6). Objects keep which primitives they produced.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "modeling/scene/camera.h"
#include "modeling/csg/csg_tree.h"
#include "modeling/geometry/exact_surface.h"
#include "modeling/scene/light.h"
#include "modeling/scene/material.h"
#include "modeling/geometry/primitive.h"

namespace qacc {

struct SceneObject {
  std::string type;           // scene "type" of the object
  std::size_t first = 0;      // first primitive
  std::size_t count = 0;      // number of primitives
  int material = 0;           // the object's material
  int exact_surface = -1;     // index into Scene::exact_surfaces, or -1
  std::string note;           // the builder's account (ObjectContext::note), may be empty
  // The cells of the object's whole model, whatever view culling kept (ObjectContext::
  // model_cells; 0: not given): the facets engine sizes the mesh of its exact surface by it.
  std::size_t model_cells = 0;
};

struct Scene {
  std::string name = "scene";
  std::string file;  // path it was loaded from (for messages)
  int width = 640;
  int height = 480;
  Eigen::Vector3d background{0.05, 0.05, 0.08};  // linear RGB
  // The frame every coordinate below is held in: world = scene coordinates + origin
  // (scene_origin.h; 0 unless the view is far from the world origin).
  Eigen::Vector3d origin{0, 0, 0};
  Camera camera;
  std::vector<Light> lights;        // never empty after loading (headlight + ambient default)
  std::vector<Material> materials;  // index 0 is the default light grey
  std::vector<Primitive> primitives;
  std::vector<SceneObject> objects;
  // Exact (non-quadric) surfaces the reference renderer draws instead of the pieces of the
  // objects that refer to them (see exact_surface.h).
  std::vector<std::shared_ptr<const ExactSurface>> exact_surfaces;
  // Boolean trees of the `csg` objects (modeling/csg/csg_tree.h); their leaves are
  // primitives of `primitives` that renderers must combine, not draw one by one.
  std::vector<CsgTree> csg_trees;

  // Default lights when a scene gives none: a headlight along the view direction plus ambient.
  static std::vector<Light> defaultLights(const Camera& camera);
};

}  // namespace qacc
