#include "modeling/geometry/primitive.h"

#include "modeling/support/double_bits.h"

namespace qacc {

namespace {

// One 64-bit word into the key: xor, then a multiply and shift that spread every bit
// (the finaliser of splitmix64). Not a cryptographic hash: it tells a primitive changed
// after its bounds were recorded from the one they were recorded for.
std::uint64_t mix(std::uint64_t h, std::uint64_t word) {
  h ^= word;
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}

}  // namespace

std::uint64_t Primitive::shapeKey() const {
  std::uint64_t h = mix(0x9e3779b97f4a7c15ULL, (std::uint64_t(clip.size()) << 1) | std::uint64_t(solid));
  for (int i = 0; i < 16; ++i) h = mix(h, doubleBits(quadric.Q(i)));
  for (const HalfSpace& c : clip) {
    for (int i = 0; i < 4; ++i) h = mix(h, doubleBits(c.p[i]));
    h = mix(h, std::uint64_t(c.owns_boundary));
  }
  return h == 0 ? 1 : h;
}

Primitive Primitive::transformed(const Eigen::Matrix4d& M) const {
  const Eigen::Matrix4d Minv = M.inverse();
  Primitive out = *this;
  out.known_box = {};  // found for the primitive before the move
  out.quadric = quadric.transformedByInverse(Minv);
  for (auto& h : out.clip) h = h.transformedByInverse(Minv);
  return out;
}

}  // namespace qacc
