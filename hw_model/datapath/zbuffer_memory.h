// ZBufferMemory: what the Z-buffer holds per pixel, and its read-compare-write (design
// §3.2): the stored Z value — the top zbuffer_bits of the depth fraction — and, for the
// final shading, the winner's identity and internal depth, one record per pixel so that a
// Z test touches one cache line. The test is strict (z < stored), so equal depths keep
// the earlier primitive. Pixel (x, y) lives in bank (x + y) mod banks; how long a bank is
// busy is the Z-buffer unit's timing (timing/zbuffer_unit.h).
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/fixed_point.h"
#include "hw_model/datapath/screen_interleave.h"
#include "raster/image/default_init_allocator.h"

namespace qacc {

// 16 bytes: the depth and the cap share one 64-bit word (bit-fields, read sign-extended),
// so a 1920x1080 frame's records take 33 MB, not the 50 MB of an 8-byte depth beside a
// 2-byte cap padded to 24.
struct ZEntry {
  std::int64_t depth : 48;  // the winner's depth in the internal format (depth_bits <= 40)
  std::int64_t cap : 16;    // its cap plane (-1 = surface; a plane index below 2^15, as the datapath's)
  std::uint32_t z;          // stored Z value (UINT32_MAX = cleared)
  std::int32_t prim;        // winning primitive (-1 = none)
  ZEntry() : depth(0), cap(-1), z(0xFFFFFFFFu), prim(-1) {}  // cleared: no winner
  void set(i128 d, std::uint32_t stored, int p, int c) {
    depth = std::int64_t(d);
    cap = c;
    z = stored;
    prim = p;
  }
};
static_assert(sizeof(ZEntry) == 16, "a Z-buffer record is 16 bytes");

struct ZBufferMemory {
  int width = 0, height = 0;
  // Frame-sized in hw-cycle: backed by huge pages where the system offers them
  // (raster/image/default_init_allocator.h); every record is still constructed cleared.
  UninitVector<ZEntry> px;

  ZBufferMemory(int w, int h) : width(w), height(h), px(std::size_t(w) * std::size_t(h)) {}
  // The same records, bit for bit (16 bytes without padding).
  bool sameRecords(const ZBufferMemory& o) const {
    return width == o.width && height == o.height && std::memcmp(px.data(), o.px.data(), px.size() * sizeof(ZEntry)) == 0;
  }
  std::size_t size() const { return px.size(); }
  void clear() { std::fill(px.begin(), px.end(), ZEntry{}); }  // no winner anywhere
  std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }

  // The read-compare-write: true (and the record replaced) when z is nearer than the
  // stored value.
  bool testAndWrite(std::size_t pix, std::uint32_t z, int prim, i128 depth, int cap) {
    ZEntry& e = px[pix];
    if (!(z < e.z)) return false;
    e.set(depth, z, prim, cap);
    return true;
  }
  // The same test for a primitive drawn after others that come later in scene order
  // (hw-cycle's CSG pass, engines/csg_cycle_pass.h): an equal stored value goes to the
  // primitive earlier in scene order, so the result equals drawing in scene order.
  bool testAndWriteInSceneOrder(std::size_t pix, std::uint32_t z, int prim, i128 depth, int cap) {
    ZEntry& e = px[pix];
    if (!(z < e.z || (z == e.z && prim < e.prim))) return false;
    e.set(depth, z, prim, cap);
    return true;
  }
  // The value stored for an internal depth: its top zbuffer_bits fraction bits, clamped.
  // StoredFormat holds the format's shift and top, so that a unit testing every pixel
  // (timing/zbuffer_unit.h) computes them once per frame; depths come as i128 or, where the
  // pixel datapath's bound |z| < 2^40 (depth_bits <= 40) holds, as 64-bit values.
  struct StoredFormat {
    int shift = 0;         // depth_frac_bits - zbuffer_bits (0 to 28)
    std::int64_t top = 0;  // 2^zbuffer_bits - 1
    static StoredFormat from(const HwConfig& cfg) {
      return {cfg.depth_frac_bits - cfg.zbuffer_bits, (std::int64_t(1) << cfg.zbuffer_bits) - 1};
    }
    template <typename I>
    std::uint32_t operator()(I depth) const {
      const I v = depth >> shift;
      return std::uint32_t(v < 0 ? 0 : (v > I(top) ? I(top) : v));
    }
  };
  static std::uint32_t storedValue(i128 depth, const HwConfig& cfg) { return StoredFormat::from(cfg)(depth); }
  static int bankOf(int x, int y, int banks) { return interleavedUnit(x, y, banks); }
};

}  // namespace qacc
