// OpenCSG (Debian libopencsg-dev) on an OSMesa (llvmpipe) context: what the facets engine
// would need to draw csg scenes as triangles (docs/CSG.md, "Triangles"). OpenCSG calls
// OpenGL extensions through GLEW's function pointers and flags, which glewInit() cannot
// fill in an OSMesa context (Debian's GLEW is built for GLX: "Missing GL version"); they
// are loaded through OSMesaGetProcAddress (raster/osmesa/opencsg_glew.h). A box minus a box, orthographic, with the
// Goldfeather and the SCS algorithm: the pixels of each box's visible surface, counted.
#include <GL/glew.h>
// glew.h leaves GLAPI undefined, which osmesa.h needs.
#ifndef GLAPI
#define GLAPI extern
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#include <GL/osmesa.h>
#include <gtest/gtest.h>
#include <opencsg.h>

#include <vector>

#include "raster/osmesa/opencsg_glew.h"

using namespace qacc;

namespace {

// An axis-aligned cube (centre, half-size) as 6 quads, outward facing.
class Cube : public OpenCSG::Primitive {
 public:
  Cube(OpenCSG::Operation op, float x, float y, float z, float h) : OpenCSG::Primitive(op, 1), c_{x, y, z}, h_(h) {}
  void render() override {
    static const float q[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    glBegin(GL_QUADS);
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        const int b = (a + 1) % 3, d = (a + 2) % 3;
        for (int k = 0; k < 4; ++k) {
          float v[3];
          v[a] = c_[a] + float(s) * h_;
          v[b] = c_[b] + q[k][0] * h_;
          v[d] = c_[d] + q[k][1] * h_ * float(s);
          glVertex3fv(v);
        }
      }
    glEnd();
  }

 private:
  float c_[3], h_;
};

struct Counts {
  int first = 0, subtracted = 0;
};

Counts boxMinusBox(int algorithm) {
  constexpr int W = 64, H = 64;
  std::vector<unsigned char> rgba(std::size_t(W) * H * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  EXPECT_NE(ctx, nullptr);
  if (!ctx) return {};
  EXPECT_TRUE(OSMesaMakeCurrent(ctx, rgba.data(), GL_UNSIGNED_BYTE, W, H));
  EXPECT_TRUE(loadGlewForOpenCsg());
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2, 2, -2, 2, -10, 10);  // 16 pixels per unit
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  Cube a(OpenCSG::Intersection, 0, 0, 0, 1), b(OpenCSG::Subtraction, 0.5f, 0.5f, 0.5f, 0.75f);
  std::vector<OpenCSG::Primitive*> product{&a, &b};
  OpenCSG::setOption(OpenCSG::AlgorithmSetting, algorithm);
  OpenCSG::setOption(OpenCSG::DepthComplexitySetting, OpenCSG::NoDepthComplexitySampling);
  OpenCSG::render(product);
  // Shade each primitive where its surface is the product's depth.
  glDepthFunc(GL_EQUAL);
  glColor3f(1, 0, 0);
  a.render();
  glColor3f(0, 1, 0);
  b.render();
  glFinish();
  Counts c;
  for (std::size_t i = 0; i < std::size_t(W) * H; ++i) {
    c.first += rgba[4 * i] > 128;
    c.subtracted += rgba[4 * i + 1] > 128;
  }
  OpenCSG::freeResources();
  OSMesaDestroyContext(ctx);
  return c;
}

}  // namespace

// [-1, 1]^3 minus the cube of half-size 0.75 at (0.5, 0.5, 0.5), seen along -z: the notch
// covers x, y in [-0.25, 1] (20 x 20 pixels), where the subtracted cube's back face at
// z = -0.25 shows; the rest of the 32 x 32 square is the first cube's front face.
TEST(OpenCsgOnOsmesa, GoldfeatherDrawsABoxMinusABox) {
  const Counts c = boxMinusBox(OpenCSG::Goldfeather);
  EXPECT_EQ(c.subtracted, 20 * 20);
  EXPECT_EQ(c.first, 32 * 32 - 20 * 20);
}

TEST(OpenCsgOnOsmesa, ScsDrawsABoxMinusABox) {
  const Counts c = boxMinusBox(OpenCSG::SCS);
  EXPECT_EQ(c.subtracted, 20 * 20);
  EXPECT_EQ(c.first, 32 * 32 - 20 * 20);
}
