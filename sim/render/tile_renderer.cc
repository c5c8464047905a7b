#include "sim/render/tile_renderer.h"

#include <algorithm>
#include <cmath>

namespace avc::sim {
namespace {

// Relative 1/z difference within which samples of one material and label count as one surface.
constexpr float kSameSurfaceDepth = 0.01f;

}  // namespace

TileRenderer::TileRenderer(const Scene& scene, const FrameGeometry& frame, const LensModel& lens,
                           const RenderOptions& options, const Eigen::Matrix3d& R_cam_world,
                           const BackgroundImage& background)
    : scene_(scene),
      frame_(frame),
      lens_(lens),
      grid_{options.samples_per_pixel_axis},
      ambient_(options.ambient),
      diffuse_(options.diffuse),
      srgb_(options.srgb ? &SrgbTable::Get() : nullptr),
      background_(background) {
  const Eigen::Vector3d light = options.light_direction.normalized();
  light_cam_ = options.light_in_world_frame ? Eigen::Vector3d(R_cam_world * light) : light;
  light_world_ = (R_cam_world.transpose() * light_cam_).cast<float>();
}

Eigen::Vector2d TileRenderer::Normalised(const RasterTriangle& t, const Eigen::Vector2d& s) const {
  const double dx = s.x() - static_cast<double>(t.x[0]) / kSubpixelScale;
  const double dy = s.y() - static_cast<double>(t.y[0]) / kSubpixelScale;
  const Eigen::Vector2d guess(t.n0x + t.jxx * dx + t.jxy * dy, t.n0y + t.jyx * dx + t.jyy * dy);
  return lens_.NormalisedOf({grid_.ToPixel(s.x()), grid_.ToPixel(s.y())}, guess);
}

double TileRenderer::Depth(const RasterTriangle& t, const Eigen::Vector2d& n,
                           const Eigen::Vector2d& s) const {
  const FaceShading& face = frame_.shadings[t.shading];
  const double z = face.plane_offset / face.plane_normal.dot(Eigen::Vector3d(n.x(), n.y(), 1));
  if (z > 0 && std::isfinite(z)) return z;
  // A ray grazing the plane at a silhouette: fall back to the rasteriser's screen-space depth.
  const double dx = s.x() - static_cast<double>(t.x[0]) / kSubpixelScale;
  const double dy = s.y() - static_cast<double>(t.y[0]) / kSubpixelScale;
  return 1.0 / std::max(1e-9, t.inv_z0 + t.inv_z_dx * dx + t.inv_z_dy * dy);
}

Eigen::Vector3f TileRenderer::Shade(const RasterTriangle& t, const Eigen::Vector2d& n,
                                    const Eigen::Vector2d& s) const {
  const FaceShading& face = frame_.shadings[t.shading];
  const Eigen::Vector3d hit = Depth(t, n, s) * Eigen::Vector3d(n.x(), n.y(), 1);
  const Eigen::Vector3f q = (hit - face.origin).cast<float>();
  // Barycentrics of the hit, clamped onto the face (samples at silhouettes may sit a hair off).
  float b1 = std::max(0.0f, face.bary1.dot(q)), b2 = std::max(0.0f, face.bary2.dot(q));
  float b0 = std::max(0.0f, 1.0f - face.bary1.dot(q) - face.bary2.dot(q));
  const float sum = b0 + b1 + b2;
  if (sum > 0) {
    b0 /= sum, b1 /= sum, b2 /= sum;
  } else {
    b0 = 1;
  }
  const Eigen::Vector2f uv = b0 * face.uv[0] + b1 * face.uv[1] + b2 * face.uv[2];
  const Eigen::Vector3f normal = b0 * face.normal[0] + b1 * face.normal[1] + b2 * face.normal[2];
  const float length = normal.norm();
  // Two-sided: a leaf sheet is lit alike from either side.
  const float cosine = length > 1e-6f
                           ? std::abs(normal.dot(light_world_)) / length
                           : static_cast<float>(std::abs(face.plane_normal.dot(light_cam_)));
  const Eigen::Vector3f albedo = Albedo(scene_.materials[face.material], uv);
  return albedo * (ambient_ + diffuse_ * cosine);
}

void TileRenderer::WritePixel(const Eigen::Vector3f& radiance, cv::Vec3b* out) const {
  for (int c = 0; c < 3; ++c) {
    (*out)[2 - c] = srgb_ ? srgb_->Encode(radiance[c]) : EncodeLinear(radiance[c]);
  }
}

void TileRenderer::GatherSurfaces(const SampleLattice& colour, int lx, int ly, int32_t centre_id,
                                  PixelSurfaces* out) const {
  const int n = grid_.n;
  const int32_t first = colour.triangle(lx * n, ly * n);
  bool uniform = true;
  for (int sy = 0; sy < n && uniform; ++sy) {
    for (int sx = 0; sx < n; ++sx) {
      uniform = uniform && colour.triangle(lx * n + sx, ly * n + sy) == first;
    }
  }
  if (uniform) {
    // The common case: one triangle (or none) covers the whole pixel.
    out->count = 1;
    out->triangle[0] = first;
    out->samples[0] = n * n;
    out->sum_x[0] = out->sum_y[0] = n * n * (n - 1) / 2;
    return;
  }
  out->count = 0;
  int32_t material[kMaxSamples], label[kMaxSamples];
  float inv_z[kMaxSamples];
  for (int sy = 0; sy < n; ++sy) {
    for (int sx = 0; sx < n; ++sx) {
      const int32_t id = colour.triangle(lx * n + sx, ly * n + sy);
      int k = 0;
      if (id < 0) {
        while (k < out->count && out->triangle[k] >= 0) ++k;
      } else {
        // Tiny triangles of one surface: join a group of the same face material and label at
        // nearly the same depth (their shading differs by less than the texture does).
        const FaceShading& face = frame_.shadings[frame_.triangles[id].shading];
        const float depth = colour.inv_z(lx * n + sx, ly * n + sy);
        while (k < out->count &&
               !(out->triangle[k] == id ||
                 (out->triangle[k] >= 0 && material[k] == face.material && label[k] == face.label &&
                  std::abs(inv_z[k] - depth) <= kSameSurfaceDepth * std::max(inv_z[k], depth)))) {
          ++k;
        }
        if (k == out->count) material[k] = face.material, label[k] = face.label, inv_z[k] = depth;
        // The group shades on the triangle seen at the pixel centre when it has it.
        if (k < out->count && id == centre_id) out->triangle[k] = id;
      }
      if (k == out->count) {
        out->triangle[k] = id, out->samples[k] = 0, out->sum_x[k] = 0, out->sum_y[k] = 0;
        ++out->count;
      }
      ++out->samples[k], out->sum_x[k] += sx, out->sum_y[k] += sy;
    }
  }
}

void TileRenderer::Render(const TileRect& rect, const uint32_t* first, const uint32_t* last,
                          TileScratch* scratch, RenderResult* result) const {
  const int n = grid_.n;
  const int width = rect.x1 - rect.x0, height = rect.y1 - rect.y0;
  scratch->background.resize(width);
  if (first == last) {
    // Nothing reaches this tile: background only.
    for (int v = rect.y0; v < rect.y1; ++v) {
      cv::Vec3b* color_row = result->color.ptr<cv::Vec3b>(v);
      background_.Row(v, rect.x0, rect.x1, scratch->background.data());
      for (int u = rect.x0; u < rect.x1; ++u) {
        WritePixel(scratch->background[u - rect.x0], &color_row[u]);
      }
      std::fill_n(result->depth.ptr<float>(v) + rect.x0, width, 0.0f);
      std::fill_n(result->labels.ptr<int32_t>(v) + rect.x0, width, 0);
    }
    return;
  }
  SampleLattice& colour = scratch->colour;
  SampleLattice& centre = scratch->centre;
  colour.Reset(int64_t{rect.x0} * n * kSubpixelScale, int64_t{rect.y0} * n * kSubpixelScale,
               kSubpixelScale, width * n, height * n);
  // Pixel centres sit on the colour lattice for odd n, between its samples for even n.
  const bool separate_centre = n % 2 == 0;
  if (separate_centre) {
    centre.Reset((int64_t{rect.x0} * n * 2 + n - 1) * (kSubpixelScale / 2),
                 (int64_t{rect.y0} * n * 2 + n - 1) * (kSubpixelScale / 2),
                 int64_t{n} * kSubpixelScale, width, height);
  }
  for (const uint32_t* it = first; it != last; ++it) {
    const RasterTriangle& t = frame_.triangles[*it];
    colour.Rasterize(t, static_cast<int32_t>(*it));
    if (separate_centre) centre.Rasterize(t, static_cast<int32_t>(*it));
  }

  const float inv_samples = 1.0f / static_cast<float>(n * n);
  const double half = 0.5 * (n - 1);
  for (int ly = 0; ly < height; ++ly) {
    const int v = rect.y0 + ly;
    cv::Vec3b* color_row = result->color.ptr<cv::Vec3b>(v);
    float* depth_row = result->depth.ptr<float>(v);
    int32_t* label_row = result->labels.ptr<int32_t>(v);
    background_.Row(v, rect.x0, rect.x1, scratch->background.data());
    for (int lx = 0; lx < width; ++lx) {
      const int u = rect.x0 + lx;
      const int32_t centre_id = separate_centre ? centre.triangle(lx, ly)
                                                : colour.triangle(lx * n + n / 2, ly * n + n / 2);
      PixelSurfaces surfaces;
      GatherSurfaces(colour, lx, ly, centre_id, &surfaces);
      const Eigen::Vector2d centre_s(u * n + half, v * n + half);
      bool have_centre_normalised = false;
      Eigen::Vector2d centre_normalised;

      Eigen::Vector3f radiance = Eigen::Vector3f::Zero();
      for (int k = 0; k < surfaces.count; ++k) {
        const float weight = static_cast<float>(surfaces.samples[k]);
        if (surfaces.triangle[k] < 0) {
          radiance += weight * scratch->background[lx];
          continue;
        }
        // Shade once per surface per pixel, at the centroid of its samples.
        const RasterTriangle& t = frame_.triangles[surfaces.triangle[k]];
        const Eigen::Vector2d s(u * n + static_cast<double>(surfaces.sum_x[k]) / weight,
                                v * n + static_cast<double>(surfaces.sum_y[k]) / weight);
        const Eigen::Vector2d normalised = Normalised(t, s);
        if (surfaces.triangle[k] == centre_id && s == centre_s) {
          centre_normalised = normalised;
          have_centre_normalised = true;
        }
        radiance += weight * Shade(t, normalised, s);
      }
      WritePixel(radiance * inv_samples, &color_row[u]);
      if (centre_id < 0) {
        depth_row[u] = 0.0f;
        label_row[u] = 0;
        continue;
      }
      const RasterTriangle& t = frame_.triangles[centre_id];
      if (!have_centre_normalised) centre_normalised = Normalised(t, centre_s);
      depth_row[u] = static_cast<float>(Depth(t, centre_normalised, centre_s));
      label_row[u] = frame_.shadings[t.shading].label;
    }
  }
}

}  // namespace avc::sim
