// The pixel datapath's host fast path (PixelDatapath::evaluateSpan: the primitive's kind and
// 64-bit registers chosen per primitive) against the straightforward datapath (evaluate() and
// stepRight(): 128-bit registers, every test per pixel), outcome by outcome and counter by
// counter: on the shipped scenes under configurations that cover the rounding modes, depth
// variants, overflow modes and the narrow and wide widths; on random primitives whose values
// reach the registers' limits (overflows, clamps, wrap); and the arithmetic it relies on
// (divRound64ByReciprocal, the 64-bit square root) at its edges.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "hw_model/datapath/pixel_datapath.h"
#include "hw_model/datapath/sqrt_extractor.h"
#include "hw_model/engines/frame_setup.h"
#include "modeling/loader/scene_loader.h"
#include "tests/hw_model/exact_div_round.h"

using namespace qacc;

namespace {

bool sameCounter(const OverflowCounter& a, const OverflowCounter& b) {
  return a.events == b.events && a.zeroed == b.zeroed && a.coarse == b.coarse;
}

bool sameCounters(const OverflowCounters& a, const OverflowCounters& b) {
  return sameCounter(a.setup, b.setup) && sameCounter(a.interpolator, b.interpolator) && sameCounter(a.sqrt, b.sqrt) &&
         sameCounter(a.depth, b.depth) && sameCounter(a.clip, b.clip) && sameCounter(a.shading, b.shading) &&
         a.depth_clamps == b.depth_clamps && a.depth_floor_clamps == b.depth_floor_clamps;
}

// Every pixel of [0, width) x [0, rows) in local coordinates, the fast path in pieces of
// `piece` pixels (a datapath reused across primitives: `fast`), the reference per pixel.
// Returns the number of differing pixels (0) and adds the outcomes' hits to *hits.
int compareBox(PixelDatapath& fast, const PrimitiveSetup& s, const HwConfig& cfg, int width, int rows, int piece,
               OverflowCounters& ovfFast, OverflowCounters& ovfRef, long* hits) {
  fast.load(s);
  PixelDatapath ref(s, cfg);
  std::vector<PixelOutcome> out(std::size_t(piece) + 1);
  int bad = 0;
  for (int v = 0; v < rows; ++v) {
    ref.startSpan(0, v);
    for (int u0 = 0; u0 < width; u0 += piece) {
      const int n = std::min(piece, width - u0);
      fast.evaluateSpan(u0, v, n, out.data(), ovfFast);
      for (int i = 0; i < n; ++i) {
        const PixelOutcome r = ref.evaluate(ovfRef);
        ref.stepRight();
        const PixelOutcome& f = out[std::size_t(i)];
        const bool same = f.candidate == r.candidate && f.hit == r.hit && f.cap == r.cap && f.z == r.z &&
                          f.clipPasses == r.clipPasses;
        if (!same && bad++ < 5)
          ADD_FAILURE() << "primitive " << s.index << " pixel (" << u0 + i << ", " << v << "): fast hit " << f.hit
                        << " cand " << f.candidate << " cap " << f.cap << " z " << std::int64_t(f.z) << " clip "
                        << f.clipPasses << ", reference hit " << r.hit << " cand " << r.candidate << " cap " << r.cap
                        << " z " << std::int64_t(r.z) << " clip " << r.clipPasses;
        *hits += r.hit;
      }
    }
  }
  return bad;
}

HwConfig configNamed(const std::string& name) {
  HwConfig c;
  c.name = name;
  if (name == "minimal") {  // configs/minimal.json's widths: truncate, reciprocal
    c.value_bits = 24, c.delta_bits = 48, c.interp_frac_bits = 16, c.interp_acc_bits = 70;
    c.depth_frac_bits = 24, c.depth_bits = 28, c.clip_bits = 24, c.recip_bits = 24, c.zbuffer_bits = 16;
    c.rounding = Rounding::Truncate;
    c.depth_variant = DepthVariant::Reciprocal;
    c.clip_evaluators = 2;
  } else if (name == "wide") {  // configs/wide.json's widths: the 128-bit host path
    c.value_bits = 36, c.delta_bits = 72, c.interp_frac_bits = 28, c.interp_acc_bits = 104;
    c.depth_frac_bits = 32, c.depth_bits = 36, c.clip_bits = 36, c.recip_bits = 36, c.zbuffer_bits = 28;
    c.clip_evaluators = 8;
  } else if (name == "wrap") {  // narrow everything, wrapping overflow
    c.value_bits = 14, c.delta_bits = 24, c.interp_acc_bits = 50, c.depth_frac_bits = 18, c.depth_bits = 20;
    c.clip_bits = 8, c.zbuffer_bits = 16;
    c.overflow = OverflowMode::Wrap;
  } else if (name == "trunc") {
    c.value_bits = 16, c.delta_bits = 24, c.rounding = Rounding::Truncate;
  } else if (name == "even") {
    c.rounding = Rounding::NearestEven;
  } else if (name == "recip") {
    c.depth_variant = DepthVariant::Reciprocal;
  } else if (name == "edge64") {  // value_bits + 1 + depth_frac_bits = 62: the last 64-bit width
    c.value_bits = 33, c.delta_bits = 66, c.interp_acc_bits = 100, c.depth_frac_bits = 28;
  } else if (name == "edge128") {  // one bit more: the 128-bit path
    c.value_bits = 34, c.delta_bits = 68, c.interp_acc_bits = 100, c.depth_frac_bits = 28;
  } else if (name == "widest") {  // every width at its maximum
    c.value_bits = 40, c.delta_bits = 80, c.interp_frac_bits = 32, c.interp_acc_bits = 120;
    c.depth_frac_bits = 36, c.depth_bits = 40, c.clip_bits = 40, c.recip_bits = 48, c.zbuffer_bits = 31;
    c.rounding = Rounding::NearestEven;
  } else if (name == "wrap_recip_even") {
    c.overflow = OverflowMode::Wrap, c.depth_variant = DepthVariant::Reciprocal, c.rounding = Rounding::NearestEven;
    c.value_bits = 20, c.delta_bits = 32, c.depth_frac_bits = 20, c.depth_bits = 22, c.zbuffer_bits = 16;
  }
  checkHwConfig(c, name);
  return c;
}

const char* kConfigs[] = {"default", "minimal", "wide",   "wrap",   "trunc",          "even",
                          "recip",   "edge64",  "edge128", "widest", "wrap_recip_even"};

}  // namespace

// Every primitive of shipped scenes (spheres, clipped cylinders, solids with caps, facets,
// csg leaves), every pixel of its box, under every configuration above.
TEST(PixelDatapathFast, SameAsReferenceOnScenes) {
  const char* scenes[] = {"sphereflake", "molecule", "cylinders", "gallery", "vase", "torus", "quartic",
                          "csg/csg_mechanical"};
  for (const char* name : kConfigs) {
    const HwConfig cfg = configNamed(name);
    long hits = 0, narrow = 0, primitives = 0;
    for (const char* sc : scenes) {
      Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + sc + ".json");
      scene.width = 120;
      scene.height = 90;
      const FrameSetup fs = FrameSetup::build(scene, cfg, 2);
      PixelDatapath fast(cfg);
      OverflowCounters ovfFast, ovfRef;
      for (const PrimitiveSetup& s : fs.setups) {
        if (!s.visible) continue;
        primitives += !s.facet;
        // Piece lengths 1, 7 and 32: a span cut anywhere gives the same pixels.
        const int piece = (s.index % 3 == 0) ? 1 : (s.index % 3 == 1 ? 7 : 32);
        ASSERT_EQ(compareBox(fast, s, cfg, s.x1 - s.x0, s.y1 - s.y0, piece, ovfFast, ovfRef, &hits), 0)
            << sc << " under " << name;
        narrow += fast.narrowHostPath();
      }
      EXPECT_TRUE(sameCounters(ovfFast, ovfRef)) << sc << " under " << name;
    }
    EXPECT_GT(hits, 1000) << name;
    // The configurations within 64 bits take the 64-bit path for (nearly) every quadric.
    const bool fits = cfg.value_bits + 1 + cfg.depth_frac_bits <= 62;
    if (fits) EXPECT_GT(narrow, primitives / 2) << name;
    else EXPECT_EQ(narrow, 0) << name;
  }
}

// Random primitives whose registers reach their limits: b and c beyond value_bits, Δ beyond
// delta_bits and the accumulator, depths beyond the depth datapath, a = 0, extreme exponents
// (the 128-bit fallback of fits64), clip planes with and without caps, facets.
TEST(PixelDatapathFast, SameAsReferenceOnRandomPrimitives) {
  std::mt19937_64 rng(20261128);
  const auto bits = [&](int n) {  // a random signed value of about n bits (n <= 126)
    std::uniform_int_distribution<int> w(0, n);
    const int m = w(rng);
    i128 v = (i128(rng()) << 64) | i128(rng());
    v = m >= 126 ? v >> 1 : (m == 0 ? 0 : v >> (127 - m));
    return v;
  };
  long hits = 0;
  for (const char* name : kConfigs) {
    const HwConfig cfg = configNamed(name);
    const int Fi = cfg.interp_frac_bits, Fz = cfg.depth_frac_bits, vb = cfg.value_bits;
    PixelDatapath fast(cfg);
    OverflowCounters ovfFast, ovfRef;
    // A depth in [0, 1] and a little beyond, at 2^(Fz + Fi) (a facet's or a plane's seed).
    const auto depthSeed = [&] {
      return shl(i128(rng() % ((std::uint64_t(1) << Fz) + (std::uint64_t(1) << (Fz - 4)))), Fi) +
             i128(rng() % (std::uint64_t(1) << Fi));
    };
    for (int trial = 0; trial < 400; ++trial) {
      PrimitiveSetup s;
      s.index = trial;
      s.visible = true;
      const int kind = trial % 5;  // 0-2 surfaces, 3 solid, 4 facet
      s.solid = kind == 3;
      s.facet = kind == 4;
      s.x0 = s.y0 = 0;
      s.x1 = 24;
      s.y1 = 6;
      s.e = int(rng() % 9) - 4;
      s.ed = s.e + int(rng() % 9) - 4;
      if (trial % 37 == 0) s.ed = s.e - 40;  // a √Δ scaled far up: the 128-bit path
      if (trial % 41 == 0) s.ed = s.e + 70;  // and far down
      s.z0 = i128(rng() % ((std::uint64_t(1) << Fz) + 1));
      s.zShift = int(rng() % std::uint64_t(Fz / 2 + 1));
      s.a = (trial % 7 == 0) ? 0 : bits(vb - 1);
      s.aSign = s.a > 0 ? 1 : (s.a < 0 ? -1 : 0);
      if (s.a != 0) {
        s.recipShift = cfg.recip_bits - 3 + bitLength(s.a);
        s.recipM = divRound(i128(1) << s.recipShift, s.a, cfg.rounding);
        s.recipValid = true;
      }
      // Values near the value registers' limits: b, c of about value_bits + 2 bits, a slope
      // that crosses the limit along the span.
      const int over = trial % 3 == 0 ? 3 : 0;
      s.b = {bits(vb + Fi - 6 + over), bits(vb + Fi - 6), bits(vb + Fi + over)};
      s.c = {bits(vb + Fi - 10), bits(vb + Fi - 10), bits(vb + Fi - 10), bits(vb + Fi - 5 + over),
             bits(vb + Fi - 5), bits(vb + Fi + over)};
      const int db = cfg.delta_bits + Fi;
      // Δ past its register now and then: under "wrap" a wrapped Δ turns negative, and the
      // square-root extractor reads the register's bits (SqrtExtractor::operand).
      const int dover = trial % 4 == 0 ? 4 : -2;
      s.delta = {bits(db - 12), bits(db - 12), bits(db - 12), bits(db - 5 + dover), bits(db - 5), bits(db + dover)};
      if (trial % 2 == 0) s.delta.F = s.delta.F < 0 ? -s.delta.F : s.delta.F;  // more covered pixels
      s.facetZ = {bits(Fz + Fi - 6), bits(Fz + Fi - 6), depthSeed()};
      s.zFloor = i128(rng() % ((std::uint64_t(1) << Fz) / 2));
      const int planes = int(rng() % 4) + (trial % 11 == 0 ? 6 : 0);  // past the clip evaluators too
      for (int p = 0; p < planes; ++p) {
        PlaneSetup ps;
        const int hb = cfg.clip_bits + Fi;
        ps.h = {bits(hb - 6), bits(hb - 6), bits(hb + (p == 0 && trial % 5 == 0 ? 3 : -1))};
        ps.zdir = int(rng() % 3) - 1;
        ps.pz = ps.zdir == 0 ? 0 : ps.zdir * (bits(cfg.clip_bits - 2) | 1);
        if (ps.pz != 0 && (ps.pz > 0) != (ps.zdir > 0)) ps.pz = -ps.pz;
        ps.zk = {bits(Fz + Fi - 6), bits(Fz + Fi - 6), depthSeed()};
        ps.owns = rng() % 2;
        s.planes.push_back(ps);
      }
      const int piece = 1 + int(rng() % 24);
      ASSERT_EQ(compareBox(fast, s, cfg, s.x1, s.y1, piece, ovfFast, ovfRef, &hits), 0) << name << " trial " << trial;
    }
    EXPECT_TRUE(sameCounters(ovfFast, ovfRef)) << name;
    EXPECT_GT(ovfRef.interpolator.events + ovfRef.sqrt.events, 0u) << name << ": the limits were reached";
  }
  EXPECT_GT(hits, 0);
}

// The division by a constant divisor through its reciprocal: the same quotient as divRound
// for every rounding mode — random operands of every size, exact multiples and halves, ±1 of
// them, quotients at 2^50 (the integer divide's side) and operands at 2^62 - 1. The reference
// is the 128-bit integer division (divRound's wide path).
TEST(PixelDatapathFast, DivisionByReciprocalIsDivRound) {
  std::mt19937_64 rng(7);
  const std::int64_t lim = (std::int64_t(1) << 62) - 1;
  const auto check = [&](std::int64_t n, std::int64_t d) {
    if (d == 0 || n > lim || n < -lim || d > lim || d < -lim) return;
    const double inv = 1.0 / double(d < 0 ? -d : d);
    for (Rounding r : {Rounding::Truncate, Rounding::Nearest, Rounding::NearestEven})
      ASSERT_EQ(i128(divRound64ByReciprocal(n, d, inv, r)), test::exactDivRound(n, d, r)) << n << " / " << d;
  };
  for (int i = 0; i < 200000; ++i) {
    const int nb = int(rng() % 63), dbits = int(rng() % 63);
    std::int64_t n = nb == 0 ? 0 : std::int64_t(rng() >> (64 - nb));
    std::int64_t d = dbits == 0 ? 1 : std::int64_t(rng() >> (64 - dbits));
    if (d == 0) d = 1;
    if (rng() % 2) n = -n;
    if (rng() % 2) d = -d;
    check(n, d);
    const std::int64_t q = (d != 0 && std::llabs(d) < (std::int64_t(1) << 30)) ? std::int64_t(rng() >> 34) : 1;
    for (std::int64_t delta : {-1, 0, 1}) {
      check(q * d + delta, d);                   // exact multiples and their neighbours
      check(q * d + d / 2 + delta, d);           // halves: the ties of the rounding modes
      check(-(q * d + d / 2 + delta), d);
    }
  }
  const std::int64_t divisors[] = {1, 3, std::int64_t(1) << 12, lim, lim - 1, std::int64_t(1) << 61};
  for (std::int64_t d : divisors) {
    check(lim, d);
    check(-lim, d);
    check((std::int64_t(1) << 50) * (d < (1 << 12) ? d : 1), d < (1 << 12) ? d : 1);
    check((std::int64_t(1) << 50) * 3 - 1, 3);
    check((std::int64_t(1) << 50) * 3 + 1, 3);
  }
}

// The extractor's 64-bit fast path: the exact floor of the square root at perfect squares,
// their neighbours and 2^64 - 1.
TEST(PixelDatapathFast, SquareRootAtEdges) {
  for (std::uint64_t x : {std::uint64_t(1), std::uint64_t(2), std::uint64_t(94906265), std::uint64_t(1) << 26,
                          (std::uint64_t(1) << 32) - 1, (std::uint64_t(1) << 31) + 12345}) {
    const std::uint64_t sq = x * x;
    EXPECT_EQ(SqrtExtractor::compute(sq), x);
    EXPECT_EQ(SqrtExtractor::compute(sq - 1), x - 1);
    if (x < (std::uint64_t(1) << 32) - 1) {
      EXPECT_EQ(SqrtExtractor::compute(sq + 1), x);
    }
  }
  EXPECT_EQ(SqrtExtractor::compute(~std::uint64_t(0)), (std::uint64_t(1) << 32) - 1);
  EXPECT_EQ(SqrtExtractor::compute(0), 0u);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 100000; ++i) {
    const std::uint64_t m = rng() >> (rng() % 64);
    const std::uint64_t x = SqrtExtractor::compute(m);
    ASSERT_LE((unsigned __int128)x * x, m);
    ASSERT_GT((unsigned __int128)(x + 1) * (x + 1), m);
  }
}
