#pragma once

// What the renderer of the simulated cell is asked for and what it returns.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace avc::sim {

// What fills pixels (or samples) that no surface covers.
struct Background {
  enum class Kind {
    kPlain,  // one colour
    kCloth,  // mottled grey noise fixed to world directions, like a distant backdrop cloth
  };
  Kind kind = Kind::kPlain;
  Eigen::Vector3f rgb{0.35f, 0.35f, 0.35f};  // linear 0..1; the mean for kCloth
  float contrast = 0.35f;                    // kCloth: relative amplitude of the mottling
  double feature_deg = 3.0;  // kCloth: size of the coarsest blotches (degrees of view)
  uint32_t seed = 0;         // kCloth: which pattern
};

struct RenderOptions {
  // Anti-aliasing: n x n colour samples per pixel (1 = none). Depth and label always come from
  // the ray through the pixel centre (see RenderResult).
  int samples_per_pixel_axis = 2;
  // Light: unit-less direction from the surface towards the light. In the camera frame (a ring
  // flash or a studio light riding with the camera) unless light_in_world_frame.
  Eigen::Vector3d light_direction{0.2, -0.3, -1.0};
  bool light_in_world_frame = false;
  float ambient = 0.3f;  // radiance factor everywhere
  float diffuse = 0.7f;  // times |n . l| (two-sided: open leaf sheets are lit from either side)
  // Interpolated vertex normals (area-weighted) instead of flat faces.
  bool smooth_shading = true;
  Background background;
  // Surfaces closer than this (metres, along the optical axis) are clipped away.
  double near_clip_m = 0.01;
  // With lens distortion straight 3D edges image as curves; triangles are split until each
  // rasterised straight edge is within this many pixels of the true curve.
  double max_edge_error_px = 0.05;
  // sRGB-encode the linear colour (else write linear values scaled to 0..255).
  bool srgb = true;
};

struct RenderStats {
  size_t faces = 0;             // faces of the scene
  size_t raster_triangles = 0;  // after clipping and distortion subdivision, within the image
  size_t clipped_faces = 0;     // faces cut by the near plane or the guard band
  size_t subdivided_faces = 0;  // faces split because of lens distortion
};

// Images of one render. Depth and label of pixel (u, v) belong to the nearest surface along the
// ray through the pixel centre (u, v) (pixel centres at integer coordinates, as
// cv::projectPoints), so they never mix two surfaces at an edge; colour is the average of the
// n x n samples.
struct RenderResult {
  cv::Mat color;   // CV_8UC3, BGR (as cv::imwrite expects)
  cv::Mat depth;   // CV_32F, z in the camera frame (metres), 0 where no surface
  cv::Mat labels;  // CV_32S, face_labels of the visible face, 0 (kBackground) where none
  RenderStats stats;
};

}  // namespace avc::sim
