#pragma once

// One measured configuration of `avc bench render`: a scene rendered from views around it with
// given options and thread count.

#include <cstddef>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "sim/render/render_options.h"
#include "sim/scene/scene.h"

namespace avc::bench {

struct RenderCaseSpec {
  std::string name;
  int width = 1280, height = 960;
  int views = 12;
  int threads = 2;
  sim::RenderOptions options;
};

struct RenderCaseResult {
  RenderCaseSpec spec;
  size_t triangles = 0;         // scene faces
  size_t raster_triangles = 0;  // median over views, after clipping and subdivision
  double median_ms = 0, p90_ms = 0, max_ms = 0;
  // Process CPU time (user + system, all threads) per frame: the work itself, which other load
  // on the machine inflates far less than the wall-clock times above.
  double cpu_ms_per_frame = 0;
  double max_rss_mb = 0;  // process peak after the case (getrusage; never decreases)
  double coverage = 0;    // mean fraction of pixels showing the scene
};

// The bench camera: a 1280x960-class lens (fx = 1.1 x width) with mild barrel distortion.
camera::Intrinsics BenchIntrinsics(int width, int height);
// Cameras on a ring around the scene's bounds, alternating 20 and 45 degrees of elevation, at
// 0.75 of the distance where the scene's bounding sphere fills the narrower field of view.
std::vector<camera::Camera> ViewsAround(const sim::Scene& scene, const camera::Intrinsics& k,
                                        int count);

// Renders every view once to warm up, then times each; thread count capped with
// tbb::global_control.
RenderCaseResult RunRenderCase(const sim::Scene& scene, const RenderCaseSpec& spec);

}  // namespace avc::bench
