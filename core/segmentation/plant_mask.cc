#include "core/segmentation/plant_mask.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/segmentation/mask_cleanup.h"
#include "core/segmentation/otsu.h"
#include "core/segmentation/plant_features.h"

namespace avc::segmentation {
namespace {

void CheckFraction(double value, const char* name) {
  if (!(value >= 0.0 && value <= 1.0)) {
    throw std::invalid_argument(std::string("SegmentPlant: MaskOptions.") + name +
                                " must be in [0, 1], got " + std::to_string(value));
  }
}

void CheckInputs(const cv::Mat& bgr, const MaskOptions& options) {
  if (bgr.empty()) throw std::invalid_argument("SegmentPlant: empty image");
  if (bgr.type() != CV_8UC3) {
    throw std::invalid_argument("SegmentPlant: image must be 8-bit BGR (CV_8UC3), got type " +
                                std::to_string(bgr.type()) + " with " +
                                std::to_string(bgr.channels()) + " channel(s)");
  }
  if (std::isinf(options.threshold)) {
    throw std::invalid_argument("SegmentPlant: MaskOptions.threshold is infinite");
  }
  if (options.histogram_bins < 2) {
    throw std::invalid_argument("SegmentPlant: MaskOptions.histogram_bins must be >= 2");
  }
  CheckFraction(options.dark_fraction, "dark_fraction");
  CheckFraction(options.border_fraction, "border_fraction");
  CheckFraction(options.min_component_fraction, "min_component_fraction");
  CheckFraction(options.min_component_image_fraction, "min_component_image_fraction");
  if (!(options.background_min_scale > 0) || !std::isfinite(options.background_min_scale)) {
    throw std::invalid_argument("SegmentPlant: MaskOptions.background_min_scale must be > 0");
  }
  CheckFraction(options.hysteresis, "hysteresis");
  if (!std::isfinite(options.green_min_exg)) {
    throw std::invalid_argument("SegmentPlant: MaskOptions.green_min_exg must be finite");
  }
  if (!(options.green_preference > 0) || !std::isfinite(options.green_preference)) {
    throw std::invalid_argument("SegmentPlant: MaskOptions.green_preference must be > 0");
  }
}

struct Candidate {
  MaskMethod method = MaskMethod::kExcessGreen;
  cv::Mat feature;
  OtsuSplit split;
};

Candidate Evaluate(const cv::Mat& bgr, MaskMethod method, const MaskOptions& options) {
  Candidate candidate{method, {}, {}};
  if (method == MaskMethod::kExcessGreen) {
    candidate.feature = ExcessGreen(bgr, options.dark_fraction);
  } else {
    const BackgroundModel model =
        EstimateBorderBackground(bgr, options.border_fraction, options.background_min_scale);
    candidate.feature = BackgroundDistance(bgr, model);
  }
  candidate.split = OtsuThreshold(candidate.feature, options.histogram_bins);
  return candidate;
}

// Means of the feature at or below and above `threshold` (0 for an empty class).
std::pair<double, double> ClassMeans(const cv::Mat& feature, double threshold) {
  double n[2] = {0, 0}, sum[2] = {0, 0};
  for (int y = 0; y < feature.rows; ++y) {
    const float* row = feature.ptr<float>(y);
    for (int x = 0; x < feature.cols; ++x) {
      const int c = row[x] > threshold ? 1 : 0;
      n[c] += 1.0;
      sum[c] += row[x];
    }
  }
  return {n[0] > 0 ? sum[0] / n[0] : 0.0, n[1] > 0 ? sum[1] / n[1] : 0.0};
}

// Pixels above `low` that are 8-connected to a pixel above `high`.
cv::Mat HysteresisThreshold(const cv::Mat& feature, double high, double low) {
  const cv::Mat strong = feature > high;
  const cv::Mat weak = feature > low;
  cv::Mat labels;
  const int count = cv::connectedComponents(weak, labels, 8, CV_32S);
  std::vector<uint8_t> seeded(static_cast<size_t>(count), 0);
  for (int y = 0; y < feature.rows; ++y) {
    const uint8_t* is_strong = strong.ptr<uint8_t>(y);
    const int* label = labels.ptr<int>(y);
    for (int x = 0; x < feature.cols; ++x) {
      if (is_strong[x]) seeded[static_cast<size_t>(label[x])] = 255;
    }
  }
  seeded[0] = 0;
  cv::Mat mask(feature.size(), CV_8UC1);
  for (int y = 0; y < feature.rows; ++y) {
    const int* label = labels.ptr<int>(y);
    uint8_t* out = mask.ptr<uint8_t>(y);
    for (int x = 0; x < feature.cols; ++x) out[x] = seeded[static_cast<size_t>(label[x])];
  }
  return mask;
}

int CloseRadius(const cv::Mat& bgr, const MaskOptions& options) {
  if (options.close_radius_px >= 0) return options.close_radius_px;
  return std::max(1, static_cast<int>(std::lround(std::min(bgr.cols, bgr.rows) / 400.0)));
}

}  // namespace

std::string MaskMethodName(MaskMethod method) {
  switch (method) {
    case MaskMethod::kAuto:
      return "auto";
    case MaskMethod::kExcessGreen:
      return "excess_green";
    case MaskMethod::kBackgroundDistance:
      return "background_distance";
  }
  return "unknown";
}

MaskResult SegmentPlant(const cv::Mat& bgr, const MaskOptions& options) {
  CheckInputs(bgr, options);
  Candidate chosen;
  if (options.method == MaskMethod::kAuto) {
    Candidate green = Evaluate(bgr, MaskMethod::kExcessGreen, options);
    Candidate background = Evaluate(bgr, MaskMethod::kBackgroundDistance, options);
    const bool green_is_plant =
        ClassMeans(green.feature, green.split.threshold).second >= options.green_min_exg;
    const bool green_wins = green_is_plant && green.split.separability * options.green_preference >=
                                                  background.split.separability;
    chosen = green_wins ? std::move(green) : std::move(background);
  } else {
    chosen = Evaluate(bgr, options.method, options);
  }

  MaskResult result;
  result.method = chosen.method;
  if (std::isnan(options.threshold)) {
    result.threshold = chosen.split.threshold;
    result.separability = chosen.split.separability;
  } else {
    result.threshold = options.threshold;
    result.separability = SplitSeparability(chosen.feature, options.threshold);
  }
  const double background_mean = ClassMeans(chosen.feature, result.threshold).first;
  result.low_threshold =
      result.threshold - options.hysteresis * std::max(0.0, result.threshold - background_mean);
  const cv::Mat raw = HysteresisThreshold(chosen.feature, result.threshold, result.low_threshold);
  CleanupOptions cleanup;
  cleanup.close_radius_px = CloseRadius(bgr, options);
  cleanup.min_component_fraction = options.min_component_fraction;
  cleanup.min_component_image_fraction = options.min_component_image_fraction;
  result.mask = CleanMask(raw, cleanup);
  return result;
}

}  // namespace avc::segmentation
