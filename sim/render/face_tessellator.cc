#include "sim/render/face_tessellator.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace avc::sim {
namespace {

// Each level halves an edge and quarters its bend, so 10 levels absorb a bend a million times the
// allowed error; deeper splits would only chase numerical noise.
constexpr int kMaxSubdivisionDepth = 10;
// At most 3 + 5 vertices after clipping a triangle by five planes.
constexpr int kMaxPolygon = 8;
// Screen coordinates are clamped far inside int32 fixed point so edge functions fit int64.
constexpr double kMaxSampleCoordinate = 1 << 21;

bool CanonicalLess(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

double PlaneValue(const Eigen::Vector4d& plane, const Eigen::Vector3d& p) {
  return plane.x() * p.x() + plane.y() * p.y() + plane.z() * p.z() + plane.w();
}

// Point where edge a-b crosses the plane, computed from the endpoints in canonical order so both
// faces sharing the edge get the same bits.
Eigen::Vector3d Intersect(const Eigen::Vector4d& plane, Eigen::Vector3d a, Eigen::Vector3d b) {
  if (CanonicalLess(b, a)) std::swap(a, b);
  const double fa = PlaneValue(plane, a), fb = PlaneValue(plane, b);
  const double t = fa / (fa - fb);
  return a + t * (b - a);
}

// Nearest fixed-point value (halves round up), inline for |v| < 2^62.
int64_t RoundToFixed(double v) {
  v += 0.5;
  const int64_t t = static_cast<int64_t>(v);
  return t - (static_cast<double>(t) > v);
}

// Floor of a / 128 for the half-sample lattice test.
int64_t FloorHalf(int64_t a) { return a >> (kSubpixelBits - 1); }

// Gradient g of a function with values f0 f1 f2 at s0 s1 s2: g . (s1 - s0) = f1 - f0, etc.
Eigen::Vector2d Gradient(const Eigen::Vector2d& d1, const Eigen::Vector2d& d2, double inv_det,
                         double delta1, double delta2) {
  return {(d2.y() * delta1 - d1.y() * delta2) * inv_det,
          (d1.x() * delta2 - d2.x() * delta1) * inv_det};
}

}  // namespace

FaceTessellator::FaceTessellator(const LensModel& lens, const SampleGrid& grid, double near_clip_m,
                                 double max_edge_error_px)
    : lens_(lens),
      grid_(grid),
      max_error_px_(max_edge_error_px),
      width_(lens.intrinsics().width),
      height_(lens.intrinsics().height) {
  const GuardBox& g = lens.guard();
  planes_ = {Eigen::Vector4d(0, 0, 1, -near_clip_m), Eigen::Vector4d(1, 0, -g.x_min, 0),
             Eigen::Vector4d(-1, 0, g.x_max, 0), Eigen::Vector4d(0, 1, -g.y_min, 0),
             Eigen::Vector4d(0, -1, g.y_max, 0)};
}

uint8_t FaceTessellator::Outcode(const Eigen::Vector3d& p) const {
  uint8_t code = 0;
  for (size_t k = 0; k < planes_.size(); ++k) code |= (PlaneValue(planes_[k], p) < 0) << k;
  return code;
}

ScreenVertex FaceTessellator::MakeVertex(const Eigen::Vector3d& p) const {
  ScreenVertex v;
  v.p = p;
  v.n = Eigen::Vector2d(p.x() / p.z(), p.y() / p.z());
  v.pixel = lens_.PixelOf(v.n);
  v.s = Eigen::Vector2d(grid_.FromPixel(v.pixel.x()), grid_.FromPixel(v.pixel.y()));
  v.in_range = std::abs(v.s.x()) < kMaxSampleCoordinate && std::abs(v.s.y()) < kMaxSampleCoordinate;
  if (v.in_range) {
    v.x = RoundToFixed(v.s.x() * kSubpixelScale);
    v.y = RoundToFixed(v.s.y() * kSubpixelScale);
  }
  return v;
}

void FaceTessellator::EmitOrSubdivide(const ScreenVertex& a, const ScreenVertex& b,
                                      const ScreenVertex& c, int32_t shading, bool* subdivided,
                                      std::vector<RasterTriangle>* out) const {
  if (lens_.distorted()) {
    Subdivide(a, b, c, 0, shading, subdivided, out);
  } else {
    Emit(a, b, c, shading, out);
  }
}

FaceTessellator::Outcome FaceTessellator::Tessellate(
    const std::array<const ScreenVertex*, 3>& vertices, const std::array<uint8_t, 3>& outcodes,
    int32_t shading, std::vector<RasterTriangle>* out) const {
  Outcome outcome;
  if (outcodes[0] & outcodes[1] & outcodes[2]) return outcome;  // wholly beyond one plane
  if ((outcodes[0] | outcodes[1] | outcodes[2]) == 0) {
    EmitOrSubdivide(*vertices[0], *vertices[1], *vertices[2], shading, &outcome.subdivided, out);
    return outcome;
  }
  outcome.clipped = true;
  const uint8_t crossed = outcodes[0] | outcodes[1] | outcodes[2];
  std::array<Eigen::Vector3d, kMaxPolygon> polygon;
  int count = 3;
  for (int i = 0; i < 3; ++i) polygon[i] = vertices[i]->p;
  for (size_t k = 0; k < planes_.size(); ++k) {
    if (!(crossed & (1 << k))) continue;
    std::array<Eigen::Vector3d, kMaxPolygon> clipped;
    int kept = 0;
    for (int i = 0; i < count; ++i) {
      const Eigen::Vector3d& cur = polygon[i];
      const Eigen::Vector3d& next = polygon[(i + 1) % count];
      const bool cur_in = PlaneValue(planes_[k], cur) >= 0;
      const bool next_in = PlaneValue(planes_[k], next) >= 0;
      if (cur_in) clipped[kept++] = cur;
      if (cur_in != next_in && kept < kMaxPolygon)
        clipped[kept++] = Intersect(planes_[k], cur, next);
    }
    polygon = clipped;
    count = kept;
    if (count < 3) return outcome;
  }
  std::array<ScreenVertex, kMaxPolygon> screen;
  for (int i = 0; i < count; ++i) screen[i] = MakeVertex(polygon[i]);
  for (int i = 1; i + 1 < count; ++i) {
    EmitOrSubdivide(screen[0], screen[i], screen[i + 1], shading, &outcome.subdivided, out);
  }
  return outcome;
}

bool FaceTessellator::SplitEdge(const ScreenVertex& a, const ScreenVertex& b,
                                ScreenVertex* mid) const {
  // Short edges cannot bend enough: skip the projection (symmetric in a and b).
  if (lens_.MidpointErrorBound((a.n - b.n).squaredNorm()) <= max_error_px_) return false;
  const bool a_first = CanonicalLess(a.p, b.p);
  const ScreenVertex& lo = a_first ? a : b;
  const ScreenVertex& hi = a_first ? b : a;
  // The 3D point imaging halfway between the undistorted images of the endpoints. Without
  // distortion it images exactly on the chord's midpoint; its distance from there bounds both the
  // bend of the edge (what coverage sees) and how far the triangle's affine screen-to-ray map
  // (depth for the z-test, the start of undistortion) is off inside the triangle, since a smooth
  // map's linear interpolation error on a triangle is governed by its edge-midpoint errors.
  const double t = lo.p.z() / (lo.p.z() + hi.p.z());
  *mid = MakeVertex(lo.p + t * (hi.p - lo.p));
  return (mid->pixel - 0.5 * (lo.pixel + hi.pixel)).norm() > max_error_px_;
}

void FaceTessellator::Subdivide(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                                int depth, int32_t shading, bool* subdivided,
                                std::vector<RasterTriangle>* out) const {
  if (depth >= kMaxSubdivisionDepth) {
    Emit(a, b, c, shading, out);
    return;
  }
  ScreenVertex ab, bc, ca;
  const bool split_ab = SplitEdge(a, b, &ab);
  const bool split_bc = SplitEdge(b, c, &bc);
  const bool split_ca = SplitEdge(c, a, &ca);
  const int splits = split_ab + split_bc + split_ca;
  if (splits == 0) {
    Emit(a, b, c, shading, out);
    return;
  }
  *subdivided = true;
  const int next = depth + 1;
  if (splits == 3) {
    Subdivide(a, ab, ca, next, shading, subdivided, out);
    Subdivide(ab, b, bc, next, shading, subdivided, out);
    Subdivide(ca, bc, c, next, shading, subdivided, out);
    Subdivide(ab, bc, ca, next, shading, subdivided, out);
    return;
  }
  // Rotate so that the split edges come first: (p, q) split, and (q, r) split when two are.
  const ScreenVertex *p, *q, *r, *pq, *qr;
  if (splits == 1) {
    if (split_ab) {
      p = &a, q = &b, r = &c, pq = &ab;
    } else if (split_bc) {
      p = &b, q = &c, r = &a, pq = &bc;
    } else {
      p = &c, q = &a, r = &b, pq = &ca;
    }
    Subdivide(*p, *pq, *r, next, shading, subdivided, out);
    Subdivide(*pq, *q, *r, next, shading, subdivided, out);
    return;
  }
  if (!split_ca) {
    p = &a, q = &b, r = &c, pq = &ab, qr = &bc;
  } else if (!split_ab) {
    p = &b, q = &c, r = &a, pq = &bc, qr = &ca;
  } else {
    p = &c, q = &a, r = &b, pq = &ca, qr = &ab;
  }
  Subdivide(*pq, *q, *qr, next, shading, subdivided, out);
  Subdivide(*p, *pq, *qr, next, shading, subdivided, out);
  Subdivide(*p, *qr, *r, next, shading, subdivided, out);
}

void FaceTessellator::Emit(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                           int32_t shading, std::vector<RasterTriangle>* out) const {
  // Out of fixed-point range is only reachable through a degenerate guard region.
  if (!a.in_range || !b.in_range || !c.in_range) return;
  std::array<const ScreenVertex*, 3> v = {&a, &b, &c};
  const int64_t area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (area2 == 0) return;
  if (area2 < 0) std::swap(v[1], v[2]);
  const int64_t x_min = std::min({a.x, b.x, c.x}), x_max = std::max({a.x, b.x, c.x});
  const int64_t y_min = std::min({a.y, b.y, c.y}), y_max = std::max({a.y, b.y, c.y});
  const int64_t last_x = int64_t{width_ * grid_.n - 1} * kSubpixelScale;
  const int64_t last_y = int64_t{height_ * grid_.n - 1} * kSubpixelScale;
  if (x_max < 0 || y_max < 0 || x_min > last_x || y_min > last_y) return;
  // Samples sit at integer (colour) or half-integer (pixel centres for even n) positions: a
  // triangle whose box holds neither covers none.
  if (FloorHalf(x_max) < -FloorHalf(-x_min) || FloorHalf(y_max) < -FloorHalf(-y_min)) return;

  RasterTriangle t;
  for (int i = 0; i < 3; ++i) {
    t.x[i] = static_cast<int32_t>(v[i]->x);
    t.y[i] = static_cast<int32_t>(v[i]->y);
  }
  t.shading = shading;
  const Eigen::Vector2d d1 = v[1]->s - v[0]->s, d2 = v[2]->s - v[0]->s;
  const double det = d1.x() * d2.y() - d1.y() * d2.x();
  std::array<double, 3> inv_z;
  for (int i = 0; i < 3; ++i) inv_z[i] = 1.0 / v[i]->p.z();
  Eigen::Vector2d g_inv_z = Eigen::Vector2d::Zero();
  Eigen::Matrix2d j;
  j << 1.0 / (lens_.intrinsics().fx * grid_.n), 0, 0, 1.0 / (lens_.intrinsics().fy * grid_.n);
  if (std::abs(det) > 1e-9) {
    const double inv_det = 1.0 / det;
    const Eigen::Vector2d& n0 = v[0]->n;
    g_inv_z = Gradient(d1, d2, inv_det, inv_z[1] - inv_z[0], inv_z[2] - inv_z[0]);
    j.row(0) = Gradient(d1, d2, inv_det, v[1]->n.x() - n0.x(), v[2]->n.x() - n0.x()).transpose();
    j.row(1) = Gradient(d1, d2, inv_det, v[1]->n.y() - n0.y(), v[2]->n.y() - n0.y()).transpose();
  }
  // Re-anchor at the snapped vertex 0, where the rasteriser measures from.
  const Eigen::Vector2d snap_shift =
      Eigen::Vector2d(static_cast<double>(v[0]->x), static_cast<double>(v[0]->y)) / kSubpixelScale -
      v[0]->s;
  t.inv_z0 = static_cast<float>(inv_z[0] + g_inv_z.dot(snap_shift));
  t.inv_z_dx = static_cast<float>(g_inv_z.x());
  t.inv_z_dy = static_cast<float>(g_inv_z.y());
  const Eigen::Vector2d n0 = v[0]->n + j * snap_shift;
  t.n0x = n0.x();
  t.n0y = n0.y();
  t.jxx = static_cast<float>(j(0, 0));
  t.jxy = static_cast<float>(j(0, 1));
  t.jyx = static_cast<float>(j(1, 0));
  t.jyy = static_cast<float>(j(1, 1));
  out->push_back(t);
}

}  // namespace avc::sim
