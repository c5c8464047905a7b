#pragma once

// One reference view's depth map by fronto-parallel plane sweeping: planes uniform in inverse
// depth, each neighbour warped by the plane homography, windowed ZNCC, best-k aggregation,
// winner-take-all among the planes inside each pixel's interval, parabola sub-plane refinement.

#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/mvs/depth_range.h"
#include "core/mvs/plane_sweep/plane_sweep_mvs.h"
#include "core/mvs/plane_sweep/sweep_views.h"

namespace avc::mvs {

struct SweepDepthMap {
  cv::Mat depth;   // CV_32F, metres along the optical axis; 0 = no estimate
  cv::Mat score;   // CV_32F, aggregated ZNCC of the winning plane (-1 where no estimate)
  int planes = 0;  // planes swept
};

// Inverse-depth spacing so that neighbouring planes move a covered pixel's projection in any
// neighbour by at most max_step_px (estimated on a grid of covered pixels).
double InverseDepthStep(const SweepView& reference, const std::vector<const SweepView*>& others,
                        const DepthRange& range, double max_step_px);

SweepDepthMap SweepReference(const SweepView& reference,
                             const std::vector<const SweepView*>& neighbours,
                             const DepthRange& range, const PlaneSweepOptions& options);

}  // namespace avc::mvs
