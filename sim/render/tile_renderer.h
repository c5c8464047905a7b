#pragma once

// Renders one screen tile: rasterises the tile's triangles into its sample lattices, then shades
// each pixel (colour from its n x n samples, depth and label from its centre) into the output
// images. Tiles are independent, so any number of threads produce the same bytes.

#include <Eigen/Core>
#include <vector>

#include "sim/render/background.h"
#include "sim/render/frame_geometry.h"
#include "sim/render/lens_model.h"
#include "sim/render/render_options.h"
#include "sim/render/sample_lattice.h"
#include "sim/render/srgb.h"
#include "sim/render/tile_bins.h"
#include "sim/scene/scene.h"

namespace avc::sim {

// Per-thread working memory, reused from tile to tile.
struct TileScratch {
  SampleLattice colour;                     // n x n samples per pixel
  SampleLattice centre;                     // one sample per pixel centre (used when n is even)
  std::vector<Eigen::Vector3f> background;  // the background of the current tile row
};

inline constexpr int kMaxSamples = 64;  // n <= 8

// The surfaces one pixel's samples see: background (triangle -1) or groups of triangles of one
// surface, each with the triangle to shade it on, its sample count and the sums of the samples'
// offsets in the pixel (for the centroid).
struct PixelSurfaces {
  int count = 0;
  int32_t triangle[kMaxSamples];
  int samples[kMaxSamples];
  int sum_x[kMaxSamples], sum_y[kMaxSamples];
};

class TileRenderer {
 public:
  TileRenderer(const Scene& scene, const FrameGeometry& frame, const LensModel& lens,
               const RenderOptions& options, const Eigen::Matrix3d& R_cam_world,
               const BackgroundImage& background);

  void Render(const TileRect& rect, const uint32_t* first, const uint32_t* last,
              TileScratch* scratch, RenderResult* result) const;

 private:
  void GatherSurfaces(const SampleLattice& colour, int lx, int ly, int32_t centre_id,
                      PixelSurfaces* out) const;
  void WritePixel(const Eigen::Vector3f& radiance, cv::Vec3b* out) const;
  // Exact normalised coordinates (x/z, y/z) of supersample position s on triangle t.
  Eigen::Vector2d Normalised(const RasterTriangle& t, const Eigen::Vector2d& s) const;
  // Depth along the ray through normalised n to the triangle's face plane.
  double Depth(const RasterTriangle& t, const Eigen::Vector2d& n, const Eigen::Vector2d& s) const;
  // Linear radiance of the face of t seen through normalised n.
  Eigen::Vector3f Shade(const RasterTriangle& t, const Eigen::Vector2d& n,
                        const Eigen::Vector2d& s) const;

  const Scene& scene_;
  const FrameGeometry& frame_;
  const LensModel& lens_;
  SampleGrid grid_;
  Eigen::Vector3f light_world_;
  Eigen::Vector3d light_cam_;
  float ambient_, diffuse_;
  const SrgbTable* srgb_;  // null: linear output
  const BackgroundImage& background_;
};

}  // namespace avc::sim
