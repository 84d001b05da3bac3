// Fixed-point arithmetic of the accelerator's datapaths.
//
// A datapath value is a two's-complement integer `raw` of `width` bits; its real value is
// raw · 2^-frac (for block-floating datapaths the per-primitive exponent chosen by the
// setup unit is added on top). Every conversion to a narrower datapath goes through
// `fit`, which saturates (or wraps) AND counts the event in an OverflowCounter, so an
// overflow is never silent. Intermediate products are exact in 128-bit integers (a
// hardware multiplier produces the full product; only the result register is narrowed).
#pragma once
#include <cmath>
#include <cstdint>
#include <string>

namespace qacc {

using i128 = __int128;

// v · 2^n for a signed v: a left shift of a negative value is undefined in C++17, the
// multiplication by a power of two is not (and compiles to the same shift).
inline i128 shl(i128 v, int n) { return v * (i128(1) << n); }

enum class Rounding { Truncate, Nearest, NearestEven };
enum class OverflowMode { Saturate, Wrap };

Rounding roundingFromString(const std::string& s);  // "truncate" | "nearest" | "nearest_even"
OverflowMode overflowFromString(const std::string& s);  // "saturate" | "wrap"
std::string toString(Rounding r);
std::string toString(OverflowMode m);

struct FixedFormat {
  int width = 32;  // total bits, sign included (2..126)
  int frac = 0;    // fraction bits (may exceed width for small values)
  i128 maxRaw() const { return (i128(1) << (width - 1)) - 1; }
  i128 minRaw() const { return -(i128(1) << (width - 1)); }
};

// Overflow events, one counter per datapath (grouped in overflow_counters.h).
struct OverflowCounter {
  std::uint64_t events = 0;
  // Precision loss of the setup constants quantised into this datapath (quantize()):
  // non-zero values that became 0, and non-zero values left with fewer than 8 significant bits.
  std::uint64_t zeroed = 0, coarse = 0;
};

// Narrows an exact value to `width` bits with the given overflow mode, counting overflows.
inline i128 fitWidth(i128 v, int width, OverflowMode mode, OverflowCounter& ovf) {
  const i128 hi = (i128(1) << (width - 1)) - 1, lo = -(i128(1) << (width - 1));
  if (v >= lo && v <= hi) return v;
  ++ovf.events;
  if (mode == OverflowMode::Saturate) return v > hi ? hi : lo;
  const unsigned __int128 m = (unsigned __int128)v & (((unsigned __int128)1 << width) - 1);
  const unsigned __int128 sign = (unsigned __int128)1 << (width - 1);
  return (m & sign) ? i128(m) - (i128(1) << width) : i128(m);
}

// The range of a `width`-bit register, computed once (a datapath narrows every pixel's
// value to the same widths): fit() is fitWidth() with the in-range test on precomputed
// bounds, the same result.
struct WidthRange {
  int width = 2;
  i128 lo = -2, hi = 1;
  WidthRange() = default;
  explicit WidthRange(int w) : width(w), lo(-(i128(1) << (w - 1))), hi((i128(1) << (w - 1)) - 1) {}
  i128 fit(i128 v, OverflowMode mode, OverflowCounter& ovf) const {
    if (v >= lo && v <= hi) return v;
    return fitWidth(v, width, mode, ovf);
  }
  // fit() in a register type T (std::int64_t: a width of at most 64 bits, so the bounds and
  // every in-range value are T's; the rare overflow goes through fitWidth).
  template <typename T>
  T fitT(T v, OverflowMode mode, OverflowCounter& ovf) const {
    if (v >= T(lo) && v <= T(hi)) return v;
    return T(fitWidth(v, width, mode, ovf));
  }
};

// v · 2^-shift rounded with the given mode (shift >= 0); shift <= 0 multiplies exactly.
// T is the register type: i128 in general, std::int64_t where a datapath's widths are
// known to fit (same result, cheaper on the host).
template <typename T>
inline T shiftRoundT(T v, int shift, Rounding r) {
  if (shift <= 0) return v * (T(1) << (-shift));
  const T floorv = v >> shift;  // arithmetic: floor
  if (r == Rounding::Truncate) return floorv;
  const T rem = v - floorv * (T(1) << shift);  // in [0, 2^shift)
  const T half = T(1) << (shift - 1);
  if (rem > half) return floorv + 1;
  if (rem < half) return floorv;
  if (r == Rounding::Nearest) return floorv + 1;  // ties up
  return (floorv & 1) ? floorv + 1 : floorv;       // ties to even
}
inline i128 shiftRound(i128 v, int shift, Rounding r) { return shiftRoundT<i128>(v, shift, r); }

// shiftRoundT with the rounding mode fixed at compile time (the datapaths are instantiated
// per configured mode, so their inner loops test no mode): truncation is the floor shift;
// round-to-nearest with ties up is floor((v + 2^(shift-1)) · 2^-shift), the same value
// (rem >= half ⇔ the added half carries into the kept bits), taken unless the addition
// overflows T; ties-to-even keeps the general form. Tests check it against shiftRoundT.
template <Rounding R, typename T>
inline T shiftRoundR(T v, int shift) {
  if (shift <= 0) return v * (T(1) << (-shift));
  if constexpr (R == Rounding::Truncate) {
    return v >> shift;
  } else if constexpr (R == Rounding::Nearest) {
    T sum;
    if (!__builtin_add_overflow(v, T(1) << (shift - 1), &sum)) return sum >> shift;
    return shiftRoundT<T>(v, shift, R);
  } else {
    return shiftRoundT<T>(v, shift, R);
  }
}

// shiftRoundR where the caller knows shift >= 1 and |v| + 2^(shift-1) < 2^(bits of T - 1)
// (it states the bound where it calls): round to nearest is then always the add-and-floor
// form, with no overflow test and no test of the shift's sign. The same value as shiftRoundR.
template <Rounding R, typename T>
inline T shiftRoundFitR(T v, int shift) {
  if constexpr (R == Rounding::Truncate) return v >> shift;
  else if constexpr (R == Rounding::Nearest) return (v + (T(1) << (shift - 1))) >> shift;
  else return shiftRoundT<T>(v, shift, R);
}

// num / den (den != 0, |num|, |den| < 2^62, so that the negations and 2·rem cannot
// overflow) rounded with r, from an estimate qf of |num / den|. A quotient below 2^50 comes
// from the host's floating-point unit, corrected by its remainder (faster than a 64-bit
// integer divide): an estimate that carries at most 4 roundings of 2^-53 is off by at most
// about 4 · 2^-53 · 2^50 = 1/2 there, so its floor is off by at most one.
[[gnu::always_inline]] inline std::int64_t divRoundFromEstimate(std::int64_t num, std::int64_t den, double qf,
                                                                Rounding r) {
  long long n = num, d = den;
  if (d < 0) {
    n = -n;
    d = -d;
  }
  const bool ng = n < 0;
  const long long a = ng ? -n : n;
  long long q, rem;
  if (qf < 0x1p50) {
    q = (long long)qf;
    rem = a - q * d;
    if (rem < 0) {
      --q;
      rem += d;
    } else if (rem >= d) {
      ++q;
      rem -= d;
    }
  } else {
    q = a / d;
    rem = a - q * d;
  }
  if (r != Rounding::Truncate) {
    const long long twice = 2 * rem;
    if (twice > d || (twice == d && (r == Rounding::Nearest || (q & 1)))) ++q;
  }
  return ng ? -q : q;
}

// divRound's 64-bit path: num / den (den != 0) rounded with r, for |num|, |den| < 2^62. The
// datapaths whose widths keep both operands in that range (pixel_datapath.cpp) call it
// directly; divRound calls it for them. Always inlined: the rounding mode is then a constant
// of the caller's inner loop. The estimate |double(num) / double(den)| is
// double(|num|) / double(|den|) exactly (the conversions and the division round the
// magnitudes alike): 3 roundings.
[[gnu::always_inline]] inline std::int64_t divRound64(std::int64_t num, std::int64_t den, Rounding r) {
  return divRoundFromEstimate(num, den, std::fabs(double(num) / double(den)), r);
}

// divRound64 by a constant divisor den whose reciprocal invAbsDen = 1.0 / double(|den|) the
// caller computed once: the same quotient, the host's multiplier instead of its divider
// (4 roundings: |num|, |den|, the reciprocal and the product).
[[gnu::always_inline]] inline std::int64_t divRound64ByReciprocal(std::int64_t num, std::int64_t den, double invAbsDen,
                                                                  Rounding r) {
  return divRoundFromEstimate(num, den, std::fabs(double(num)) * invAbsDen, r);
}

// Integer quotient num / den (den != 0) with the given rounding (Truncate = toward zero).
inline i128 divRound(i128 num, i128 den, Rounding r) {
  constexpr i128 k63 = i128(1) << 62;
  if (num > -k63 && num < k63 && den > -k63 && den < k63)  // 64-bit fast path, same result
    return divRound64(std::int64_t(num), std::int64_t(den), r);
  if (den < 0) {
    num = -num;
    den = -den;
  }
  const bool neg = num < 0;
  const i128 n = neg ? -num : num;
  i128 q = n / den;
  const i128 rem = n - q * den;
  if (r != Rounding::Truncate) {
    const i128 twice = 2 * rem;
    if (twice > den || (twice == den && (r == Rounding::Nearest || (q & 1)))) ++q;
  }
  return neg ? -q : q;
}

// divRound and shl in the register type T of a datapath: i128 in general, std::int64_t where
// the datapath's widths keep |num|, |den| < 2^62 (divRound64's domain) and v · 2^n below 2^63.
template <typename T>
[[gnu::always_inline]] inline T divRoundT(T num, T den, Rounding r) {
  if constexpr (sizeof(T) == sizeof(std::int64_t)) return divRound64(num, den, r);
  else return divRound(num, den, r);
}
template <typename T>
inline T shlT(T v, int n) { return v * (T(1) << n); }

// Quantises a real number to raw = round(v · 2^scaleBits) (half away from zero, so that
// quantise(-v) == -quantise(v): a plane and its opposite get exactly opposite
// coefficients), then narrows it to `width` bits. Non-finite inputs saturate (counted).
inline i128 quantize(double v, int scaleBits, int width, OverflowMode mode, OverflowCounter& ovf) {
  const double lim = std::ldexp(1.0, width - 1);
  if (!std::isfinite(v)) {
    ++ovf.events;
    return v > 0 ? (i128(1) << (width - 1)) - 1 : (std::isnan(v) ? 0 : -(i128(1) << (width - 1)));
  }
  const double s = std::round(std::ldexp(v, scaleBits));
  if (!(std::fabs(s) < lim) || std::fabs(s) >= 1.0e37) {
    if (mode == OverflowMode::Saturate || std::fabs(s) >= 1.0e37) {
      ++ovf.events;
      return s > 0 ? (i128(1) << (width - 1)) - 1 : -(i128(1) << (width - 1));
    }
    return fitWidth(i128(s), width, mode, ovf);  // counts the event
  }
  if (v != 0) {
    if (s == 0) ++ovf.zeroed;
    else if (std::fabs(s) < 256.0) ++ovf.coarse;
  }
  return i128(s);
}

// |v| as an unsigned 128-bit number (exact for every v).
inline unsigned __int128 magnitude(i128 v) {
  return v < 0 ? (unsigned __int128)0 - (unsigned __int128)v : (unsigned __int128)v;
}

// Number of bits of m (0 for 0): the leading-zero count of a 128-bit register.
inline int bitLength(unsigned __int128 m) {
  const std::uint64_t hi = std::uint64_t(m >> 64), lo = std::uint64_t(m);
  if (hi) return 128 - __builtin_clzll(hi);
  return lo ? 64 - __builtin_clzll(lo) : 0;
}

// Number of bits needed for |v| (0 for 0).
inline int bitLength(i128 v) { return bitLength(magnitude(v)); }

// The exponent e such that |m| · 2^e < 2^(bits) with the least headroom: the block
// exponent a setup unit chooses so that the largest value of a datapath uses its width.
inline int blockExponent(double maxAbs, int bits) {
  if (!(maxAbs > 0) || !std::isfinite(maxAbs)) return 0;
  int ex;
  std::frexp(maxAbs, &ex);  // maxAbs in [2^(ex-1), 2^ex)
  return bits - ex;
}

}  // namespace qacc
