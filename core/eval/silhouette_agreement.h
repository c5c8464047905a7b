#pragma once

// The Middlebury-style check of MVS points without a ground-truth mesh: the fraction of points
// that project inside the silhouette of every view that sees them (a point outside any of them
// is off the object).

#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/dataset/view.h"
#include "core/mvs/mvs_points.h"

namespace avc::eval {

// silhouettes[i] is view i's (CV_8UC1, non-zero = object). A point whose view list is empty
// counts as outside.
double InsideAllSilhouettesFraction(const mvs::MvsPoints& points,
                                    const std::vector<dataset::View>& views,
                                    const std::vector<cv::Mat>& silhouettes);

}  // namespace avc::eval
