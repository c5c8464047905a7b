#include "core/mvs/plane_sweep/box_mean.h"

#include <algorithm>
#include <vector>

namespace avc::mvs {

void BoxMean(const cv::Mat& src, int radius, cv::Mat& dst) {
  CV_Assert(src.type() == CV_32F && radius >= 0);
  const int rows = src.rows;
  const int cols = src.cols;
  cv::Mat horizontal(rows, cols, CV_32F);
  // Horizontal window sums, then vertical sums of those; counts give the clipped-window mean.
  for (int y = 0; y < rows; ++y) {
    const float* in = src.ptr<float>(y);
    float* out = horizontal.ptr<float>(y);
    double sum = 0;
    for (int x = 0; x < std::min(radius, cols); ++x) sum += in[x];
    for (int x = 0; x < cols; ++x) {
      if (x + radius < cols) sum += in[x + radius];
      if (x - radius - 1 >= 0) sum -= in[x - radius - 1];
      out[x] = static_cast<float>(sum);
    }
  }
  std::vector<float> col_count(static_cast<size_t>(cols));
  for (int x = 0; x < cols; ++x) {
    col_count[static_cast<size_t>(x)] =
        static_cast<float>(std::min(cols - 1, x + radius) - std::max(0, x - radius) + 1);
  }
  dst.create(rows, cols, CV_32F);
  std::vector<double> sums(static_cast<size_t>(cols), 0.0);
  for (int y = 0; y < std::min(radius, rows); ++y) {
    const float* in = horizontal.ptr<float>(y);
    for (int x = 0; x < cols; ++x) sums[static_cast<size_t>(x)] += in[x];
  }
  for (int y = 0; y < rows; ++y) {
    if (y + radius < rows) {
      const float* add = horizontal.ptr<float>(y + radius);
      for (int x = 0; x < cols; ++x) sums[static_cast<size_t>(x)] += add[x];
    }
    if (y - radius - 1 >= 0) {
      const float* sub = horizontal.ptr<float>(y - radius - 1);
      for (int x = 0; x < cols; ++x) sums[static_cast<size_t>(x)] -= sub[x];
    }
    const double row_count = std::min(rows - 1, y + radius) - std::max(0, y - radius) + 1;
    float* out = dst.ptr<float>(y);
    for (int x = 0; x < cols; ++x) {
      out[x] = static_cast<float>(sums[static_cast<size_t>(x)] /
                                  (row_count * col_count[static_cast<size_t>(x)]));
    }
  }
}

}  // namespace avc::mvs
