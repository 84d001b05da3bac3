// Reference renderer against analytic answers.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "modeling/geometry/natural_quadrics.h"
#include "raster/reference/reference_renderer.h"

using namespace qacc;

namespace {

Scene baseScene(int w, int h) {
  Scene s;
  s.width = w;
  s.height = h;
  s.materials = {Material{}};
  s.lights = Scene::defaultLights(s.camera);
  return s;
}

void add(Scene& s, Primitive p) {
  p.object = int(s.objects.size());
  SceneObject o;
  o.type = "test";
  o.first = s.primitives.size();
  o.count = 1;
  s.objects.push_back(o);
  s.primitives.push_back(std::move(p));
}

Eigen::Vector3d windowToWorld(const Scene& s, double x, double y, double z) {
  const Eigen::Matrix4d Minv = s.camera.worldToWindow(s.width, s.height).inverse();
  return (Minv * Eigen::Vector4d(x, y, z, 1)).hnormalized();
}

}  // namespace

TEST(ReferenceRenderer, OrthographicSphereAreaIsPiRSquared) {
  Scene s = baseScene(301, 301);
  s.camera.type = Camera::Type::Orthographic;
  s.camera.eye = {0, 0, 10};
  s.camera.height = 3.01;  // 100 px per world unit
  add(s, makeSphere({0, 0, 0}, 1.0));  // r = 100 px
  const FrameBuffer fb = renderReference(s, 2);
  const double r = 100.0;
  const double covered = double(fb.covered());
  EXPECT_LT(std::abs(covered - M_PI * r * r), 2 * M_PI * r) << covered;
  // Every covered pixel centre lies inside the disc and vice versa (exactly, up to ties).
  int wrong = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const double dx = (x + 0.5 - 150.5) / 100.0, dy = (y + 0.5 - 150.5) / 100.0;
      const bool inside = dx * dx + dy * dy <= 1.0;
      if (std::abs(dx * dx + dy * dy - 1.0) < 1e-9) continue;
      wrong += inside != (fb.object[std::size_t(y) * s.width + x] >= 0);
    }
  EXPECT_EQ(wrong, 0);
}

TEST(ReferenceRenderer, PerspectiveSphereSilhouetteIsTheAnalyticEllipse) {
  Scene s = baseScene(640, 480);
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.fov_y_deg = 60;
  const Eigen::Vector3d c(2.0, 0.8, -6.0);
  const double R = 1.2;
  add(s, makeSphere(c, R));
  const FrameBuffer fb = renderReference(s, 2);

  // Independent per-pixel test: does the eye ray through the pixel centre meet the sphere?
  const double t = std::tan(s.camera.fov_y_deg * M_PI / 360.0), aspect = 640.0 / 480.0;
  int mismatches = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const double nx = 2 * (x + 0.5) / s.width - 1, ny = 1 - 2 * (y + 0.5) / s.height;
      const Eigen::Vector3d d = Eigen::Vector3d(nx * t * aspect, ny * t, -1).normalized();
      const double dist2 = (c - c.dot(d) * d).squaredNorm();
      if (std::abs(dist2 - R * R) < 1e-9) continue;  // on the silhouette itself
      mismatches += (dist2 <= R * R) != (fb.object[std::size_t(y) * s.width + x] >= 0);
    }
  EXPECT_EQ(mismatches, 0);

  // Area of the ellipse: semi-axes f sinα cosα / (cos²θ − sin²α) and f sinα / √(cos²θ − sin²α).
  const double f = s.height / (2 * t);
  const double sa = R / c.norm(), ca = std::sqrt(1 - sa * sa);
  const double ct = -c.z() / c.norm();
  const double den = ct * ct - sa * sa;
  const double A = f * sa * ca / den, B = f * sa / std::sqrt(den);
  const double perimeter = M_PI * (3 * (A + B) - std::sqrt((3 * A + B) * (A + 3 * B)));
  EXPECT_LT(std::abs(double(fb.covered()) - M_PI * A * B), perimeter) << fb.covered() << " vs " << M_PI * A * B;
}

TEST(ReferenceRenderer, DepthAtKnownPoints) {
  // Orthographic: window depth is linear in eye distance.
  Scene s = baseScene(101, 101);
  s.camera.type = Camera::Type::Orthographic;
  s.camera.eye = {0, 0, 10};
  s.camera.height = 10;
  s.camera.near = 1;
  s.camera.far = 21;
  add(s, makeSphere({0, 0, 0}, 2));
  FrameBuffer fb = renderReference(s, 1);
  EXPECT_NEAR(fb.depth[50 * 101 + 50], (8.0 - 1.0) / 20.0, 1e-12);
  // Off-centre pixel: the sphere point at (x, y) has z = √(4 − x² − y²).
  {
    const double x = (60 + 0.5 - 50.5) * 10.0 / 101.0, y = -(45 + 0.5 - 50.5) * 10.0 / 101.0;
    const double zs = std::sqrt(4 - x * x - y * y);
    EXPECT_NEAR(fb.depth[45 * 101 + 60], (10 - zs - 1.0) / 20.0, 1e-12);
  }
  // Perspective: z_win = ((f+n)/(f−n) − 2fn/((f−n) d) + 1) / 2 for eye distance d.
  s.camera.type = Camera::Type::Perspective;
  s.camera.fov_y_deg = 45;
  fb = renderReference(s, 1);
  const double n = 1, F = 21, d = 8;
  EXPECT_NEAR(fb.depth[50 * 101 + 50], ((F + n) / (F - n) - 2 * F * n / ((F - n) * d) + 1) / 2, 1e-12);
  EXPECT_TRUE(std::isinf(fb.depth[0]));
}

TEST(ReferenceRenderer, SolidCapLiesExactlyOnItsClipPlane) {
  Scene s = baseScene(200, 200);
  s.camera.eye = {3, 4, 5};
  Primitive cyl = makeCylinder({0, -1, 0}, {0, 1, 0}, 0.7);
  const HalfSpace cut(Eigen::Vector4d(0.3, 1, 0.2, -0.4));
  cyl.clip.push_back(cut);
  cyl.solid = true;
  add(s, cyl);
  const FrameBuffer fb = renderReference(s, 2);
  int capPixels = 0, surfacePixels = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const std::size_t i = std::size_t(y) * s.width + x;
      if (fb.object[i] < 0) continue;
      const Eigen::Vector3d P = windowToWorld(s, x + 0.5, y + 0.5, fb.depth[i]);
      const double onSurface = std::abs(cyl.quadric.eval(P));
      const double onCut = std::abs(cut.eval(P));
      if (onSurface < 1e-6) {
        ++surfacePixels;
      } else {
        ++capPixels;
        EXPECT_LT(onCut, 1e-9) << "pixel " << x << "," << y;
        EXPECT_LE(P.x() * P.x() + P.z() * P.z(), 0.49 + 1e-9);
      }
    }
  EXPECT_GT(capPixels, 1000);
  EXPECT_GT(surfacePixels, 1000);
  // The same cylinder as a surface shows no cap: every hit is on the quadric.
  s.primitives[0].solid = false;
  const FrameBuffer open = renderReference(s, 2);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const std::size_t i = std::size_t(y) * s.width + x;
      if (open.object[i] < 0) continue;
      EXPECT_LT(std::abs(cyl.quadric.eval(windowToWorld(s, x + 0.5, y + 0.5, open.depth[i]))), 1e-6);
    }
}

TEST(ReferenceRenderer, HalfSpaceKeepsTheNegativeSide) {
  Scene s = baseScene(120, 120);
  s.camera.eye = {6, 1, 0.5};
  Primitive sph = makeSphere({0, 0, 0}, 1);
  sph.clip.push_back(HalfSpace(Eigen::Vector4d(0, 0, 1, 0)));  // keep z <= 0
  add(s, sph);
  const FrameBuffer fb = renderReference(s, 1);
  int hits = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const std::size_t i = std::size_t(y) * s.width + x;
      if (fb.object[i] < 0) continue;
      ++hits;
      EXPECT_LE(windowToWorld(s, x + 0.5, y + 0.5, fb.depth[i]).z(), 1e-9);
    }
  EXPECT_GT(hits, 500);
}

TEST(ReferenceRenderer, EqualDepthKeepsTheEarlierPrimitive) {
  Scene s = baseScene(64, 64);
  add(s, makeSphere({0, 0, 0}, 1));
  add(s, makeSphere({0, 0, 0}, 1));
  const FrameBuffer fb = renderReference(s, 2);
  std::size_t first = 0;
  for (auto o : fb.object) first += o == 0;
  EXPECT_EQ(first, fb.covered());
  EXPECT_GT(first, 100u);
}

TEST(ReferenceRenderer, SphereAroundTheEyeAndNearPlane) {
  // The eye inside a sphere: it becomes a two-sheeted hyperboloid in window space; the
  // whole image sees the inside of the sphere.
  Scene s = baseScene(80, 60);
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  add(s, makeSphere({0.1, 0, 0}, 3));
  const FrameBuffer fb = renderReference(s, 2);
  EXPECT_EQ(fb.covered(), fb.pixels());
  for (double z : fb.depth) EXPECT_TRUE(z >= 0 && z <= 1);
}

TEST(ReferenceRenderer, ByteIdenticalForAnyThreadCount) {
  Scene s = baseScene(320, 240);
  s.camera.eye = {0, 3, 12};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3, 3), r(0.2, 0.9);
  for (int i = 0; i < 60; ++i) {
    Primitive p = makeSphere({u(rng), u(rng), u(rng)}, r(rng));
    if (i % 3 == 0) {
      p = makeCylinder({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, r(rng) / 2);
      p.solid = i % 2 == 0;
    }
    add(s, p);
  }
  const FrameBuffer a = renderReference(s, 1), b = renderReference(s, 2), c = renderReference(s, 3);
  EXPECT_EQ(a.color.data, b.color.data);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.object, b.object);
  EXPECT_EQ(a.color.data, c.color.data);
  EXPECT_EQ(a.primitive, c.primitive);
  EXPECT_GT(a.covered(), 10000u);
}
