#include "core/mvs/patch/features.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace avc::mvs::patch {
namespace {

// Fraction of the strongest response (over usable pixels) below which maxima are noise.
constexpr double kRelativeThreshold = 0.002;

void CollectMaxima(const cv::Mat& response, const cv::Mat& usable, FeatureType type, int block,
                   int per_block, std::vector<std::vector<Feature>>* blocks, int blocks_x) {
  cv::Mat dilated;
  cv::dilate(response, dilated, cv::Mat());
  double max_value = 0;
  cv::minMaxLoc(response, nullptr, &max_value, nullptr, nullptr, usable);
  const float threshold = static_cast<float>(kRelativeThreshold * max_value);
  std::vector<std::vector<Feature>> found(blocks->size());
  for (int y = 1; y < response.rows - 1; ++y) {
    const float* r = response.ptr<float>(y);
    const float* d = dilated.ptr<float>(y);
    const uint8_t* m = usable.ptr<uint8_t>(y);
    for (int x = 1; x < response.cols - 1; ++x) {
      if (!m[x] || r[x] <= threshold || r[x] < d[x]) continue;
      const size_t b = static_cast<size_t>(y / block) * blocks_x + x / block;
      found[b].push_back({static_cast<float>(x), static_cast<float>(y), r[x], type});
    }
  }
  for (size_t b = 0; b < found.size(); ++b) {
    auto& f = found[b];
    std::stable_sort(f.begin(), f.end(),
                     [](const Feature& a, const Feature& c) { return a.response > c.response; });
    if (static_cast<int>(f.size()) > per_block) f.resize(per_block);
    (*blocks)[b].insert((*blocks)[b].end(), f.begin(), f.end());
  }
}

}  // namespace

std::vector<Feature> DetectFeatures(const cv::Mat& bgr, const cv::Mat& usable, int block,
                                    int per_block) {
  cv::Mat grey, grey_f;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(grey_f, CV_32F, 1.0 / 255);
  const int blocks_x = (bgr.cols + block - 1) / block;
  const int blocks_y = (bgr.rows + block - 1) / block;
  std::vector<std::vector<Feature>> blocks(static_cast<size_t>(blocks_x) * blocks_y);

  cv::Mat harris;
  cv::cornerHarris(grey_f, harris, 3, 3, 0.06);
  CollectMaxima(harris, usable, FeatureType::kHarris, block, per_block, &blocks, blocks_x);

  cv::Mat fine, coarse, dog;
  cv::GaussianBlur(grey_f, fine, cv::Size(), 1.0);
  cv::GaussianBlur(grey_f, coarse, cv::Size(), 1.6);
  dog = cv::abs(fine - coarse);
  CollectMaxima(dog, usable, FeatureType::kDog, block, per_block, &blocks, blocks_x);

  std::vector<Feature> features;
  for (const auto& b : blocks) features.insert(features.end(), b.begin(), b.end());
  return features;
}

}  // namespace avc::mvs::patch
