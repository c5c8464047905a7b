#include "core/segmentation/plant_features.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace avc::segmentation {
namespace {

// R + G + B below which `fraction` of the pixels lie (0..765), from an exact histogram.
int SumPercentile(const cv::Mat& bgr, double fraction) {
  std::array<double, 766> count{};
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3b* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; ++x) count[row[x][0] + row[x][1] + row[x][2]] += 1.0;
  }
  const double wanted = fraction * static_cast<double>(bgr.total());
  double seen = 0;
  for (int s = 0; s < 766; ++s) {
    seen += count[static_cast<size_t>(s)];
    if (seen >= wanted) return s;
  }
  return 765;
}

cv::Mat ToLab(const cv::Mat& bgr) {
  cv::Mat unit, lab;
  bgr.convertTo(unit, CV_32FC3, 1.0 / 255.0);
  cv::cvtColor(unit, lab, cv::COLOR_BGR2Lab);
  return lab;
}

float Median(std::vector<float>& values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

cv::Mat ExcessGreen(const cv::Mat& bgr, double dark_fraction) {
  const float dark_level =
      std::max(1.0f, static_cast<float>(dark_fraction * SumPercentile(bgr, 0.99)));
  cv::Mat exg(bgr.size(), CV_32FC1);
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3b* in = bgr.ptr<cv::Vec3b>(y);
    float* out = exg.ptr<float>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      const float b = in[x][0], g = in[x][1], r = in[x][2];
      out[x] = (2.0f * g - r - b) / std::max(r + g + b, dark_level);
    }
  }
  return exg;
}

BackgroundModel EstimateBorderBackground(const cv::Mat& bgr, double border_fraction,
                                         double min_scale) {
  const int strip =
      std::max(1, static_cast<int>(std::lround(border_fraction * std::min(bgr.cols, bgr.rows))));
  const cv::Mat lab = ToLab(bgr);
  std::array<std::vector<float>, 3> channel;
  for (int y = 0; y < lab.rows; ++y) {
    const cv::Vec3f* row = lab.ptr<cv::Vec3f>(y);
    const bool full_row = y < strip || y >= lab.rows - strip;
    for (int x = 0; x < lab.cols; ++x) {
      if (!full_row && x >= strip && x < lab.cols - strip) continue;
      for (int c = 0; c < 3; ++c) channel[static_cast<size_t>(c)].push_back(row[x][c]);
    }
  }
  BackgroundModel model;
  for (int c = 0; c < 3; ++c) {
    std::vector<float>& values = channel[static_cast<size_t>(c)];
    const float median = Median(values);
    for (float& v : values) v = std::abs(v - median);
    model.median_lab[c] = median;
    model.scale_lab[c] = std::max(static_cast<float>(min_scale), 1.4826f * Median(values));
  }
  return model;
}

cv::Mat BackgroundDistance(const cv::Mat& bgr, const BackgroundModel& model) {
  const cv::Mat lab = ToLab(bgr);
  cv::Mat distance(bgr.size(), CV_32FC1);
  for (int y = 0; y < lab.rows; ++y) {
    const cv::Vec3f* in = lab.ptr<cv::Vec3f>(y);
    float* out = distance.ptr<float>(y);
    for (int x = 0; x < lab.cols; ++x) {
      float sum = 0;
      for (int c = 0; c < 3; ++c) {
        const float d = (in[x][c] - model.median_lab[c]) / model.scale_lab[c];
        sum += d * d;
      }
      out[x] = std::sqrt(sum);
    }
  }
  return distance;
}

}  // namespace avc::segmentation
