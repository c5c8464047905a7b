#pragma once

// Per-frame geometry of a render: the scene's faces seen from the camera, cut into screen
// triangles the rasteriser can fill, and what shading a pixel of each face needs.
//
// Coverage uses straight-edged screen triangles in fixed point; depth and texture coordinates are
// not interpolated in screen space but taken from the exact ray through the sample, so they are
// right under lens distortion too.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "sim/render/lens_model.h"
#include "sim/render/render_options.h"
#include "sim/scene/scene.h"

namespace avc::sim {

// Supersample coordinates: with n samples per pixel axis, sample centres sit at integer S where
// S = (u + 0.5) n - 0.5 for pixel coordinate u (pixel centres at integer u, as OpenCV).
struct SampleGrid {
  int n = 1;
  double FromPixel(double u) const { return (u + 0.5) * n - 0.5; }
  double ToPixel(double s) const { return (s + 0.5) / n - 0.5; }
};

// Fixed-point precision of screen vertices: 1/256 of a sample spacing.
inline constexpr int kSubpixelBits = 8;
inline constexpr int32_t kSubpixelScale = 1 << kSubpixelBits;

// What shading a pixel of one scene face needs, camera frame for geometry.
struct FaceShading {
  Eigen::Vector3d plane_normal;  // unit; plane: plane_normal . p = plane_offset
  double plane_offset = 0;
  Eigen::Vector3d origin;  // the face's vertex 0
  // Barycentric weights of vertices 1 and 2 of a point p on the plane: bary . (p - origin).
  Eigen::Vector3f bary1, bary2;
  std::array<Eigen::Vector2f, 3> uv;
  std::array<Eigen::Vector3f, 3> normal;  // world frame, unit: vertex normals or the face normal
  int32_t material = 0;
  int32_t label = 0;
};

// One screen triangle, positively oriented, vertices in fixed-point supersample coordinates.
struct RasterTriangle {
  std::array<int32_t, 3> x, y;
  // 1/z at vertex 0 and its change per supersample unit (affine in screen space: exact without
  // distortion, used only to decide visibility).
  float inv_z0, inv_z_dx, inv_z_dy;
  int32_t shading;  // index into FrameGeometry::shadings
  // Normalised image coordinates (x/z, y/z) near the triangle ~ n0 + J (S - S0): the starting
  // point of the Newton step that undistorts a sample.
  double n0x, n0y;
  float jxx, jxy, jyx, jyy;
};

// A vertex in the camera frame with its image, as the tessellator uses it.
struct ScreenVertex {
  Eigen::Vector3d p;      // camera frame
  Eigen::Vector2d n;      // normalised (x/z, y/z)
  Eigen::Vector2d pixel;  // distorted projection
  Eigen::Vector2d s;      // supersample coordinates of pixel
  int64_t x = 0, y = 0;   // s in fixed point
  bool in_range = false;  // fixed point representable (always, inside the guard region)
};

// What one fixed chunk of faces produced, shading indices local to the chunk.
struct FrameChunk {
  std::vector<RasterTriangle> triangles;
  std::vector<FaceShading> shadings;
  RenderStats stats;
};

struct FrameGeometry {
  std::vector<FaceShading> shadings;      // one per face with triangles, in scene face order
  std::vector<RasterTriangle> triangles;  // in scene face order (the rasteriser's tie-break)
  RenderStats stats;

  // Working memory, kept so the next frame reuses it instead of faulting in fresh pages.
  std::vector<ScreenVertex> vertices;
  std::vector<uint8_t> outcodes;
  std::vector<Eigen::Vector3d> normal_sums;
  std::vector<Eigen::Vector3f> normals;
  std::vector<FrameChunk> chunks;
};

// Throws std::invalid_argument for a scene the renderer cannot draw (invalid mesh, missing
// attributes, material index out of range) naming the scene and the problem.
void ValidateScene(const Scene& scene);

// Transforms, clips, subdivides and sets up every face into *frame (replacing its contents,
// reusing its memory). Deterministic for any thread count.
void BuildFrameGeometry(const Scene& scene, const camera::Camera& camera, const LensModel& lens,
                        const RenderOptions& options, FrameGeometry* frame);

}  // namespace avc::sim
