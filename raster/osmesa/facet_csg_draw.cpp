#include "raster/osmesa/facet_csg_draw.h"

#include <GL/glew.h>
#include <opencsg.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "modeling/csg/csg_product_pruning.h"

namespace qacc {

namespace {

// A csg leaf as OpenCSG sees it: its closed mesh, drawn from the bound vertex arrays.
class LeafMesh : public OpenCSG::Primitive {
 public:
  // Convexity 2: a line meets a clipped quadric solid in at most two intervals.
  LeafMesh(OpenCSG::Operation op, const std::vector<unsigned>& vertices, const std::function<void()>& bind)
      : OpenCSG::Primitive(op, 2), v_(vertices), bind_(bind) {}
  void render() override {
    if (v_.empty()) return;
    bind_();
    glDisableClientState(GL_COLOR_ARRAY);  // OpenCSG labels fragments with glColor and the alpha test
    glDrawElements(GL_TRIANGLES, GLsizei(v_.size()), GL_UNSIGNED_INT, v_.data());
  }

 private:
  const std::vector<unsigned>& v_;
  const std::function<void()>& bind_;
};

void drawVertices(const std::vector<unsigned>& v) {
  if (!v.empty()) glDrawElements(GL_TRIANGLES, GLsizei(v.size()), GL_UNSIGNED_INT, v.data());
}

// The view volume in normalised device coordinates, widened by `margin`: what GL can draw.
Eigen::AlignedBox3d viewCube(const Eigen::Vector3d& margin) {
  return Eigen::AlignedBox3d(-Eigen::Vector3d::Ones() - margin, Eigen::Vector3d::Ones() + margin);
}

}  // namespace

std::string FacetCsgPruning::line() const {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "csg: %zu products of the normal forms, %zu skipped (positive leaves' boxes apart), %zu "
                "complemented leaves left out (box apart), %zu drawn with one leaf",
                products, skipped, literals_dropped, single_leaf_products);
  return buf;
}

FacetCsgDraw::FacetCsgDraw(const Scene& scene, const TriangleMesh3& mesh, bool boxPruning)
    : leaf_(scene.primitives.size()), box_(scene.primitives.size()), boxPruning_(boxPruning) {
  std::vector<char> isLeaf(scene.primitives.size(), 0);
  std::vector<CsgNormalForm> forms;
  for (const CsgTree& t : scene.csg_trees) {
    forms.push_back(normalForm(t));
    if (!forms.back().complete)
      throw std::invalid_argument("facets: a csg object's normal form has too many products for OpenCSG");
    for (int p : t.leafPrimitives()) isLeaf[std::size_t(p)] = 1;
  }
  // A leaf's box: its vertices projected as GL projects them (the renderer's matrices), in
  // double. A triangle in front of the eye projects inside its vertices' box; one with a
  // vertex at or behind the eye plane may cover the whole view. Widened by two pixels (GL
  // rounds in float, OpenCSG truncates the box to whole pixels) and 1e-5 in depth.
  const Eigen::Matrix4d toClip = scene.camera.projection(double(scene.width) / double(scene.height)) * scene.camera.view();
  const Eigen::Vector3d margin(4.0 / scene.width, 4.0 / scene.height, 1e-5);
  std::vector<char> behindEye(scene.primitives.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int p = t < mesh.primitive.size() ? mesh.primitive[t] : -1;
    const unsigned v = unsigned(3 * t);
    if (p < 0 || !isLeaf[std::size_t(p)]) {
      plain_.insert(plain_.end(), {v, v + 1, v + 2});
      continue;
    }
    // OpenCSG tells entering from leaving faces by their winding: counter-clockwise seen
    // from outside the solid, where the vertex normals (the quadric's gradient, a cap's
    // plane normal) point.
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.positions[std::size_t(tri[0])];
    const Eigen::Vector3d g = (mesh.positions[std::size_t(tri[1])] - a).cross(mesh.positions[std::size_t(tri[2])] - a);
    const Eigen::Vector3d n = mesh.normals[std::size_t(tri[0])] + mesh.normals[std::size_t(tri[1])] +
                              mesh.normals[std::size_t(tri[2])];
    if (g.dot(n) >= 0) leaf_[std::size_t(p)].insert(leaf_[std::size_t(p)].end(), {v, v + 1, v + 2});
    else leaf_[std::size_t(p)].insert(leaf_[std::size_t(p)].end(), {v, v + 2, v + 1});
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector4d c = toClip * mesh.positions[std::size_t(tri[k])].homogeneous();
      if (!(c.w() > 0)) behindEye[std::size_t(p)] = 1;
      else box_[std::size_t(p)].extend(c.head<3>() / c.w());
    }
  }
  const Eigen::AlignedBox3d view = viewCube(margin);
  for (std::size_t p = 0; p < box_.size(); ++p) {
    if (!isLeaf[p]) continue;
    if (behindEye[p]) box_[p] = view;
    else if (!box_[p].isEmpty()) box_[p] = Eigen::AlignedBox3d(box_[p].min() - margin, box_[p].max() + margin).intersection(view);
  }
  for (const CsgNormalForm& form : forms)
    for (const CsgProduct& product : form.products) {
      ++pruning_.products;
      if (!boxPruning_) {
        products_.push_back(product);
        continue;
      }
      CsgProduct kept = pruneProduct(product, box_);
      if (kept.empty()) {
        ++pruning_.skipped;
        continue;
      }
      pruning_.literals_dropped += product.size() - kept.size();
      pruning_.single_leaf_products += kept.size() == 1;
      products_.push_back(std::move(kept));
    }
}

void FacetCsgDraw::draw(const std::function<void()>& bindArrays, const std::function<void()>& programOff,
                        const std::function<void()>& programOn) const {
  bindArrays();
  drawVertices(plain_);
  OpenCSG::setOption(OpenCSG::AlgorithmSetting, OpenCSG::Goldfeather);
  OpenCSG::setOption(OpenCSG::DepthComplexitySetting, OpenCSG::NoDepthComplexitySampling);
  for (const CsgProduct& product : products_) {
    std::vector<std::unique_ptr<LeafMesh>> leaves;
    std::vector<OpenCSG::Primitive*> prims;
    for (const CsgLiteral& l : product) {
      leaves.push_back(std::make_unique<LeafMesh>(l.complement ? OpenCSG::Subtraction : OpenCSG::Intersection,
                                                  leaf_[std::size_t(l.primitive)], bindArrays));
      if (boxPruning_) {
        const Eigen::AlignedBox3f b = box_[std::size_t(l.primitive)].cast<float>();
        leaves.back()->setBoundingBox(b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z());
      }
      prims.push_back(leaves.back().get());
    }
    programOff();
    OpenCSG::render(prims);
    programOn();
    bindArrays();
    // OpenCSG leaves its own state behind: the depth test on, colour writes on, no
    // culling or stencil, as the renderer draws.
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDepthFunc(GL_EQUAL);
    for (const CsgLiteral& l : product) drawVertices(leaf_[std::size_t(l.primitive)]);
    glDepthFunc(GL_LESS);
  }
  // OpenCSG keeps its frame buffer objects per context key, not per OSMesa context: free
  // them while this context is current, so that the next context does not inherit stale
  // names.
  OpenCSG::freeResources();
}

}  // namespace qacc
