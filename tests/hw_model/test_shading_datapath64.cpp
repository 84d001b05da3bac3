// The shading unit's 64-bit datapath (shadePixel, hw_model/datapath/shading_datapath64.h)
// against the 128-bit reference (shadePixelWide): random configurations, fields, depths,
// caps and lights, in every rounding mode with either normaliser, and the edge cases —
// zero vectors, components at the full coefficient width, a back face (N·V < 0), lights
// behind (N·L <= 0), colours above white and wrapped below zero. And the host's shortcut of
// the reciprocal square root (ReciprocalSqrt::compute64) against the unit as specified.
#include <gtest/gtest.h>

#include <random>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/reciprocal_sqrt.h"
#include "hw_model/datapath/shading_arithmetic.h"
#include "hw_model/datapath/shading_datapath64.h"

using namespace qacc;

namespace {

// A random signed value of at most `bits` bits (sign included), its length uniform: small
// and huge magnitudes alike.
i128 randomValue(std::mt19937_64& rng, int bits) {
  const int len = int(rng() % std::uint64_t(bits));  // magnitude bits, < bits
  if (len == 0) return 0;
  unsigned __int128 m = ((unsigned __int128)rng() << 64) | rng();
  m >>= 128 - len;
  const i128 v = i128(m);
  return rng() & 1 ? -v : v;
}

i128 fullWidth(std::mt19937_64& rng, int bits) {  // the largest magnitude of the width
  const i128 v = (i128(1) << (bits - 1)) - 1;
  return rng() & 1 ? -v - 1 : v;
}

VectorSetup randomField(std::mt19937_64& rng, int w) {
  VectorSetup f;
  const bool huge = rng() % 8 == 0;
  for (int k = 0; k < 3; ++k) {
    f.uv[k].A = huge ? fullWidth(rng, w) : randomValue(rng, w);
    f.uv[k].B = huge ? fullWidth(rng, w) : randomValue(rng, w);
    f.uv[k].C = huge ? fullWidth(rng, w) : randomValue(rng, w);
    f.cz[k] = huge ? fullWidth(rng, w) : randomValue(rng, w);
  }
  if (rng() % 8 == 0) f = VectorSetup();  // the zero vector
  return f;
}

// The opposite field in the same w-bit coefficient registers: -(-2^(w-1)) does not fit them
// and saturates to 2^(w-1) - 1, as setup's quantize would (a coefficient of 2^63 at w = 64 is
// outside the registers the 64-bit datapath reads, and no setup produces it).
VectorSetup negated(const VectorSetup& f, int w) {
  const i128 hi = (i128(1) << (w - 1)) - 1;
  const auto neg = [&](i128 x) { return -x > hi ? hi : -x; };
  VectorSetup g = f;
  for (int k = 0; k < 3; ++k) {
    g.uv[k].A = neg(f.uv[k].A);
    g.uv[k].B = neg(f.uv[k].B);
    g.uv[k].C = neg(f.uv[k].C);
    g.cz[k] = neg(f.cz[k]);
  }
  return g;
}

// Whether every coefficient of f is a value of the w-bit registers setup fills.
bool fitsWidth(const VectorSetup& f, int w) {
  const i128 hi = (i128(1) << (w - 1)) - 1, lo = -hi - 1;
  const auto in = [&](i128 x) { return x >= lo && x <= hi; };
  for (int k = 0; k < 3; ++k)
    if (!in(f.uv[k].A) || !in(f.uv[k].B) || !in(f.uv[k].C) || !in(f.cz[k])) return false;
  return true;
}

Eigen::Vector3d randomDirection(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Vector3d d(n(rng), n(rng), n(rng));
  if (rng() % 6 == 0) d = Eigen::Vector3d::Unit(int(rng() % 3)) * (rng() & 1 ? 1.0 : -1.0);  // on an axis
  return d.norm() > 0 ? d : Eigen::Vector3d(0, 0, 1);
}

// A configuration with random widths within what the validator accepts.
HwConfig randomConfig(std::mt19937_64& rng) {
  HwConfig c;
  auto pick = [&](int lo, int hi) { return lo + int(rng() % std::uint64_t(hi - lo + 1)); };
  c.normal_bits = pick(6, 30);
  c.unit_frac_bits = pick(6, std::min(c.normal_bits, kMaxUnitFracBits));
  c.color_frac_bits = pick(8, 16);
  c.value_bits = pick(12, 40);
  c.interp_frac_bits = pick(0, 32);
  c.depth_frac_bits = pick(12, 36);
  c.depth_bits = std::min(40, c.depth_frac_bits + pick(2, 4));
  c.zbuffer_bits = std::min(c.zbuffer_bits, c.depth_frac_bits);
  c.delta_bits = std::max(c.delta_bits, 2 * c.value_bits - 8);
  c.interp_acc_bits = std::max(c.interp_acc_bits, c.delta_bits + c.interp_frac_bits + 2);
  const Rounding modes[] = {Rounding::Truncate, Rounding::Nearest, Rounding::NearestEven};
  c.rounding = modes[rng() % 3];
  c.shading_normalizer = rng() & 1 ? Normalizer::Newton : Normalizer::Recurrence;
  c.overflow = rng() % 4 == 0 ? OverflowMode::Wrap : OverflowMode::Saturate;
  checkHwConfig(c, "random");
  return c;
}

// Lights and materials: some colours above white (and above the 2^8 the light format holds,
// saturated or wrapped to negative), specular weights up to the ROM's saturation.
Scene randomLighting(std::mt19937_64& rng) {
  Scene scene;
  std::uniform_real_distribution<double> c01(0.0, 1.0);
  const int lights = 1 + int(rng() % 5);
  for (int i = 0; i < lights; ++i) {
    Light l;
    const int t = int(rng() % 5);
    l.type = t == 0 ? Light::Type::Ambient : t <= 2 ? Light::Type::Directional : Light::Type::Point;
    l.direction = randomDirection(rng);
    const double scale = rng() % 6 == 0 ? 300.0 : rng() % 3 == 0 ? 2.0 : 1.0;
    l.color = Eigen::Vector3d(c01(rng), c01(rng), c01(rng)) * scale;
    scene.lights.push_back(l);
  }
  const int materials = 1 + int(rng() % 3);
  for (int i = 0; i < materials; ++i) {
    Material m;
    m.color = Eigen::Vector3d(c01(rng), c01(rng), c01(rng)) * (rng() % 4 == 0 ? 1.5 : 1.0);
    m.specular = rng() % 8 == 0 ? 1e6 : 2.0 * c01(rng);
    m.shininess = 1.0 + 100.0 * c01(rng);
    scene.materials.push_back(m);
    Primitive p;
    p.material = i;
    scene.primitives.push_back(p);  // every material used: each gets its specular ROM
  }
  return scene;
}

// A random configuration with random lights and materials, its quantised lighting, the
// number of point lights (each primitive needs a field for each) and the width of the
// shading fields' coefficients (setup's vectorSetup).
struct RandomShading {
  HwConfig cfg;
  Scene scene;
  LightingSetup L;
  int points = 0;
  int w = 0;
};
RandomShading randomShading(std::mt19937_64& rng) {
  RandomShading r;
  r.cfg = randomConfig(rng);
  r.scene = randomLighting(rng);
  OverflowCounter ovf;
  r.L = LightingSetup::build(r.scene, r.cfg, ovf);
  for (const Light& l : r.scene.lights) r.points += l.type == Light::Type::Point;
  r.w = r.cfg.value_bits + r.cfg.interp_frac_bits + 2;
  return r;
}

}  // namespace

TEST(ReciprocalSqrt, SixtyFourBitShortcutEqualsTheUnit) {
  auto expectSame = [](std::uint64_t L) {
    const ReciprocalSqrt::Result a = ReciprocalSqrt::compute(L), b = ReciprocalSqrt::compute64(L);
    ASSERT_EQ(a.y, b.y) << (unsigned long long)L;
    ASSERT_EQ(a.k, b.k) << (unsigned long long)L;
  };
  for (std::uint64_t L = 0; L < (1u << 20); ++L) expectSame(L);
  for (int b = 0; b < 64; ++b) {  // powers of two and their neighbours, every bit length
    const std::uint64_t p = std::uint64_t(1) << b;
    expectSame(p);
    expectSame(p - 1);
    expectSame(p + 1);
    expectSame(p | (p - 1));
  }
  std::mt19937_64 rng(64);
  for (int i = 0; i < 2000000; ++i) expectSame(rng() >> (rng() % 64));
}

TEST(ShadingUnit, SixtyFourBitDatapathEqualsTheReferenceOnRandomFieldsAndConfigurations) {
  std::mt19937_64 rng(2064);
  int compared = 0, backFaces = 0, zeroNormals = 0, datapath64 = 0;
  for (int trial = 0; trial < 250; ++trial) {
    const RandomShading r = randomShading(rng);
    const auto& [cfg, scene, L, points, w] = r;
    OverflowCounter ovf;
    datapath64 += shadingDatapath64Applies(cfg);
    for (int prim = 0; prim < 8; ++prim) {
      PrimitiveSetup s;
      s.material = int(rng() % (scene.materials.size() + 1));
      if (s.material >= int(scene.materials.size())) s.material = -1;  // out of range: material 0
      s.normal = randomField(rng, w);
      const bool backFace = rng() % 6 == 0;
      s.view = backFace ? negated(s.normal, w) : randomField(rng, w);
      for (int i = 0; i < points; ++i) s.pointLights.push_back(rng() % 6 == 0 ? negated(s.view, w) : randomField(rng, w));
      // The inputs are what setup can produce: coefficients within their registers.
      ASSERT_TRUE(fitsWidth(s.normal, w) && fitsWidth(s.view, w)) << "trial " << trial;
      for (const VectorSetup& f : s.pointLights) ASSERT_TRUE(fitsWidth(f, w)) << "trial " << trial;
      const int planes = int(rng() % 3);
      for (int i = 0; i < planes; ++i) {
        PlaneSetup p;
        for (int k = 0; k < 3; ++k) p.capNormal[k] = randomValue(rng, w);
        s.planes.push_back(p);
      }
      const bool zeroNormal = s.normal.uv[0].A == 0 && s.normal.uv[0].C == 0 && s.normal.cz[0] == 0;
      for (int i = 0; i < 25; ++i) {
        const int u = rng() % 4 == 0 ? 16383 : int(rng() % 2048), v = rng() % 4 == 0 ? 16383 : int(rng() % 2048);
        const i128 z = i128(rng() % (std::uint64_t(1) << (cfg.depth_bits - 1)));
        const int cap = planes > 0 && i % 3 == 0 ? int(rng() % std::uint64_t(planes)) : -1;
        const auto fast = shadePixel(s, L, cfg, u, v, z, cap, ovf);
        const auto ref = shadePixelWide(s, L, cfg, u, v, z, cap);
        ASSERT_EQ(fast, ref) << "trial " << trial << " rounding " << toString(cfg.rounding) << " normaliser "
                             << int(cfg.shading_normalizer) << " normal_bits " << cfg.normal_bits << " unit_frac "
                             << cfg.unit_frac_bits << " value_bits " << cfg.value_bits << " interp_frac "
                             << cfg.interp_frac_bits << " at " << u << "," << v << " cap " << cap;
        ++compared;
        backFaces += cap < 0 && backFace && !zeroNormal;
        zeroNormals += cap < 0 && zeroNormal;
      }
    }
  }
  EXPECT_EQ(compared, 250 * 8 * 25);
  EXPECT_GT(datapath64, 180);  // most configurations take the 64-bit datapath
  EXPECT_GT(backFaces, 60);
  EXPECT_GT(zeroNormals, 60);
}

// The cases a random field seldom produces, built on purpose: a unit normal facing the
// viewer or turned away, lights in front and behind, a light exactly opposite the view
// (L + V = 0), colours above white and below zero.
TEST(ShadingUnit, SixtyFourBitDatapathEqualsTheReferenceOnConstructedCases) {
  auto constant = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    VectorSetup f;
    f.uv[0].C = x;
    f.uv[1].C = y;
    f.uv[2].C = z;
    return f;
  };
  int compared = 0;
  for (Rounding r : {Rounding::Truncate, Rounding::Nearest, Rounding::NearestEven})
    for (Normalizer n : {Normalizer::Newton, Normalizer::Recurrence})
      for (int nb : {6, 16, 23, 24, 30})
        for (OverflowMode o : {OverflowMode::Saturate, OverflowMode::Wrap}) {
          HwConfig cfg;
          cfg.rounding = r;
          cfg.shading_normalizer = n;
          cfg.normal_bits = nb;
          cfg.unit_frac_bits = std::min(nb, 14);
          cfg.overflow = o;
          Scene scene;
          for (const Eigen::Vector3d& d : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 1, 1),
                                           Eigen::Vector3d(-1, 0.5, 0)}) {
            Light l;
            l.type = Light::Type::Directional;
            l.direction = d;
            l.color = Eigen::Vector3d(1.5, 0.7, 200.0);  // above white; the last beyond the format
            scene.lights.push_back(l);
          }
          Light a;
          a.type = Light::Type::Ambient;
          a.color = Eigen::Vector3d(0.3, 0.0, 150.0);
          scene.lights.push_back(a);
          Material m;
          m.color = Eigen::Vector3d(1.0, 0.5, 0.0);
          m.specular = 0.8;
          m.shininess = 20;
          scene.materials = {m};
          scene.primitives.emplace_back();
          OverflowCounter ovf;
          const LightingSetup L = LightingSetup::build(scene, cfg, ovf);
          const std::int64_t big = std::int64_t(1) << 40;
          const VectorSetup fields[] = {constant(0, 0, big),  constant(0, 0, -big), constant(big, big, big),
                                        constant(0, 0, 0),    constant(1, 0, 0),    constant(-1, -1, 1),
                                        constant(3, -5, 7),   constant(-big, 1, 0), constant(big - 1, -big, 1)};
          for (const VectorSetup& N : fields)
            for (const VectorSetup& V : fields) {
              PrimitiveSetup s;
              s.normal = N;
              s.view = V;
              for (int z : {0, 1 << 20})
                ASSERT_EQ(shadePixel(s, L, cfg, 0, 0, z, -1, ovf), shadePixelWide(s, L, cfg, 0, 0, z, -1))
                    << toString(r) << " normaliser " << int(n) << " nb " << nb;
              ++compared;
            }
        }
  EXPECT_EQ(compared, 3 * 2 * 5 * 2 * 81);
}

// shadeSpan (the resolve's path: a run of one primitive's winners along a row, the fields'
// affine parts by forward differences) gives shadePixel's bits (a span of one) and the
// reference's (shadePixelWide) at every pixel of the run, on
// random configurations (those past the 64-bit datapath too), fields of every width, spans
// that start anywhere up to the largest image side, caps and depths changing per pixel.
TEST(ShadingUnit, SpanEqualsThePixelByPixelDatapath) {
  std::mt19937_64 rng(4096);
  int compared = 0, longSpans = 0, capsSeen = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const RandomShading r = randomShading(rng);
    const auto& [cfg, scene, L, points, w] = r;
    OverflowCounter ovf;
    for (int prim = 0; prim < 6; ++prim) {
      PrimitiveSetup s;
      s.material = int(rng() % scene.materials.size());
      s.normal = randomField(rng, w);
      s.view = rng() % 6 == 0 ? negated(s.normal, w) : randomField(rng, w);
      for (int i = 0; i < points; ++i) s.pointLights.push_back(randomField(rng, w));
      const int planes = int(rng() % 3);
      for (int i = 0; i < planes; ++i) {
        PlaneSetup p;
        for (int k = 0; k < 3; ++k) p.capNormal[k] = randomValue(rng, w);
        s.planes.push_back(p);
      }
      for (int span = 0; span < 4; ++span) {
        const int n = 1 + int(rng() % 64);
        const int u = rng() % 4 == 0 ? 16383 - n : int(rng() % 2048), v = rng() % 4 == 0 ? 16383 : int(rng() % 2048);
        std::vector<ZEntry> winners(static_cast<std::size_t>(n));
        for (ZEntry& e : winners) {
          const int cap = planes > 0 && rng() % 3 == 0 ? int(rng() % std::uint64_t(planes)) : -1;
          e.set(i128(rng() % (std::uint64_t(1) << (cfg.depth_bits - 1))), 0, prim, cap);
          capsSeen += cap >= 0;
        }
        std::vector<std::array<std::uint8_t, 3>> rgb(static_cast<std::size_t>(n));
        shadeSpan(s, L, cfg, u, v, n, winners.data(), rgb.data(), ovf);
        for (int i = 0; i < n; ++i) {
          const ZEntry& e = winners[std::size_t(i)];
          ASSERT_EQ(rgb[std::size_t(i)], shadePixel(s, L, cfg, u + i, v, e.depth, int(e.cap), ovf))
              << "trial " << trial << " span of " << n << " at " << u << "," << v << " pixel " << i;
          ASSERT_EQ(rgb[std::size_t(i)], shadePixelWide(s, L, cfg, u + i, v, e.depth, int(e.cap)))
              << "trial " << trial << " span of " << n << " at " << u << "," << v << " pixel " << i;
          ++compared;
        }
        longSpans += n >= 32;
      }
    }
  }
  EXPECT_GT(compared, 120 * 6 * 4 * 16);
  EXPECT_GT(longSpans, 500);
  EXPECT_GT(capsSeen, 1000);
}
