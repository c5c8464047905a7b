#pragma once

// PMVS's seed features: Harris corners and difference-of-Gaussian blobs, the strongest few per
// coarse block, so that seeds cover the image evenly.

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

namespace avc::mvs::patch {

enum class FeatureType : uint8_t { kHarris = 0, kDog = 1 };

struct Feature {
  float u = 0, v = 0;  // pixel (centres at integers)
  float response = 0;
  FeatureType type = FeatureType::kHarris;
};

// Local maxima (3x3) of each detector at usable pixels (CV_8UC1, non-zero), the strongest
// `per_block` of each detector in every block x block square; ordered by block, detector,
// strength. Responses below a small fraction of the image's strongest are ignored.
std::vector<Feature> DetectFeatures(const cv::Mat& bgr, const cv::Mat& usable, int block,
                                    int per_block);

}  // namespace avc::mvs::patch
