#include "core/segmentation/otsu.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace avc::segmentation {
namespace {

void CheckFeatureImage(const cv::Mat& values, const char* who) {
  if (values.empty()) throw std::invalid_argument(std::string(who) + ": empty feature image");
  if (values.type() != CV_32FC1) {
    throw std::invalid_argument(std::string(who) + ": feature image must be CV_32FC1, got type " +
                                std::to_string(values.type()));
  }
}

}  // namespace

OtsuSplit OtsuThreshold(const cv::Mat& values, int bins) {
  CheckFeatureImage(values, "OtsuThreshold");
  if (bins < 2) throw std::invalid_argument("OtsuThreshold: bins must be >= 2");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int y = 0; y < values.rows; ++y) {
    const float* row = values.ptr<float>(y);
    for (int x = 0; x < values.cols; ++x) {
      if (!std::isfinite(row[x])) {
        throw std::invalid_argument("OtsuThreshold: non-finite feature value at (" +
                                    std::to_string(x) + ", " + std::to_string(y) + ")");
      }
      lo = std::min(lo, static_cast<double>(row[x]));
      hi = std::max(hi, static_cast<double>(row[x]));
    }
  }
  if (hi <= lo) return {lo, 0.0};

  const double width = (hi - lo) / bins;
  std::vector<double> count(static_cast<size_t>(bins), 0.0);
  for (int y = 0; y < values.rows; ++y) {
    const float* row = values.ptr<float>(y);
    for (int x = 0; x < values.cols; ++x) {
      const int bin = std::min(bins - 1, static_cast<int>((row[x] - lo) / width));
      count[static_cast<size_t>(bin)] += 1.0;
    }
  }
  // Moments over bin centres; the total variance uses the same centres so eta stays in [0, 1].
  double total = 0, sum = 0, sum_sq = 0;
  for (int b = 0; b < bins; ++b) {
    const double centre = lo + (b + 0.5) * width;
    total += count[static_cast<size_t>(b)];
    sum += count[static_cast<size_t>(b)] * centre;
    sum_sq += count[static_cast<size_t>(b)] * centre * centre;
  }
  const double mean = sum / total;
  const double total_variance = sum_sq / total - mean * mean;

  double best_between = -1, w0 = 0, sum0 = 0;
  int best_bin = 0;
  for (int b = 0; b < bins - 1; ++b) {
    w0 += count[static_cast<size_t>(b)];
    sum0 += count[static_cast<size_t>(b)] * (lo + (b + 0.5) * width);
    const double w1 = total - w0;
    if (w0 <= 0 || w1 <= 0) continue;
    const double mu0 = sum0 / w0, mu1 = (sum - sum0) / w1;
    const double between = (w0 / total) * (w1 / total) * (mu0 - mu1) * (mu0 - mu1);
    if (between > best_between) best_between = between, best_bin = b;
  }
  OtsuSplit split;
  split.threshold = lo + (best_bin + 1) * width;
  split.separability =
      total_variance > 0 ? std::clamp(best_between / total_variance, 0.0, 1.0) : 0.0;
  return split;
}

double SplitSeparability(const cv::Mat& values, double threshold) {
  CheckFeatureImage(values, "SplitSeparability");
  double n[2] = {0, 0}, sum[2] = {0, 0}, sum_sq = 0;
  for (int y = 0; y < values.rows; ++y) {
    const float* row = values.ptr<float>(y);
    for (int x = 0; x < values.cols; ++x) {
      const int c = row[x] > threshold ? 1 : 0;
      n[c] += 1.0;
      sum[c] += row[x];
      sum_sq += static_cast<double>(row[x]) * row[x];
    }
  }
  const double total = n[0] + n[1];
  const double mean = (sum[0] + sum[1]) / total;
  const double total_variance = sum_sq / total - mean * mean;
  if (n[0] == 0 || n[1] == 0 || total_variance <= 0) return 0.0;
  const double d = sum[0] / n[0] - sum[1] / n[1];
  return std::clamp((n[0] / total) * (n[1] / total) * d * d / total_variance, 0.0, 1.0);
}

}  // namespace avc::segmentation
