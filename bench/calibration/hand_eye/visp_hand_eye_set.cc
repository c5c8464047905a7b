#include "bench/calibration/hand_eye/visp_hand_eye_set.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>

#include "core/calibration/board/board_pose.h"
#include "core/calibration/board/visp_camera.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

// apriltag-data.txt: a line "size: <metres> m".
double ReadTagSize(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot be read", path.string()));
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("size:", 0) != 0) continue;
    std::istringstream value(line.substr(5));
    double size = 0;
    if (value >> size && std::isfinite(size) && size > 0) return size;
    throw std::runtime_error(fmt::format("{}: '{}' is not a positive size", path.string(), line));
  }
  throw std::runtime_error(fmt::format("{}: no 'size:' line", path.string()));
}

}  // namespace

Eigen::Isometry3d ReadVispRobotPose(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot be read", path.string()));
  // "data:" is followed by six "- [value]" lines.
  std::vector<double> values;
  std::string line;
  while (std::getline(in, line)) {
    const size_t open = line.find('['), close = line.find(']');
    if (line.find('-') == std::string::npos || open == std::string::npos || close < open) continue;
    std::istringstream number(line.substr(open + 1, close - open - 1));
    double value = 0;
    if (!(number >> value) || !std::isfinite(value)) {
      throw std::runtime_error(fmt::format("{}: '{}' is not a number", path.string(), line));
    }
    values.push_back(value);
  }
  if (values.size() != 6) {
    throw std::runtime_error(
        fmt::format("{}: {} values, expected 6 (tx ty tz and a rotation vector)", path.string(),
                    values.size()));
  }
  const cv::Mat rvec = (cv::Mat_<double>(3, 1) << values[3], values[4], values[5]);
  const cv::Mat tvec = (cv::Mat_<double>(3, 1) << values[0], values[1], values[2]);
  return calibration::PoseFromRvecTvec(rvec, tvec);
}

VispHandEyeSet ReadVispHandEyeSet(const fs::path& folder, const std::string& robot, int tag_id) {
  VispHandEyeSet set;
  set.intrinsics = calibration::ReadVispCameraXml(folder / fmt::format("{}_camera.xml", robot));
  set.tag_size = ReadTagSize(folder / "apriltag-data.txt");
  set.tag_id = tag_id;
  for (int i = 1; fs::exists(folder / fmt::format("{}_pose_rPe_{}.yaml", robot, i)); ++i) {
    VispShot shot;
    shot.T_base_flange = ReadVispRobotPose(folder / fmt::format("{}_pose_rPe_{}.yaml", robot, i));
    shot.image = fmt::format("{}_image-{}.png", robot, i);
    const cv::Mat image = cv::imread((folder / shot.image).string(), cv::IMREAD_GRAYSCALE);
    if (image.empty()) {
      throw std::runtime_error(
          fmt::format("{}: missing or unreadable (pose {} has no image)", shot.image, i));
    }
    shot.tag = calibration::DetectTagPose(image, tag_id, set.tag_size, set.intrinsics, shot.image);
    set.shots.push_back(std::move(shot));
  }
  if (set.shots.empty()) {
    throw std::runtime_error(fmt::format("{}: no {}_pose_rPe_1.yaml", folder.string(), robot));
  }
  return set;
}

std::vector<calibration::hand_eye::HandEyeObservation> EyeToHandObservations(
    const VispHandEyeSet& set) {
  std::vector<calibration::hand_eye::HandEyeObservation> observations;
  for (const VispShot& shot : set.shots) {
    observations.push_back({shot.T_base_flange.inverse(), shot.tag.T_cam_tag});
  }
  return observations;
}

std::vector<calibration::hand_eye::BoardView> EyeToHandBoardViews(const VispHandEyeSet& set) {
  std::vector<calibration::hand_eye::BoardView> views;
  const std::vector<cv::Point3f> corners = calibration::TagCornerPoints(set.tag_size);
  for (const VispShot& shot : set.shots) {
    calibration::hand_eye::BoardView view;
    view.T_base_flange = shot.T_base_flange.inverse();
    for (size_t c = 0; c < corners.size(); ++c) {
      view.board_points.emplace_back(corners[c].x, corners[c].y, corners[c].z);
      view.pixels.emplace_back(shot.tag.corners[c].x, shot.tag.corners[c].y);
    }
    views.push_back(std::move(view));
  }
  return views;
}

}  // namespace avc::bench
