#include "modeling/tessellation/parametric_grid.h"

#include <algorithm>
#include <cmath>

#include "modeling/tessellation/clip_region.h"

namespace qacc::tess {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;

double wrapU(double u) { return u >= kTwoPi ? u - kTwoPi : u; }

}  // namespace

// Grid sizes for a target triangle count.
Grid gridFor(QuadricType type, int target) {
  const int N = std::max(2, target);
  Grid g;
  switch (type) {
    case QuadricType::Ellipsoid: {
      g.nv = std::max(2, int(std::lround(std::sqrt(N / 4.0) + 0.5)));
      g.nu = std::max(3, N / (2 * (g.nv - 1)));
      break;
    }
    case QuadricType::EllipticCylinder:
      g.nv = 1;
      g.nu = std::max(3, N / 2);
      break;
    case QuadricType::EllipticCone:
      g.nv = 1;
      g.nu = std::max(3, N);
      break;
    case QuadricType::EllipticParaboloid:
    case QuadricType::HyperboloidTwoSheets:
      g.nv = std::max(1, int(std::lround(std::sqrt(N / 4.0))));
      g.nu = std::max(3, N / std::max(1, 2 * g.nv - 1));
      break;
    default:
      g.nv = std::max(1, int(std::lround(std::sqrt(N / 4.0))));
      g.nu = std::max(3, N / (2 * g.nv));
      break;
  }
  return g;
}

// Parametric grid over [u0,u1] x [v0,v1] (u periodic) through the builder.
void emitGrid(SurfaceBuilder& sb, const Grid& g, double v0, double v1, const std::vector<double>& extra_v) {
  std::vector<double> vs;
  // The last row exactly at v1 (v0 + (v1 - v0) nv / nv can miss it by an ulp: at an
  // ellipsoid's pole, sin v would then differ from 0 and the pole would not close).
  for (int j = 0; j <= g.nv; ++j) vs.push_back(j == g.nv ? v1 : v0 + (v1 - v0) * j / g.nv);
  const double snap = 1e-9 * (std::abs(v1 - v0) + std::abs(v0) + std::abs(v1));
  for (double e : extra_v) {
    for (double& v : vs)
      if (std::abs(v - e) <= snap) v = e;
    if (e > v0 && e < v1) vs.push_back(e);
  }
  std::sort(vs.begin(), vs.end());
  vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  // The grid's vertices, row by row (u = 2π closes a row: its own column), each made once
  // for the quads around it.
  const std::size_t columns = std::size_t(g.nu) + 1;
  auto row = [&](double v, std::vector<ClipVertex>& out) {
    out.clear();
    for (int i = 0; i <= g.nu; ++i) out.push_back(sb.vertex(Vector3d(i == g.nu ? kTwoPi : kTwoPi * i / g.nu, v, 0)));
  };
  std::vector<ClipVertex> lower, upper;
  if (!vs.empty()) row(vs[0], upper);
  for (std::size_t j = 0; j + 1 < vs.size(); ++j) {
    lower.swap(upper);
    row(vs[j + 1], upper);
    for (std::size_t i = 0; i + 1 < columns; ++i) sb.addQuad(lower[i], lower[i + 1], upper[i + 1], upper[i]);
  }
}

GridChooser gridByTarget(QuadricType type, int target) {
  return [type, target](double v0, double v1) {
    Grid g = gridFor(type, target);
    if (type == QuadricType::EllipticCone && v0 < 0 && v1 > 0) g.nu = std::max(3, g.nu / 2);
    return g;
  };
}

bool emitNaturalQuadricGrid(SurfaceBuilder& sb, Domain& domain, QuadricType type, const Frame& f, double ltol,
                            const std::vector<Vector3d>& regionVertices, const GridChooser& choose) {
  switch (type) {
    case QuadricType::Ellipsoid: {
      const Vector3d c = -f.E.ldlt().solve(f.g);
      const double Jp = evalFrame(f, c);
      const Vector3d a(std::sqrt(-Jp / f.lambda[0]), std::sqrt(-Jp / f.lambda[1]), std::sqrt(-Jp / f.lambda[2]));
      const Matrix3d V = f.V;
      domain.position = [c, a, V](const Vector3d& uv) {
        const double u = wrapU(uv.x()), v = uv.y();
        const double sv = (v <= 0 || v >= M_PI) ? 0.0 : std::sin(v);
        const double cv = v <= 0 ? 1.0 : (v >= M_PI ? -1.0 : std::cos(v));
        return Vector3d(c + V * Vector3d(a.x() * sv * std::cos(u), a.y() * sv * std::sin(u), a.z() * cv));
      };
      emitGrid(sb, choose(0.0, M_PI), 0.0, M_PI);
      break;
    }
    case QuadricType::EllipticCylinder: {
      const Vector3d c = partialCentre(f, ltol);
      const double Jp = evalFrame(f, c);
      const double a1 = std::sqrt(-Jp / f.lambda[0]), a2 = std::sqrt(-Jp / f.lambda[1]);
      const Matrix3d V = f.V;
      double t0, t1;
      axialExtent(regionVertices, c, V.col(2), t0, t1);
      domain.position = [c, a1, a2, V](const Vector3d& uv) {
        const double u = wrapU(uv.x());
        return Vector3d(c + a1 * std::cos(u) * V.col(0) + a2 * std::sin(u) * V.col(1) + uv.y() * V.col(2));
      };
      emitGrid(sb, choose(t0, t1), t0, t1);
      break;
    }
    case QuadricType::EllipticCone:
    case QuadricType::HyperboloidOneSheet:
    case QuadricType::HyperboloidTwoSheets: {
      const Vector3d c = -f.E.ldlt().solve(f.g);
      const double Jp = type == QuadricType::EllipticCone ? 0.0 : evalFrame(f, c);
      const double l3 = -f.lambda[2];
      const double s1 = 1 / std::sqrt(f.lambda[0]), s2 = 1 / std::sqrt(f.lambda[1]);
      const Matrix3d V = f.V;
      double t0, t1;
      axialExtent(regionVertices, c, V.col(2), t0, t1);
      if (type != QuadricType::HyperboloidTwoSheets) {
        domain.position = [c, Jp, l3, s1, s2, V](const Vector3d& uv) {
          const double u = wrapU(uv.x()), t = uv.y();
          const double r = std::sqrt(std::max(0.0, l3 * t * t - Jp));
          return Vector3d(c + r * (s1 * std::cos(u) * V.col(0) + s2 * std::sin(u) * V.col(1)) + t * V.col(2));
        };
        emitGrid(sb, choose(t0, t1), t0, t1, {0.0});
      } else {
        // Sheets t = ±t0 cosh s, radius √J' sinh s (s >= 0), one grid per sheet.
        const double tv = std::sqrt(Jp / l3), rj = std::sqrt(Jp);
        for (double sheet : {1.0, -1.0}) {
          const double reach = sheet > 0 ? t1 : -t0;
          if (reach <= tv) continue;
          const double smax = std::acosh(reach / tv);
          domain.position = [c, tv, rj, s1, s2, V, sheet](const Vector3d& uv) {
            const double u = wrapU(uv.x()), s = uv.y();
            const double r = s <= 0 ? 0.0 : rj * std::sinh(s);
            return Vector3d(c + r * (s1 * std::cos(u) * V.col(0) + s2 * std::sin(u) * V.col(1)) +
                            sheet * tv * std::cosh(s) * V.col(2));
          };
          emitGrid(sb, choose(0.0, smax), 0.0, smax);
        }
      }
      break;
    }
    case QuadricType::EllipticParaboloid: {
      const Vector3d c = partialCentre(f, ltol);
      const double h = f.V.col(2).dot(f.g);
      const double tv = -evalFrame(f, c) / (2 * h);
      const double s1 = 1 / std::sqrt(f.lambda[0]), s2 = 1 / std::sqrt(f.lambda[1]);
      const Matrix3d V = f.V;
      double t0, t1;
      axialExtent(regionVertices, c, V.col(2), t0, t1);
      const double rho2 = std::max({0.0, 2 * h * (tv - t0), 2 * h * (tv - t1)});
      const double rmax = std::sqrt(rho2);
      domain.position = [c, h, tv, s1, s2, V](const Vector3d& uv) {
        const double u = wrapU(uv.x()), r = uv.y();
        return Vector3d(c + r * (s1 * std::cos(u) * V.col(0) + s2 * std::sin(u) * V.col(1)) +
                        (tv - r * r / (2 * h)) * V.col(2));
      };
      emitGrid(sb, choose(0.0, rmax), 0.0, rmax);
      break;
    }
    default: return false;
  }
  return true;
}

}  // namespace qacc::tess
