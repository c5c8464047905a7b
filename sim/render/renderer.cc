#include "sim/render/renderer.h"

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>

#include "sim/render/background.h"
#include "sim/render/frame_geometry.h"
#include "sim/render/lens_model.h"
#include "sim/render/tile_bins.h"
#include "sim/render/tile_renderer.h"

namespace avc::sim {
namespace {

// Pixels per tile side: small enough to balance two threads and keep a tile's samples in cache.
constexpr int kTileSize = 32;

void ValidatePose(const camera::Camera& camera) {
  if (!camera.T_cam_world.matrix().allFinite()) {
    throw std::invalid_argument("camera pose T_cam_world is not finite");
  }
  const Eigen::Matrix3d R = camera.T_cam_world.linear();
  if (!((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-6)) {
    throw std::invalid_argument("camera pose T_cam_world has a rotation that is not orthonormal");
  }
}

}  // namespace

std::string ValidateRenderOptions(const RenderOptions& o) {
  if (o.samples_per_pixel_axis < 1 || o.samples_per_pixel_axis > 8) {
    return fmt::format("samples_per_pixel_axis {} is outside 1..8", o.samples_per_pixel_axis);
  }
  if (!o.light_direction.allFinite() || !(o.light_direction.norm() > 0)) {
    return "light_direction must be a finite non-zero vector";
  }
  if (!(o.ambient >= 0) || !(o.diffuse >= 0) || !std::isfinite(o.ambient) ||
      !std::isfinite(o.diffuse)) {
    return fmt::format("ambient {} and diffuse {} must be finite and non-negative", o.ambient,
                       o.diffuse);
  }
  if (!(o.near_clip_m > 0) || !std::isfinite(o.near_clip_m)) {
    return fmt::format("near_clip_m {} must be a positive distance", o.near_clip_m);
  }
  if (!(o.max_edge_error_px > 0) || !std::isfinite(o.max_edge_error_px)) {
    return fmt::format("max_edge_error_px {} must be positive", o.max_edge_error_px);
  }
  const Background& b = o.background;
  if (!b.rgb.allFinite() || !(b.contrast >= 0) || !std::isfinite(b.contrast) ||
      !(b.feature_deg > 0) || !std::isfinite(b.feature_deg)) {
    return "background rgb, contrast and feature_deg must be finite (contrast >= 0, "
           "feature_deg > 0)";
  }
  return {};
}

struct Renderer::Workspace {
  FrameGeometry frame;
  TileBins bins;
  tbb::enumerable_thread_specific<TileScratch> scratch;
};

Renderer::Renderer() : workspace_(std::make_unique<Workspace>()) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

void Renderer::Render(const Scene& scene, const camera::Camera& camera,
                      const RenderOptions& options, RenderResult* result) {
  const std::string bad_option = ValidateRenderOptions(options);
  if (!bad_option.empty()) throw std::invalid_argument("render options: " + bad_option);
  ValidatePose(camera);
  ValidateScene(scene);
  const LensModel lens(camera.intrinsics);
  const int width = camera.intrinsics.width, height = camera.intrinsics.height;

  for (cv::Mat* image : {&result->color, &result->depth, &result->labels}) {
    if (image->u && image->u->refcount > 1) image->release();  // someone keeps the old frame
  }
  result->color.create(height, width, CV_8UC3);
  result->depth.create(height, width, CV_32F);
  result->labels.create(height, width, CV_32S);

  FrameGeometry& frame = workspace_->frame;
  BuildFrameGeometry(scene, camera, lens, options, &frame);
  result->stats = frame.stats;
  TileBins& bins = workspace_->bins;
  bins.Build(width, height, kTileSize, SampleGrid{options.samples_per_pixel_axis}, frame.triangles);
  const Eigen::Matrix3d R_cam_world = camera.T_cam_world.linear();
  const BackgroundImage background(options.background, lens, R_cam_world.transpose());
  const TileRenderer renderer(scene, frame, lens, options, R_cam_world, background);
  tbb::enumerable_thread_specific<TileScratch>& scratch = workspace_->scratch;
  tbb::parallel_for(size_t{0}, bins.num_tiles(), [&](size_t tile) {
    renderer.Render(bins.Rect(tile), bins.begin(tile), bins.end(tile), &scratch.local(), result);
  });
}

RenderResult Render(const Scene& scene, const camera::Camera& camera,
                    const RenderOptions& options) {
  RenderResult result;
  Renderer().Render(scene, camera, options, &result);
  return result;
}

}  // namespace avc::sim
