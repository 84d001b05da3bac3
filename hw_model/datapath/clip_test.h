// ClipTest: the clip unit's K linear evaluators test a depth against the primitive's clip planes
// (design §3.2): the plane value at (u, v, z) is h(u, v) · 2^Fz + pz · z, exact in
// integers, kept when negative, or zero on a plane that owns its boundary
// (half_space.h) — a plane and its opposite get exactly opposite coefficients
// (symmetric rounding), so two cells sharing a plane never both keep or both drop a
// point. A primitive with more than K planes takes extra passes.
#pragma once
#include <vector>

#include "hw_model/datapath/primitive_setup.h"

namespace qacc {

struct ClipTest {
  static bool keeps(const PlaneSetup& p, i128 hRaw, i128 z, int Fz) {
    const i128 v = shl(hRaw, Fz) + p.pz * z;
    return v < 0 || (v == 0 && p.owns);
  }
  // Every plane but `except` keeps depth z (hRaw: the planes' interpolated h values).
  static bool keptByAll(const std::vector<PlaneSetup>& planes, const i128* hRaw, i128 z, int Fz, int except = -1) {
    for (std::size_t i = 0; i < planes.size(); ++i)
      if (int(i) != except && !keeps(planes[i], hRaw[i], z, Fz)) return false;
    return true;
  }
  // Passes needed for `planes` planes on K evaluators (at least one: near/far).
  static int passes(int planes, int K) { return planes <= K ? 1 : (planes + K - 1) / K; }
};

}  // namespace qacc
