#include "core/calibration/board/tag_detection.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/aruco.hpp>
#include <stdexcept>

#include "core/calibration/board/board_pose.h"

namespace avc::calibration {

std::vector<TagDetection> DetectAprilTags36h11(const cv::Mat& image, const std::string& name) {
  if (image.empty()) throw std::invalid_argument(fmt::format("image '{}' is empty", name));
  if (image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3))
    throw std::invalid_argument(
        fmt::format("image '{}' must be 8-bit grey or BGR for tag detection", name));
  const cv::Ptr<cv::aruco::Dictionary> dictionary =
      cv::aruco::getPredefinedDictionary(cv::aruco::DICT_APRILTAG_36h11);
  const cv::Ptr<cv::aruco::DetectorParameters> parameters = cv::aruco::DetectorParameters::create();
  parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<int> ids;
  cv::aruco::detectMarkers(image, dictionary, corners, ids, parameters);
  std::vector<TagDetection> tags;
  for (size_t i = 0; i < ids.size(); ++i) {
    if (corners[i].size() != 4) continue;
    TagDetection tag;
    tag.id = ids[i];
    std::copy(corners[i].begin(), corners[i].end(), tag.corners.begin());
    tags.push_back(tag);
  }
  std::stable_sort(tags.begin(), tags.end(),
                   [](const TagDetection& a, const TagDetection& b) { return a.id < b.id; });
  return tags;
}

std::vector<cv::Point3f> TagCornerPoints(double size) {
  const float h = static_cast<float>(size / 2);
  return {{-h, h, 0}, {h, h, 0}, {h, -h, 0}, {-h, -h, 0}};
}

TagPose DetectTagPose(const cv::Mat& image, int id, double size,
                      const camera::Intrinsics& intrinsics, const std::string& name) {
  if (!std::isfinite(size) || !(size > 0))
    throw std::invalid_argument(
        fmt::format("tag pose '{}': tag size {} m must be positive", name, size));
  const std::vector<TagDetection> tags = DetectAprilTags36h11(image, name);
  const auto tag =
      std::find_if(tags.begin(), tags.end(), [id](const TagDetection& t) { return t.id == id; });
  if (tag == tags.end())
    throw std::runtime_error(
        fmt::format("AprilTag 36h11 id {} not found in image '{}' ({} other "
                    "tag(s) seen)",
                    id, name, tags.size()));
  const std::vector<cv::Point2f> corners(tag->corners.begin(), tag->corners.end());
  const BoardPose pose = EstimateBoardPose(TagCornerPoints(size), corners, intrinsics, name);
  return {pose.T_cam_board, pose.rms_px, tag->corners};
}

}  // namespace avc::calibration
