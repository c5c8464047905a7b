#pragma once

// Deterministic CPU renderer of the simulated cell: a tiled z-buffer rasteriser with OpenCV lens
// distortion, exact per-sample depth and texture coordinates, Lambert + ambient lighting,
// supersampled anti-aliasing and sRGB output. Same scene, camera and options give the same bytes
// on any number of threads.
//
// How, and how exact:
// - Faces are clipped in 3D against the near plane and a guard region of the image plane (where
//   the distortion polynomial does not fold), projected with the cv::projectPoints polynomial,
//   and rasterised as straight-edged triangles in fixed point (1/256 sample) with a top-left fill
//   rule, so shared edges neither crack nor double-cover.
// - Distortion bends straight edges: a triangle edge whose image midpoint strays more than
//   options.max_edge_error_px (default 0.05 px) from its chord is split (decided per edge, so
//   neighbours agree). Coverage is then within ~0.05 px of the true curved outline (the tests
//   measure < 0.05 px against cv::projectPoints).
// - The z-test uses 1/z interpolated affinely in screen space (exact without distortion, within
//   the same 0.05 px budget with it). Depth, texture coordinates and normals of a visible surface
//   are not interpolated in screen space: each comes from the exact ray through the sample
//   (Newton-undistorted, ~1e-6 px) hitting the face's plane, so depth is exact to float precision.
// - Anti-aliasing: n x n colour samples per pixel; each surface covering some samples is shaded
//   once per pixel at the centroid of its samples (Albedo is the costly part) and weighted by its
//   sample count. Depth and label come from a separate sample at the pixel centre (one of the n x n
//   for odd n), i.e. the nearest surface along Intrinsics::Ray(u, v): never a blend.
// - Work is split into 32 x 32 pixel tiles with triangles binned in scene order; each tile is
//   rendered by one task from its own data, and depth ties keep the earlier face, so the result
//   does not depend on the thread count or timing.

#include <memory>
#include <string>

#include "core/camera/pinhole_camera.h"
#include "sim/render/render_options.h"
#include "sim/scene/scene.h"

namespace avc::sim {

// Renders frame after frame, keeping its working memory (tens of MB for a 100k-triangle scene)
// between them so a frame does not pay for faulting in fresh pages. One Render at a time per
// Renderer (it is not shared between concurrent callers); the result does not depend on what
// was rendered before.
class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;

  // Renders scene (world frame) as seen by camera into *result, reusing its images when they
  // have the right size and type and nothing else shares them. Throws std::invalid_argument
  // naming the problem for an invalid mesh, a face whose material index is out of range,
  // missing uvs / labels / materials, unusable intrinsics or pose, or out-of-range options.
  void Render(const Scene& scene, const camera::Camera& camera, const RenderOptions& options,
              RenderResult* result);

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

// One frame with a throw-away Renderer; see Renderer::Render.
RenderResult Render(const Scene& scene, const camera::Camera& camera, const RenderOptions& options);

// Empty when usable, else a sentence naming the bad option.
std::string ValidateRenderOptions(const RenderOptions& options);

}  // namespace avc::sim
