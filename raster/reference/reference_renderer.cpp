#include "raster/reference/reference_renderer.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <limits>

#include "raster/pixel/pixel_hit.h"
#include "raster/pixel/shading.h"
#include "raster/pixel/tile_binner.h"
#include "raster/pixel/window_primitive.h"
#include "raster/reference/csg_hit.h"

namespace qacc {
namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Eigen::Vector3d dehom(const Eigen::Vector4d& X) { return X.head<3>() / X[3]; }

// One thing to draw, in scene order: a primitive or an object's exact surface.
struct Item {
  int primitive = -1;  // index into Scene::primitives (for an exact surface: the object's first, or -1)
  int exact = -1;      // index into Scene::exact_surfaces, or -1
  int csg = -1;        // index into Scene::csg_trees, or -1
  int object = 0;
  int material = 0;
  ScreenBox box;
};

}  // namespace

FrameBuffer renderReference(const Scene& scene, int threads, ReferenceStats* stats) {
  const auto t0 = std::chrono::steady_clock::now();
  const int W = scene.width, H = scene.height;
  const int nthreads = threads > 0 ? threads : omp_get_max_threads();
  const Eigen::Matrix4d M = scene.camera.worldToWindow(W, H);
  const Eigen::Matrix4d Minv = M.inverse();
  const int nprim = int(scene.primitives.size());

  std::vector<WindowPrimitive> win(static_cast<std::size_t>(nprim));
#pragma omp parallel for schedule(dynamic, 16) num_threads(nthreads)
  for (int i = 0; i < nprim; ++i) {
    const Primitive& p = scene.primitives[std::size_t(i)];
    const bool replaced = p.object >= 0 && p.object < int(scene.objects.size()) &&
                          scene.objects[std::size_t(p.object)].exact_surface >= 0;
    if (!replaced) win[std::size_t(i)] = toWindow(p, i, M, Minv, W, H);
  }

  // A CSG object is one item in place of its leaves (csg_hit.h).
  std::vector<int> csgOfObject(scene.objects.size(), -1);
  std::vector<CsgPixelTree> csgTrees;
  for (std::size_t t = 0; t < scene.csg_trees.size(); ++t) {
    csgTrees.emplace_back(scene.csg_trees[t], win, W, H);
    const int obj = scene.csg_trees[t].object;
    if (obj >= 0 && obj < int(csgOfObject.size())) csgOfObject[std::size_t(obj)] = int(t);
  }
  std::vector<bool> csgDone(scene.csg_trees.size(), false);

  // Draw items in scene order; an exact surface takes the place of its object's pieces.
  std::vector<Item> items;
  std::vector<bool> exactDone(scene.exact_surfaces.size(), false);
  auto addExact = [&](int obj) {
    const SceneObject& o = scene.objects[std::size_t(obj)];
    const int e = o.exact_surface;
    if (e < 0 || e >= int(scene.exact_surfaces.size()) || exactDone[std::size_t(e)]) return;
    exactDone[std::size_t(e)] = true;
    Item it;
    it.exact = e;
    it.primitive = o.count > 0 ? int(o.first) : -1;
    it.object = obj;
    it.material = o.material;
    it.box = worldBoxToScreen(scene.exact_surfaces[std::size_t(e)]->bounds(), M, W, H);
    items.push_back(it);
  };
  for (std::size_t obj = 0; obj < scene.objects.size(); ++obj)
    if (scene.objects[obj].count == 0) addExact(int(obj));
  for (int i = 0; i < nprim; ++i) {
    const Primitive& p = scene.primitives[std::size_t(i)];
    if (p.object >= 0 && p.object < int(scene.objects.size()) && scene.objects[std::size_t(p.object)].exact_surface >= 0) {
      addExact(p.object);
      continue;
    }
    const int csg = p.object >= 0 && p.object < int(csgOfObject.size()) ? csgOfObject[std::size_t(p.object)] : -1;
    if (csg >= 0) {
      if (csgDone[std::size_t(csg)]) continue;
      csgDone[std::size_t(csg)] = true;
      Item it;
      it.csg = csg;
      it.primitive = i;
      it.object = p.object;
      it.material = p.material;
      it.box = csgTrees[std::size_t(csg)].box();
      if (!it.box.empty()) items.push_back(it);
      continue;
    }
    const WindowPrimitive& w = win[std::size_t(i)];
    if (w.box.empty()) continue;
    Item it;
    it.primitive = i;
    it.object = p.object;
    it.material = p.material;
    it.box = w.box;
    items.push_back(it);
  }

  TileBinner bins(W, H);
  for (int k = 0; k < int(items.size()); ++k) bins.add(k, items[std::size_t(k)].box);
  if (stats) stats->setup_ms = msSince(t0);

  const auto t1 = std::chrono::steady_clock::now();
  // Frame-sized state is not cleared up front: each tile clears its own rectangle (in
  // parallel, first touching its pages) before drawing, and the tiles cover the frame. The
  // winner of each pixel (item, cap, and the exact surface's normal or the CSG leaf) is
  // tile-local: the tile is shaded when its last item is drawn, so no frame-sized record of
  // the winners is kept (16.6 MB at 1920x1080, 50 MB more with an exact surface).
  const FrameBuffer::Background background(toSrgb8(scene.background));
  FrameBuffer fb = FrameBuffer::uninitialised(W, H);
  constexpr int T = TileBinner::kTileSize;
  const bool anyExact = !scene.exact_surfaces.empty(), anyCsg = !csgTrees.empty();
  long long tests = 0;

#pragma omp parallel num_threads(nthreads) reduction(+ : tests)
  {
    int itemAt[T * T], capAt[T * T];
    std::vector<Eigen::Vector3d> exactNormal(anyExact ? std::size_t(T * T) : 0);
    std::vector<CsgHit> csgAt(anyCsg ? std::size_t(T * T) : 0);  // the winning leaf of a CSG item
#pragma omp for schedule(dynamic, 1)
    for (int t = 0; t < bins.tiles(); ++t) {
      const ScreenBox tile = bins.tile(t);
      fb.clearRect(tile.x0, tile.y0, tile.x1, tile.y1, background);
      std::fill_n(itemAt, T * T, -1);
      // The tile-local index of pixel (x, y).
      const auto at = [&](int x, int y) { return std::size_t((y - tile.y0) * T + (x - tile.x0)); };
      for (int k : bins.bin(t)) {
        const Item& it = items[std::size_t(k)];
        const ScreenBox b = it.box.intersect(tile);
        for (int y = b.y0; y < b.y1; ++y) {
          for (int x = b.x0; x < b.x1; ++x) {
            ++tests;
            const double px = x + 0.5, py = y + 0.5;
            const std::size_t pix = std::size_t(y) * W + x, l = at(x, y);
            if (it.csg >= 0) {
              CsgHit ch;
              if (!csgTrees[std::size_t(it.csg)].hit(px, py, ch) || !(ch.z < fb.depth[pix])) continue;
              fb.depth[pix] = ch.z;
              itemAt[l] = k;
              capAt[l] = ch.cap;
              csgAt[l] = ch;
            } else if (it.exact >= 0) {
              const Eigen::Vector3d p0 = dehom(Minv * Eigen::Vector4d(px, py, 0, 1));
              const Eigen::Vector3d p1 = dehom(Minv * Eigen::Vector4d(px, py, 1, 1));
              ExactHit eh;
              if (!scene.exact_surfaces[std::size_t(it.exact)]->intersect(p0, p1, eh)) continue;
              const Eigen::Vector4d Xw = M * (p0 + eh.t * (p1 - p0)).homogeneous();
              const double z = Xw[2] / Xw[3];
              if (z < 0 || z > 1 || !(z < fb.depth[pix])) continue;
              fb.depth[pix] = z;
              itemAt[l] = k;
              capAt[l] = -1;
              exactNormal[l] = eh.normal;
            } else {
              PixelHit h;
              if (!pixelHit(win[std::size_t(it.primitive)], px, py, h) || !(h.z < fb.depth[pix])) continue;
              fb.depth[pix] = h.z;
              itemAt[l] = k;
              capAt[l] = h.cap;
            }
          }
        }
      }
      // The tile's winners shaded.
      for (int y = tile.y0; y < tile.y1; ++y) {
        for (int x = tile.x0; x < tile.x1; ++x) {
          const std::size_t pix = std::size_t(y) * W + x, l = at(x, y);
          const int k = itemAt[l];
          if (k < 0) continue;
          const Item& it = items[std::size_t(k)];
          const Eigen::Vector3d P = dehom(Minv * Eigen::Vector4d(x + 0.5, y + 0.5, fb.depth[pix], 1));
          Eigen::Vector3d n;
          int material = it.material, primitive = it.primitive;
          if (it.csg >= 0) {
            // The leaf that won colours and orients the surface (flipped where it is subtracted).
            const CsgHit& ch = csgAt[l];
            const Primitive& prim = scene.primitives[std::size_t(ch.primitive)];
            n = ch.cap >= 0 ? Eigen::Vector3d(prim.clip[std::size_t(ch.cap)].p.head<3>()) : prim.quadric.gradient(P);
            n *= double(ch.sign);
            material = prim.material;
            primitive = ch.primitive;
          } else if (it.exact >= 0) {
            n = exactNormal[l];
          } else {
            const Primitive& prim = scene.primitives[std::size_t(it.primitive)];
            n = capAt[l] >= 0 ? Eigen::Vector3d(prim.clip[std::size_t(capAt[l])].p.head<3>())
                              : prim.quadric.gradient(P);
          }
          const int mi = material >= 0 && material < int(scene.materials.size()) ? material : 0;
          const Material fallback;
          const Material& mat = scene.materials.empty() ? fallback : scene.materials[std::size_t(mi)];
          const auto rgb = toSrgb8(shadeLinear(scene, mat, P, n));
          for (int c = 0; c < 3; ++c) fb.color.data[pix * 3 + c] = rgb[std::size_t(c)];
          fb.object[pix] = it.object;
          fb.primitive[pix] = primitive;
        }
      }
    }
  }
  if (stats) {
    stats->visibility_ms = msSince(t1);
    stats->pixel_tests = tests;
  }
  return fb;
}

}  // namespace qacc
