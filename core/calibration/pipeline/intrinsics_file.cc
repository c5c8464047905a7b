#include "core/calibration/pipeline/intrinsics_file.h"

#include <fmt/format.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/core/persistence.hpp>
#include <stdexcept>
#include <string>

#include "core/calibration/cell/calibration_yaml.h"
#include "core/util/file_io.h"

namespace avc::calibration {
namespace {

camera::Intrinsics FromOpenCvFile(const std::filesystem::path& path) {
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error(fmt::format("{}: {}", path.string(), what));
  };
  cv::FileStorage storage;
  try {
    if (!storage.open(path.string(), cv::FileStorage::READ)) fail("cannot be read");
  } catch (const cv::Exception& error) {
    fail(std::string("not an OpenCV calibration file: ") + error.what());
  }
  cv::Mat K, dist;
  storage["camera_matrix"] >> K;
  storage["distortion_coefficients"] >> dist;
  if (K.rows != 3 || K.cols != 3) fail("camera_matrix must be a 3x3 matrix");
  if (dist.empty() || (dist.rows != 1 && dist.cols != 1)) {
    fail("distortion_coefficients must be a vector (k1 k2 p1 p2 k3)");
  }
  K.convertTo(K, CV_64F);
  dist.convertTo(dist, CV_64F);
  camera::Intrinsics in;
  in.fx = K.at<double>(0, 0);
  in.fy = K.at<double>(1, 1);
  in.cx = K.at<double>(0, 2);
  in.cy = K.at<double>(1, 2);
  const int terms = static_cast<int>(dist.total());
  for (int i = 0; i < terms; ++i) {
    const double value = dist.at<double>(i);
    if (i < 5) {
      in.distortion[static_cast<size_t>(i)] = value;
    } else if (value != 0) {
      fail(
          fmt::format("distortion term {} is {}: only k1 k2 p1 p2 k3 are supported", i + 1, value));
    }
  }
  if (!storage["image_width"].empty()) in.width = static_cast<int>(storage["image_width"]);
  if (!storage["image_height"].empty()) in.height = static_cast<int>(storage["image_height"]);
  if (!std::isfinite(in.fx) || !std::isfinite(in.fy) || in.fx <= 0 || in.fy <= 0) {
    fail("camera_matrix must have positive, finite focal lengths");
  }
  return in;
}

}  // namespace

camera::Intrinsics ReadIntrinsicsFile(const std::filesystem::path& path) {
  const std::string text = ReadFile(path);
  if (text.find("camera_matrix") != std::string::npos) return FromOpenCvFile(path);
  return CalibrationFromYaml(text, path.string()).intrinsics;
}

}  // namespace avc::calibration
