#pragma once

// The views as the plane sweep works on them: checked, taken to the working pyramid level and
// converted to the grey image the ZNCC reads.

#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/dataset/view.h"

namespace avc::mvs {

struct SweepView {
  camera::Camera camera;  // at the working level
  cv::Mat colour;         // CV_8UC3 BGR
  cv::Mat grey;           // CV_32F, 0..1
  cv::Mat mask;           // CV_8UC1, 255 where to reconstruct (all of it when the input had none)
};

// Throws std::invalid_argument naming the view (index and name) and the field at fault.
void ValidateSweepInputs(const std::vector<dataset::View>& views);

// `requested` >= 0 is used as is; -1 picks the smallest level whose longer side is <= 800 px (the
// patch MVS rule).
int ChooseSweepLevel(const std::vector<dataset::View>& views, int requested);

std::vector<SweepView> PrepareSweepViews(const std::vector<dataset::View>& views, int level);

}  // namespace avc::mvs
