#include "hw_model/datapath/setup_arithmetic.h"

#include <algorithm>
#include <cmath>

#include "hw_model/datapath/plane_setup.h"
#include "modeling/geometry/unit_plane.h"
#include "raster/pixel/window_primitive.h"

namespace qacc {

namespace {

// Affine vector field rows R (3x4, columns u, v, z, 1) → VectorSetup with a shared block
// exponent so that the largest component over the box uses `bits` bits.
// The local depth origin z0 and scale 2^-zShift of the quadric datapath (PrimitiveSetup):
// from the surface depths in [0, 1] at a 5x5 grid of the box's pixels (and, for solids, the
// depths of the clip planes there), z0 = the middle of their range, 2^-zShift the power of
// two at least twice the range. A host-side floating-point step, as the rest of setup.
void chooseDepthOrigin(const WindowPrimitive& w, const Eigen::Matrix4d& T, double umax, double vmax,
                       const HwConfig& cfg, PrimitiveSetup& s) {
  const Eigen::Matrix4d Q = T.transpose() * w.Q * T;
  double lo = 2, hi = -1;
  auto take = [&](double z) {
    if (z >= 0 && z <= 1) {
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
  };
  const double a = Q(2, 2);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      const double u = std::round(umax * i / 4), v = std::round(vmax * j / 4);
      const double b = Q(0, 2) * u + Q(1, 2) * v + Q(2, 3);
      const double c = Q(0, 0) * u * u + 2 * Q(0, 1) * u * v + Q(1, 1) * v * v + 2 * Q(0, 3) * u + 2 * Q(1, 3) * v + Q(3, 3);
      const double d = b * b - a * c;
      if (d >= 0) {
        const double q = -(b + std::copysign(std::sqrt(d), b));
        if (a != 0) take(q / a);
        if (q != 0) take(c / q);
      }
      if (s.solid)
        for (const HalfSpace& h : w.clip) {
          const Eigen::Vector4d p = T.transpose() * h.p;
          if (p[2] != 0) take(-(p[0] * u + p[1] * v + p[3]) / p[2]);
        }
    }
  const int Fz = cfg.depth_frac_bits;
  if (hi < lo) {
    s.z0 = 0;
    s.zShift = 0;
    return;
  }
  s.z0 = i128(std::llround(std::ldexp(0.5 * (lo + hi), Fz)));
  const double range = std::max(hi - lo, std::ldexp(1.0, -Fz / 2));
  s.zShift = std::clamp(int(std::floor(-std::log2(range))) - 1, 0, Fz / 2);
}

VectorSetup vectorSetup(const Eigen::Matrix<double, 3, 4>& R, double umax, double vmax, const HwConfig& cfg,
                        OverflowCounter& ovf) {
  double bound = 0;
  for (int i = 0; i < 3; ++i)
    bound = std::max(bound, std::fabs(R(i, 0)) * umax + std::fabs(R(i, 1)) * vmax + std::fabs(R(i, 2)) +
                                std::fabs(R(i, 3)));
  const int ev = blockExponent(bound, cfg.value_bits - 2);
  const int sc = ev + cfg.interp_frac_bits, w = cfg.value_bits + cfg.interp_frac_bits + 2;
  VectorSetup v;
  for (int i = 0; i < 3; ++i) {
    v.uv[i] = {quantize(R(i, 0), sc, w, cfg.overflow, ovf), quantize(R(i, 1), sc, w, cfg.overflow, ovf),
               quantize(R(i, 3), sc, w, cfg.overflow, ovf)};
    v.cz[i] = quantize(R(i, 2), sc, w, cfg.overflow, ovf);
  }
  return v;
}

VectorSetup constantVector(const Eigen::Vector3d& d, const HwConfig& cfg, OverflowCounter& ovf) {
  Eigen::Matrix<double, 3, 4> R = Eigen::Matrix<double, 3, 4>::Zero();
  R.col(3) = d;
  return vectorSetup(R, 0, 0, cfg, ovf);
}

int floorDiv2(int v) { return v >= 0 ? v / 2 : -((-v + 1) / 2); }

// The depth floor of a piece whose exact window depth range is r (PrimitiveSetup::zFloor):
// r.lo less a margin, in the depth format, rounded down, at least 0 (a visible depth is never
// negative). The margin covers the datapath's rounding, so that the floor clamp leaves
// every depth the datapath computes within the piece untouched:
// kFloorMarginZbufferLsb steps of the stored Z plus kFloorMarginOfRange of the piece's depth range.
constexpr double kFloorMarginZbufferLsb = 16;
constexpr double kFloorMarginOfRange = 1.0 / 256;
i128 depthFloor(const DepthRange& r, const HwConfig& cfg) {
  if (!(r.lo <= r.hi)) return 0;
  const double margin =
      kFloorMarginZbufferLsb * std::ldexp(1.0, -cfg.zbuffer_bits) + kFloorMarginOfRange * (r.hi - r.lo);
  const double z = r.lo - margin;
  if (!(z > 0)) return 0;
  return i128(std::floor(std::ldexp(z, cfg.depth_frac_bits)));
}

}  // namespace

int setupOperationCount(int planes, int pointLights, bool facet) {
  // Multiply-adds of the setup formulas (setup_arithmetic.cpp), counted once:
  //   window transform Q' = M⁻ᵀ Q M⁻¹: 2 x 4x4x4 = 128; each plane p' = M⁻ᵀ p: 16;
  //   local origin (Tᵀ Q T, Tᵀ p): 24 + 4 per plane; normalisation (max, exponent): 12;
  //   contour conic Δ coefficients: 18; conic box (two 2x2 solves, sqrt, divides): 30;
  //   clip-polytope box: 10 per pair of planes, + 10 per plane;
  //   plane depths for caps (reciprocal of pz + 3 products): 12 per plane;
  //   1/a (Newton-Raphson, 3 iterations): 8; seeds: Δ 12, b 3, c 6;
  //   shading: normal field Q M⁻¹ (48), view field 12, each point light 12.
  // A facet skips the conic, 1/a and the Δ, c seeds and needs its plane depth (12).
  const int pairs = planes * (planes - 1) / 2;
  int ops = 128 + 16 * planes + 24 + 4 * planes + 12 + 10 * pairs + 10 * planes + 12 * planes + 48 + 12 +
            12 * pointLights;
  ops += facet ? 12 + 3 : 18 + 30 + 8 + 12 + 3 + 6;
  return ops;
}

int depthFloorOperationCount(int planes, bool facet) {
  // The z extent of the piece, the exact box's candidates along a third axis: the surface
  // points where ∇f ∥ z (one line cut with the quadric, 10; not for a facet), each face's
  // conic (5 per plane) and each edge (5 per pair of planes); the margin and the
  // quantisation of the floor (2).
  const int pairs = planes * (planes - 1) / 2;
  return (facet ? 0 : 10) + 5 * planes + 5 * pairs + 2;
}

int boxTestOperationCount(int planes, bool facet) {
  // Of setupOperationCount's items: the window transform (128 + 16 per plane), the conic box
  // (30, not for a facet) and the clip-polytope box (10 per pair of planes + 10 per plane).
  const int pairs = planes * (planes - 1) / 2;
  return 128 + 16 * planes + (facet ? 0 : 30) + 10 * pairs + 10 * planes;
}

PrimitiveSetup setupPrimitive(const Scene& scene, int index, const Eigen::Matrix4d& M, const Eigen::Matrix4d& Minv,
                              const HwConfig& cfg, OverflowCounter& ovf) {
  const Primitive& prim = scene.primitives[std::size_t(index)];
  PrimitiveSetup s;
  s.index = index;
  s.object = prim.object;
  s.material = prim.material;
  s.solid = prim.solid;
  s.facet = prim.isPlanar() && !prim.solid;
  int pointLights = 0;
  for (const Light& l : scene.lights) pointLights += l.type == Light::Type::Point;
  s.setupOps = setupOperationCount(int(prim.clip.size()), pointLights, s.facet);
  s.boxTestOps = boxTestOperationCount(int(prim.clip.size()), s.facet);
  s.descriptorWords = 10 + 4 * int(prim.clip.size()) + 2;

  // The depth floor is computed by the setup of a machine with the hierarchical Z unit
  // (its operations are charged there) and, for identical images, by the emulator always.
  if (cfg.hierarchical_z) s.setupOps += depthFloorOperationCount(int(prim.clip.size()), s.facet);

  Eigen::AlignedBox3d extentXY;  // the screen box's exact candidates, which the depth range reuses
  const WindowPrimitive w = toWindow(prim, index, M, Minv, scene.width, scene.height, &extentXY);
  if (w.box.empty()) {
    s.culled = true;
    return s;
  }
  s.zFloor = depthFloor(pieceDepthRange(prim, w, Minv, scene.width, scene.height, &extentXY), cfg);
  s.x0 = w.box.x0;
  s.y0 = w.box.y0;
  s.x1 = w.box.x1;
  s.y1 = w.box.y1;
  const double umax = s.x1 - s.x0 - 1, vmax = s.y1 - s.y0 - 1;
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T(0, 3) = s.x0 + 0.5;
  T(1, 3) = s.y0 + 0.5;
  const int Fi = cfg.interp_frac_bits, Fz = cfg.depth_frac_bits;
  const int zkWidth = cfg.depth_bits + Fi + 16;

  // Clip planes: value = pu u + pv v + pz z + p0 in local coordinates, quantised by
  // quantizePlane from the plane and the screen alone (not from this primitive's box), so that
  // a plane and its opposite in two neighbouring cells are exact integer negations.
  for (std::size_t i = 0; i < w.clip.size(); ++i) {
    const Eigen::Vector4d pl = T.transpose() * w.clip[i].p;
    PlaneSetup ps = quantizePlane(w.clip[i], s.x0, s.y0, scene.width, scene.height, cfg, ovf);
    if (ps.zdir != 0) {
      // The plane's depth -(pu u + pv v + p0) / pz feeds the cap logic through a linear
      // interpolator whose range is 2^(depth_bits - Fz + 15) depth units. A plane through the
      // eye is parallel to the lines of sight, pz only rounding noise: its depth steps by
      // about 1e17 per pixel, the saturated interpolator emptied every line of one of two
      // solid cells sharing it (half a solid sphere missing), and pz z, evaluated at each
      // cell's own depth, let both cells drop a row of pixel centres on the plane. Such a steep
      // plane, or one whose depth is outside the depth range at every pixel of the box, bounds
      // no line inside [0, 1] except within 2^-19 pixel of its trace: it is tested as parallel
      // to the lines (pz = 0, zdir = 0), kept or dropped whole by h(u, v), with the ownership
      // rule on exact zeros, the same decision in both cells.
      const double range = std::ldexp(1.0, cfg.depth_bits - Fz + 15) * std::fabs(pl[2]);
      double zlo = HUGE_VAL, zhi = -HUGE_VAL;
      for (double u : {0.0, umax})
        for (double v : {0.0, vmax}) {
          const double z = -(pl[0] * u + pl[1] * v + pl[3]) / pl[2];
          zlo = std::min(zlo, z);
          zhi = std::max(zhi, z);
        }
      if (std::fabs(pl[0]) >= range || std::fabs(pl[1]) >= range || zhi < -0.5 || zlo > 1.5) {
        ps.pz = 0;
        ps.zdir = 0;
      }
    }
    if (ps.zdir != 0 && s.solid) {
      const int zs = Fz + Fi;
      ps.zk = {quantize(-pl[0] / pl[2], zs, zkWidth, cfg.overflow, ovf),
               quantize(-pl[1] / pl[2], zs, zkWidth, cfg.overflow, ovf),
               quantize(-pl[3] / pl[2], zs, zkWidth, cfg.overflow, ovf)};
    }
    const Eigen::Vector3d n = unitPlane(prim.clip[i].p).head<3>();  // scale-free (coefficients near 1e300)
    const VectorSetup cn = constantVector(n, cfg, ovf);
    for (int k = 0; k < 3; ++k) ps.capNormal[k] = cn.uv[k].C;
    s.planes.push_back(ps);
  }

  if (s.facet) {
    const Eigen::Vector4d p(2 * prim.quadric.Q(0, 3), 2 * prim.quadric.Q(1, 3), 2 * prim.quadric.Q(2, 3),
                            prim.quadric.Q(3, 3));
    const Eigen::Vector4d pl = T.transpose() * (Minv.transpose() * p);
    const double bound = std::fabs(pl[0]) * umax + std::fabs(pl[1]) * vmax + std::fabs(pl[3]);
    if (!(std::fabs(pl[2]) > 1e-12 * bound)) return s;  // seen edge-on: nothing to draw
    const int zs = Fz + Fi;
    s.facetZ = {quantize(-pl[0] / pl[2], zs, zkWidth, cfg.overflow, ovf),
                quantize(-pl[1] / pl[2], zs, zkWidth, cfg.overflow, ovf),
                quantize(-pl[3] / pl[2], zs, zkWidth, cfg.overflow, ovf)};
    s.fullRows = true;
  } else {
    chooseDepthOrigin(w, T, umax, vmax, cfg, s);
    Eigen::Matrix4d Tq = T;
    Tq(2, 2) = std::ldexp(1.0, -s.zShift);
    Tq(2, 3) = std::ldexp(double(s.z0), -Fz);
    const Eigen::Matrix4d Ql = Tq.transpose() * w.Q * Tq;
    const double a = Ql(2, 2), bu = Ql(0, 2), bv = Ql(1, 2), b0 = Ql(2, 3);
    const double cuu = Ql(0, 0), cuv = 2 * Ql(0, 1), cvv = Ql(1, 1), cu = 2 * Ql(0, 3), cv = 2 * Ql(1, 3),
                 c0 = Ql(3, 3);
    s.tA = bu * bu - a * cuu;
    s.tB = 2 * bu * bv - a * cuv;
    s.tC = bv * bv - a * cvv;
    s.tD = 2 * bu * b0 - a * cu;
    s.tE = 2 * bv * b0 - a * cv;
    s.tF = b0 * b0 - a * c0;
    s.fullRows = s.solid && !(a > 0);
    const double bMax = std::fabs(bu) * umax + std::fabs(bv) * vmax + std::fabs(b0);
    const double cMax = std::fabs(cuu) * umax * umax + std::fabs(cuv) * umax * vmax + std::fabs(cvv) * vmax * vmax +
                        std::fabs(cu) * umax + std::fabs(cv) * vmax + std::fabs(c0);
    s.e = blockExponent(std::max({std::fabs(a), bMax, cMax}), cfg.value_bits - 2);
    const int vw = cfg.value_bits, cw = cfg.value_bits + Fi + 2;
    s.a = quantize(a, s.e, vw, cfg.overflow, ovf);
    s.aSign = s.a > 0 ? 1 : (s.a < 0 ? -1 : 0);
    const int sb = s.e + Fi;
    s.b = {quantize(bu, sb, cw, cfg.overflow, ovf), quantize(bv, sb, cw, cfg.overflow, ovf),
           quantize(b0, sb, cw, cfg.overflow, ovf)};
    s.c = {quantize(cuu, sb, cw, cfg.overflow, ovf), quantize(cuv, sb, cw, cfg.overflow, ovf),
           quantize(cvv, sb, cw, cfg.overflow, ovf), quantize(cu, sb, cw, cfg.overflow, ovf),
           quantize(cv, sb, cw, cfg.overflow, ovf), quantize(c0, sb, cw, cfg.overflow, ovf)};
    const double dMax = std::fabs(s.tA) * umax * umax + std::fabs(s.tB) * umax * vmax + std::fabs(s.tC) * vmax * vmax +
                        std::fabs(s.tD) * umax + std::fabs(s.tE) * vmax + std::fabs(s.tF);
    s.ed = floorDiv2(blockExponent(dMax, cfg.delta_bits - 2));
    const int sd = 2 * s.ed + Fi, dw = cfg.interp_acc_bits;
    s.delta = {quantize(s.tA, sd, dw, cfg.overflow, ovf), quantize(s.tB, sd, dw, cfg.overflow, ovf),
               quantize(s.tC, sd, dw, cfg.overflow, ovf), quantize(s.tD, sd, dw, cfg.overflow, ovf),
               quantize(s.tE, sd, dw, cfg.overflow, ovf), quantize(s.tF, sd, dw, cfg.overflow, ovf)};
    if (s.a != 0) {
      // 1/a as a normalised mantissa: recipM = round(2^recipShift / a), |recipM| < 2^(recip_bits-1).
      s.recipShift = cfg.recip_bits - 3 + bitLength(s.a);
      s.recipM = divRound(i128(1) << s.recipShift, s.a, cfg.rounding);
      s.recipValid = true;
    }
  }

  // Shading fields: homogeneous world point X(u, v, z) = Minv T (u, v, z, 1); the normal is
  // (Q X)_xyz, the view vector eye·X_w − X_xyz (perspective), a point light pos·X_w − X_xyz.
  const Eigen::Matrix4d Ml = Minv * T;
  const Eigen::Matrix<double, 3, 4> N = (prim.quadric.Q * Ml).topRows<3>();
  s.normal = vectorSetup(N, umax, vmax, cfg, ovf);
  if (scene.camera.type == Camera::Type::Orthographic) {
    s.viewConstant = true;
    s.view = constantVector(-scene.camera.forward(), cfg, ovf);
  } else {
    const Eigen::Matrix<double, 3, 4> V = scene.camera.eye * Ml.row(3) - Ml.topRows<3>();
    s.view = vectorSetup(V, umax, vmax, cfg, ovf);
  }
  for (const Light& l : scene.lights) {
    if (l.type != Light::Type::Point) continue;
    const Eigen::Matrix<double, 3, 4> L = l.position * Ml.row(3) - Ml.topRows<3>();
    s.pointLights.push_back(vectorSetup(L, umax, vmax, cfg, ovf));
  }
  s.visible = true;
  return s;
}

}  // namespace qacc
