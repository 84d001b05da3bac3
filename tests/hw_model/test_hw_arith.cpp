// Accelerator arithmetic: square-root extractor, interpolators, fixed-point helpers, shading registers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "hw_model/datapath/fixed_point.h"
#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/linear_interpolator.h"
#include "hw_model/datapath/quadratic_interpolator.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/datapath/reciprocal_sqrt.h"
#include "hw_model/datapath/shading_arithmetic.h"
#include "hw_model/timing/pixel_pipeline_unit.h"
#include "hw_model/datapath/sqrt_extractor.h"
#include "modeling/loader/scene_loader.h"
#include "tests/hw_model/exact_div_round.h"

using namespace qacc;

namespace {
std::uint64_t isqrtRef(std::uint64_t n) {  // independent: binary search
  std::uint64_t lo = 0, hi = std::min<std::uint64_t>(n, 0xFFFFFFFFull) + 1;
  while (hi - lo > 1) {
    const std::uint64_t mid = (lo + hi) / 2;
    if ((unsigned __int128)mid * mid <= n) lo = mid;
    else hi = mid;
  }
  return lo;
}
}  // namespace

TEST(SqrtExtractor, ExhaustiveSmallWidthsBothRadices) {
  for (int bits : {2, 4, 8, 12, 16}) {
    for (std::uint64_t n = 0; n < (std::uint64_t(1) << bits); ++n) {
      const std::uint64_t want = isqrtRef(n);
      ASSERT_EQ(SqrtExtractor::recurrence(n, bits, 2), want) << "radix 2, n=" << n;
      ASSERT_EQ(SqrtExtractor::recurrence(n, bits, 4), want) << "radix 4, n=" << n;
      ASSERT_EQ(SqrtExtractor::compute(n), want) << "fast path, n=" << n;
    }
  }
}

TEST(SqrtExtractor, AWrappedRegisterIsReadAsItsBits) {
  // A Δ register of 65 bits (delta_bits 64) whose value wrapped negative: the extractor reads
  // its 65 bits, 2^65 + reg, and returns (that is, does not loop) the root the digit
  // recurrence over those bits gives. A value that fits is read unchanged.
  for (const i128 reg : {i128(-1), -(i128(1) << 64), i128(-12345), -(i128(1) << 63) + 7}) {
    const unsigned __int128 n = SqrtExtractor::operand(reg, 65);
    EXPECT_EQ(n, (unsigned __int128)((i128(1) << 65) + reg));
    const std::uint64_t q = SqrtExtractor::compute(n);
    EXPECT_EQ(SqrtExtractor::recurrence(n, 65, 4), q);
    EXPECT_TRUE((unsigned __int128)q * q <= n && (unsigned __int128)(q + 1) * (q + 1) > n);
  }
  for (const i128 reg : {i128(0), i128(1), (i128(1) << 64) - 1})
    EXPECT_EQ(SqrtExtractor::operand(reg, 65), (unsigned __int128)reg);
}

TEST(SqrtExtractor, RandomLargeOperands) {
  std::mt19937_64 rng(12345);
  for (int i = 0; i < 200000; ++i) {
    const int bits = 17 + int(rng() % 64);  // 17..80 bits (the widest Δ datapath)
    unsigned __int128 n = ((unsigned __int128)rng() << 64) | rng();
    n &= (((unsigned __int128)1) << bits) - 1;
    if (i % 7 == 0) {  // perfect squares and their neighbours
      const std::uint64_t r = std::uint64_t(n >> (bits / 2 + 1)) + 1;
      n = (unsigned __int128)r * r - (i % 3 == 0 ? 1 : 0);
    }
    const std::uint64_t q = SqrtExtractor::compute(n);
    ASSERT_TRUE((unsigned __int128)q * q <= n && (unsigned __int128)(q + 1) * (q + 1) > n);
    ASSERT_EQ(SqrtExtractor::recurrence(n, bits, 2), q);
    ASSERT_EQ(SqrtExtractor::recurrence(n, bits, 4), q);
  }
}

TEST(PixelPipelineUnit, LatencyFromWidthsAndRadices) {
  EXPECT_EQ(PixelPipelineUnit::Params::sqrtLatency(64, 2), 33);
  EXPECT_EQ(PixelPipelineUnit::Params::sqrtLatency(64, 4), 17);
  EXPECT_EQ(PixelPipelineUnit::Params::dividerLatency(32, 4), 17);
  HwConfig c;
  c.delta_bits = 64;
  c.sqrt_radix = 4;
  c.depth_bits = 32;
  c.divider_radix = 4;
  // interpolators 1 + square root 17 + divider 17 + clip 1 + caps 1
  EXPECT_EQ(PixelPipelineUnit::Params::from(c).latency, 37);
  c.depth_variant = DepthVariant::Reciprocal;  // one multiplier and a rounding stage
  EXPECT_EQ(PixelPipelineUnit::Params::from(c).latency, 22);
}

TEST(QuadraticInterpolator, ForwardDifferencesEqualDirectEvaluationOver4096Pixels) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    auto r = [&](int bits) { return i128(std::int64_t(rng() % (std::uint64_t(1) << bits)) - (std::int64_t(1) << (bits - 1))); };
    QuadraticCoefficients k{r(40), r(44), r(40), r(56), r(56), r(62)};
    QuadraticInterpolator q(k, 24, 120);
    const int v = int(rng() % 4096);
    q.start(0, v);
    for (int u = 0; u < 4096; ++u) {
      ASSERT_EQ(q.raw(), q.direct(u, v)) << "u=" << u;
      // and the closed form written out independently
      const i128 U = u, V = v;
      ASSERT_EQ(q.raw(), k.A * U * U + k.B * U * V + k.C * V * V + k.D * U + k.E * V + k.F);
      q.stepRight();
    }
  }
}

TEST(LinearInterpolator, StepsEqualDirect) {
  LinearCoefficients k{123456789, -987654321, 55555};
  LinearInterpolator l(k);
  l.start(10, 20);
  for (int u = 10; u < 4106; ++u) {
    ASSERT_EQ(l.raw(), i128(123456789) * u - i128(987654321) * 20 + 55555);
    l.stepRight();
  }
}

TEST(QuadraticInterpolator, AccumulatorOverflowIsCountedAndSaturates) {
  QuadraticCoefficients k{0, 0, 0, 0, 0, (i128(1) << 40)};
  QuadraticInterpolator q(k, 0, 32);
  q.start(0, 0);
  OverflowCounter ovf;
  EXPECT_EQ(q.output(OverflowMode::Saturate, ovf), (i128(1) << 31) - 1);
  EXPECT_EQ(ovf.events, 1u);
}

TEST(FixedPoint, RoundingModes) {
  EXPECT_EQ(shiftRound(5, 1, Rounding::Truncate), 2);
  EXPECT_EQ(shiftRound(5, 1, Rounding::Nearest), 3);
  EXPECT_EQ(shiftRound(5, 1, Rounding::NearestEven), 2);
  EXPECT_EQ(shiftRound(7, 1, Rounding::NearestEven), 4);
  EXPECT_EQ(shiftRound(-5, 1, Rounding::Truncate), -3);  // floor
  EXPECT_EQ(divRound(7, 2, Rounding::Truncate), 3);
  EXPECT_EQ(divRound(-7, 2, Rounding::Truncate), -3);
  EXPECT_EQ(divRound(-7, 2, Rounding::Nearest), -4);
  EXPECT_EQ(divRound(i128(1) << 100, i128(3), Rounding::Truncate), (i128(1) << 100) / 3);
}

// divRound's 64-bit path takes its quotient from the floating-point divider below 2^50 and
// corrects it by the remainder: the same quotient as integer division in every rounding mode,
// on random operands of every length, ties, exact multiples and quotients near 2^50.
TEST(FixedPoint, DivRoundMatchesIntegerDivision) {
  std::mt19937_64 rng(5);
  const auto operand = [&](int bits) {
    const long long v = bits >= 63 ? (long long)(rng() >> 2) : (long long)(rng() >> (64 - bits));
    return i128(rng() & 1 ? -v : v);
  };
  int checked = 0;
  for (int i = 0; i < 400000; ++i) {
    const i128 den = operand(1 + int(rng() % 62));
    if (den == 0) continue;
    i128 num;
    switch (i % 4) {
      case 0: num = operand(1 + int(rng() % 62)); break;
      case 1: num = den * operand(1 + int(rng() % 20)); break;                          // exact multiples
      case 2: num = den * operand(1 + int(rng() % 20)) + den / 2; break;              // ties and near ties
      default: num = den * ((i128(1) << 50) + operand(8)) + operand(6); break;        // quotients near 2^50
    }
    if (num <= -(i128(1) << 62) || num >= (i128(1) << 62)) continue;
    for (Rounding r : {Rounding::Truncate, Rounding::Nearest, Rounding::NearestEven})
      ASSERT_EQ(divRound(num, den, r), test::exactDivRound(num, den, r))
          << (long long)num << " / " << (long long)den << " rounding " << toString(r);
    ++checked;
  }
  EXPECT_GT(checked, 200000);
}

// The rounding shift with the mode fixed at compile time (the datapaths' inner loops) against
// the general definition: random values of every width and sign, ties (rem = half, on odd
// and even floors), values next to the register's ends (where v + half overflows), shifts
// from 1 to the register width less one, and shift <= 0.
template <Rounding R, typename T>
void expectShiftRoundRMatches(std::mt19937_64& rng, int valueBits) {
  const T top = std::numeric_limits<T>::max(), bottom = std::numeric_limits<T>::min();
  for (int i = 0; i < 200000; ++i) {
    const int shift = i % 97 == 0 ? -int(rng() % 8) : 1 + int(rng() % std::uint64_t(valueBits - 2));
    const int bits = 1 + int(rng() % std::uint64_t(valueBits - 1));
    T v = T(((unsigned __int128)rng() << 64 | rng()) & (((unsigned __int128)1 << bits) - 1));
    if (rng() & 1) v = -v;
    switch (i % 6) {
      case 1:  // a tie: the dropped bits are exactly one half
        if (shift > 0) v = T(v & ~((T(1) << shift) - 1)) + (T(1) << (shift - 1));
        break;
      case 2: v = top - T(rng() % 4); break;
      case 3: v = bottom + T(rng() % 4); break;
      default: break;
    }
    if (shift <= 0 && (v > (top >> 8) || v < (bottom >> 8))) v >>= 8;  // the exact product fits T
    ASSERT_EQ(shiftRoundR<R>(v, shift), shiftRoundT<T>(v, shift, R))
        << toString(R) << " v=" << (long double)v << " shift=" << shift;
  }
}

TEST(FixedPoint, CompileTimeRoundingEqualsTheGeneralRoundingShift) {
  std::mt19937_64 rng(2026);
  expectShiftRoundRMatches<Rounding::Truncate, std::int64_t>(rng, 64);
  expectShiftRoundRMatches<Rounding::Nearest, std::int64_t>(rng, 64);
  expectShiftRoundRMatches<Rounding::NearestEven, std::int64_t>(rng, 64);
  expectShiftRoundRMatches<Rounding::Truncate, i128>(rng, 127);
  expectShiftRoundRMatches<Rounding::Nearest, i128>(rng, 127);
  expectShiftRoundRMatches<Rounding::NearestEven, i128>(rng, 127);
  // ties at both signs and the register's end
  EXPECT_EQ(shiftRoundR<Rounding::Nearest>(std::int64_t(5), 1), 3);
  EXPECT_EQ(shiftRoundR<Rounding::Nearest>(std::int64_t(-5), 1), -2);
  EXPECT_EQ(shiftRoundR<Rounding::Nearest>(std::numeric_limits<std::int64_t>::max(), 1), std::int64_t(1) << 62);
  EXPECT_EQ(shiftRoundR<Rounding::NearestEven>(std::int64_t(7), 1), 4);
  EXPECT_EQ(shiftRoundR<Rounding::Truncate>(std::int64_t(-5), 1), -3);
}

TEST(FixedPoint, QuantizeIsSymmetricAndCountsOverflow) {
  OverflowCounter ovf;
  for (double v : {0.5, 1.5, 2.5, -3.25, 1e-3, 12345.678}) {
    EXPECT_EQ(quantize(-v, 10, 40, OverflowMode::Saturate, ovf), -quantize(v, 10, 40, OverflowMode::Saturate, ovf));
  }
  EXPECT_EQ(ovf.events, 0u);
  EXPECT_EQ(quantize(1000.0, 0, 8, OverflowMode::Saturate, ovf), 127);
  EXPECT_EQ(ovf.events, 1u);
  EXPECT_EQ(quantize(200.0, 0, 8, OverflowMode::Wrap, ovf), 200 - 256);
  EXPECT_EQ(ovf.events, 2u);
  EXPECT_EQ(quantize(std::nan(""), 0, 8, OverflowMode::Saturate, ovf), 0);
  EXPECT_EQ(ovf.events, 3u);
}

TEST(HwConfig, ParsesAndRefusesBadKeys) {
  const HwConfig c = parseHwConfig(R"({"format": "qacc-hw-config/1", "pipelines": 4, "depth_variant": "reciprocal", "rounding": "truncate"})", "t.json");
  EXPECT_EQ(c.pipelines, 4);
  EXPECT_EQ(c.depth_variant, DepthVariant::Reciprocal);
  EXPECT_EQ(c.rounding, Rounding::Truncate);
  EXPECT_THROW(parseHwConfig(R"({"format": "qacc-hw-config/1", "pipelinez": 4})", "t.json"), std::invalid_argument);
  EXPECT_THROW(parseHwConfig(R"({"format": "qacc-hw-config/1", "pipelines": 0})", "t.json"), std::invalid_argument);
  EXPECT_THROW(parseHwConfig(R"({"format": "qacc-hw-config/1", "pipelines": 2.5})", "t.json"), std::invalid_argument);
  EXPECT_THROW(parseHwConfig(R"({"format": "qacc-hw-config/1", "shading_normalizer": "fast"})", "t.json"), std::invalid_argument);
  EXPECT_THROW(parseHwConfig(R"({"format": "qacc-hw-config/1", "depth_variant": 1})", "t.json"), std::invalid_argument);
  EXPECT_EQ(parseHwConfig(R"({"format": "qacc-hw-config/1", "shading_normalizer": "recurrence"})", "t.json").shading_normalizer,
            Normalizer::Recurrence);
  // round trip
  const HwConfig d = parseHwConfig(hwConfigToJson(c), "rt.json");
  EXPECT_EQ(hwConfigToJson(d), hwConfigToJson(c));
}

TEST(HwConfig, ShippedConfigurationsLoad) {
  for (const char* n : {"default", "minimal", "wide"}) {
    const HwConfig c = loadHwConfig(std::string(QACC_SOURCE_DIR) + "/hw_model/configs/" + n + ".json");
    EXPECT_EQ(c.name, n);
  }
  // the shipped default is the built-in default
  HwConfig d = loadHwConfig(std::string(QACC_SOURCE_DIR) + "/hw_model/configs/default.json");
  EXPECT_EQ(hwConfigToJson(d), hwConfigToJson(HwConfig()));
}

// The shading unit computes with 64-bit registers where the widths allow (and its fields
// with 64 x 64-bit products where the coefficients fit 64 bits); the 128-bit datapath must
// give the same colour for every input (surface points at any depth, caps), in every
// rounding mode, with either normaliser, under directional, ambient and point lights.
TEST(ShadingUnit, SixtyFourBitRegistersGiveTheSameBitsAsOneHundredTwentyEight) {
  struct Variant {
    const char* config;
    Rounding rounding;
    Normalizer normalizer;
  };
  std::vector<Variant> variants;
  for (const char* n : {"default", "minimal", "wide"})
    for (Rounding r : {Rounding::Truncate, Rounding::Nearest, Rounding::NearestEven})
      for (Normalizer z : {Normalizer::Newton, Normalizer::Recurrence}) variants.push_back({n, r, z});
  for (const Variant& var : variants) {
    const char* n = var.config;
    HwConfig cfg = loadHwConfig(std::string(QACC_SOURCE_DIR) + "/hw_model/configs/" + n + ".json");
    cfg.rounding = var.rounding;
    cfg.shading_normalizer = var.normalizer;
    Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/gallery.json");
    scene.width = 320;
    scene.height = 240;
    Light point;
    point.type = Light::Type::Point;
    point.position = scene.camera.eye + Eigen::Vector3d(1.5, 2.0, -0.5);
    point.color = Eigen::Vector3d(0.6, 0.5, 0.4);
    scene.lights.push_back(point);
    const FrameSetup hs = FrameSetup::build(scene, cfg, 1);
    std::mt19937_64 rng(7);
    int compared = 0;
    for (const PrimitiveSetup& s : hs.setups) {
      if (!s.visible) continue;
      std::uniform_int_distribution<int> U(0, s.x1 - s.x0 - 1), V(0, s.y1 - s.y0 - 1);
      std::uniform_int_distribution<long long> Z(0, (1LL << cfg.depth_frac_bits));
      for (int i = 0; i < 400; ++i) {
        const int u = U(rng), v = V(rng);
        const i128 z = Z(rng);
        const int cap = s.planes.empty() || i % 4 ? -1 : int(i % s.planes.size());
        OverflowCounter ovf;
        const auto narrow = shadePixel(s, hs.lighting, cfg, u, v, z, cap, ovf);
        const auto wide = shadePixelWide(s, hs.lighting, cfg, u, v, z, cap);
        ASSERT_EQ(narrow, wide) << n << " rounding " << toString(var.rounding) << " normaliser "
                                << int(var.normalizer) << " primitive " << s.index << " at " << u << "," << v;
        ++compared;
      }
    }
    EXPECT_GT(compared, 1000) << n;
  }
}

// The shading normaliser's reciprocal square root (seed ROM + one Newton step) against
// the exact value, exhaustively over a range of small inputs and on random large ones.
TEST(ReciprocalSqrt, NewtonStepFromTheSeedRomIsAccurateTo18Bits) {
  const int P = ReciprocalSqrt::kPrecision;
  auto relErr = [&](unsigned __int128 L) {
    const ReciprocalSqrt::Result r = ReciprocalSqrt::compute(L);
    const double exact = 1.0 / std::sqrt(double(L));
    const double got = std::ldexp(double(r.y), -(2 * P + 1 + r.k));
    return std::fabs(got - exact) / exact;
  };
  double worst = 0;
  for (std::uint64_t L = 1; L < (1u << 20); ++L) worst = std::max(worst, relErr(L));
  std::mt19937_64 rng(11);
  for (int i = 0; i < 200000; ++i) {
    const int bits = 20 + int(rng() % 100);
    const unsigned __int128 L = (((unsigned __int128)rng() << 64) | rng()) >> (128 - bits);
    if (L > 0) worst = std::max(worst, relErr(L));
  }
  EXPECT_LT(worst, std::ldexp(1.0, -18));
  EXPECT_GT(worst, 0.0);  // an approximation, not an exact unit
  EXPECT_EQ(ReciprocalSqrt::compute(0).y, 0);
}

TEST(FixedPoint, QuantizeCountsPrecisionLoss) {
  OverflowCounter c;
  EXPECT_EQ(quantize(1e-12, 10, 32, OverflowMode::Saturate, c), 0);  // non-zero, quantised to zero
  EXPECT_EQ(quantize(3.0, 4, 32, OverflowMode::Saturate, c), 48);    // 6 significant bits left
  EXPECT_EQ(quantize(1000.0, 10, 32, OverflowMode::Saturate, c), 1024000);
  EXPECT_EQ(quantize(0.0, 10, 32, OverflowMode::Saturate, c), 0);    // zero is not a loss
  EXPECT_EQ(c.zeroed, 1u);
  EXPECT_EQ(c.coarse, 1u);
  EXPECT_EQ(c.events, 0u);
}

// The configuration file is strict like a scene (issue 14): its format is checked and a
// duplicate key is refused (nlohmann kept the last value silently), with the JSON path.
TEST(HwConfig, FormatCheckedAndDuplicateKeysRefused) {
  auto message = [](const std::string& text) {
    try {
      parseHwConfig(text, "c.json");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(R"({"value_bits": 16})"), "c.json: /: missing \"format\" (expected \"qacc-hw-config/1\")");
  EXPECT_EQ(message(R"({"format": "qacc-scene/1", "value_bits": 16})"),
            "c.json: /format: expected \"qacc-hw-config/1\", got \"qacc-scene/1\"");
  EXPECT_EQ(message(R"({"format": 1})"), "c.json: /format: expected \"qacc-hw-config/1\", got 1");
  EXPECT_NE(message(R"({"format": "qacc-hw-config/1", "value_bits": 24, "value_bits": 16})").find("c.json: /value_bits: duplicate key"),
            std::string::npos);
  EXPECT_NE(message("{\"format\": \"qacc-hw-config/1\",\n \"pipelines\": 2,,}").find("line 2"), std::string::npos);
  EXPECT_EQ(message(R"({"format": "qacc-hw-config/1", "comment": 3})"), "c.json: /comment: expected a string");
  EXPECT_EQ(message(R"([1])"), "c.json: /: expected a JSON object");
}

// unit_frac_bits 28 built a 2^28-entry specular table per material before the first pixel
// (1 GiB of 32-bit entries); it is refused with the reason before anything is built.
TEST(HwConfig, SpecularTableAboveTheLimitRefused) {
  try {
    parseHwConfig(R"({"format": "qacc-hw-config/1", "normal_bits": 30, "unit_frac_bits": 28})", "c.json");
    FAIL() << "unit_frac_bits 28 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("c.json: /unit_frac_bits: 28 needs a specular table of 2^28 + 1 entries per material, above the limit of 2^20 + 1"),
              std::string::npos) << e.what();
  }
  EXPECT_EQ(parseHwConfig(R"({"format": "qacc-hw-config/1", "normal_bits": 30, "unit_frac_bits": 20})", "c.json").unit_frac_bits, 20);
}

TEST(HwConfig, NamedAfterItsFileAndNarrowWidthsRefusedWithTheReason) {
  EXPECT_EQ(parseHwConfig(R"({"format": "qacc-hw-config/1", "value_bits": 16})", "dir/narrow16.json").name, "narrow16");
  EXPECT_EQ(parseHwConfig(R"({"format": "qacc-hw-config/1", "name": "mine", "value_bits": 16})", "dir/narrow16.json").name, "mine");
  try {
    parseHwConfig(R"({"format": "qacc-hw-config/1", "value_bits": 32, "delta_bits": 40})", "c.json");
    FAIL() << "delta_bits 40 with value_bits 32 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("c.json: /delta_bits: 40 is below 2 value_bits - 8"), std::string::npos) << e.what();
  }
}
