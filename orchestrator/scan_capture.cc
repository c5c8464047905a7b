#include "orchestrator/scan_capture.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/kinematics/row_major_pose.h"
#include "core/util/file_io.h"
#include "core/util/sha256.h"

namespace avc::orchestrator {
namespace {

constexpr double kDegree = M_PI / 180;

bool SamePose(const CaptureRecord& capture, const plan::ViewRequest& view, double tolerance) {
  const plan::ViewRequest recorded{Eigen::Map<const kinematics::JointVector>(capture.joints.data()),
                                   capture.table_angle};
  return plan::SameView(recorded, view, tolerance);
}

// The file's bytes, or nothing when it is missing or unreadable (it is then captured again).
std::string BytesIfReadable(const std::filesystem::path& path) {
  try {
    return ReadFile(path);
  } catch (const std::runtime_error&) {
    return {};
  }
}

std::string Extension(int8_t encoding) {
  switch (encoding) {
    case avc::image_t::ENCODING_PNG:
      return ".png";
    case avc::image_t::ENCODING_JPEG:
      return ".jpg";
    default:
      throw std::invalid_argument(fmt::format(
          "scan capture: image encoding {} is not stored as a file (ask for PNG or JPEG)",
          encoding));
  }
}

}  // namespace

std::string CaptureImageId(int index) { return fmt::format("view_{:04d}", index); }

ScanCapture::ScanCapture(client::CellClient& cell, std::filesystem::path scan_dir,
                         ScanRecord& record, std::function<void()> persist,
                         ScanCaptureOptions options,
                         std::function<void(const std::string&)> progress)
    : cell_(cell),
      scan_dir_(std::move(scan_dir)),
      record_(record),
      persist_(std::move(persist)),
      options_(std::move(options)),
      progress_(std::move(progress)) {
  Extension(options_.encoding);  // refuse an unstorable encoding before any motion
}

std::optional<cv::Mat> ScanCapture::operator()(const plan::ViewRequest& view) {
  const int index = next_index_++;
  const auto recorded = std::find_if(record_.captures.begin(), record_.captures.end(),
                                     [&](const CaptureRecord& c) { return c.index == index; });
  if (recorded != record_.captures.end()) {
    if (!SamePose(*recorded, view, options_.pose_tolerance)) {
      throw std::runtime_error(fmt::format(
          "{}: the planner now asks for turntable {:.2f} deg at other joints than the recorded "
          "capture (turntable {:.2f} deg); the scan's options or calibration changed since it "
          "started, so it cannot be resumed as it is",
          recorded->image_id, view.table_angle / kDegree, recorded->table_angle / kDegree));
    }
    const std::string bytes = BytesIfReadable(scan_dir_ / recorded->file);
    if (!bytes.empty() && Sha256Hex(bytes) == recorded->sha256) {
      const cv::Mat image = cv::imdecode(
          cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data())),
          cv::IMREAD_COLOR);
      if (!image.empty()) {
        ++reused_;
        if (progress_) progress_(fmt::format("{} from {}", recorded->image_id, recorded->file));
        return segmentation::SegmentPlant(image, options_.mask).mask;
      }
    }
    if (progress_) {
      progress_(fmt::format("{}: {} is missing or damaged; capturing it again", recorded->image_id,
                            recorded->file));
    }
  }
  try {
    return TakeLive(view, index);
  } catch (const client::CommandRefused& refusal) {
    if (progress_) progress_(fmt::format("{} skipped: {}", CaptureImageId(index), refusal.what()));
    return std::nullopt;
  }
}

cv::Mat ScanCapture::TakeLive(const plan::ViewRequest& view, int index) {
  const std::string image_id = CaptureImageId(index);
  cell_.SetPlantKeepOut(plant_keep_out_, options_.motion_timeout);
  cell_.MoveJoints(view.joints, options_.motion_timeout);
  cell_.TurntableGoto(view.table_angle, options_.motion_timeout);
  cell_.WaitFreshState(options_.motion_timeout);  // the state read after both motions ended
  const Eigen::Isometry3d reported_flange = cell_.last_flange_pose();
  const double reported_angle = cell_.last_table_angle();
  const client::CapturedView captured =
      cell_.Capture(image_id, options_.encoding, options_.capture_timeout);
  if (captured.image.encoding != options_.encoding) {
    throw std::runtime_error(fmt::format("{}: the camera sent encoding {} where {} was asked for",
                                         image_id, captured.image.encoding, options_.encoding));
  }
  const std::vector<uint8_t>& bytes = captured.image.data;
  const cv::Mat image = cv::imdecode(bytes, cv::IMREAD_COLOR);
  if (image.empty()) {
    throw std::runtime_error(
        fmt::format("{}: the camera's {} bytes do not decode as an image", image_id, bytes.size()));
  }
  if (options_.image_width > 0 &&
      (image.cols != options_.image_width || image.rows != options_.image_height)) {
    throw std::runtime_error(fmt::format(
        "{}: the camera delivered {}x{} but the calibration's camera is {}x{}; load the "
        "calibration of this camera at this resolution",
        image_id, image.cols, image.rows, options_.image_width, options_.image_height));
  }

  CaptureRecord capture;
  capture.index = index;
  capture.image_id = image_id;
  capture.file = "images/" + image_id + Extension(options_.encoding);
  std::filesystem::create_directories(scan_dir_ / "images");
  WriteFileAtomically(scan_dir_ / capture.file,
                      {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  capture.sha256 = Sha256Hex(bytes);
  for (int i = 0; i < 6; ++i) capture.joints[i] = view.joints[i];
  capture.table_angle = view.table_angle;
  kinematics::RowMajorFromIsometry(reported_flange, capture.reported_T_base_flange.data());
  capture.reported_table_angle = reported_angle;
  std::erase_if(record_.captures, [&](const CaptureRecord& c) { return c.index == index; });
  record_.captures.push_back(std::move(capture));
  std::sort(record_.captures.begin(), record_.captures.end(),
            [](const CaptureRecord& a, const CaptureRecord& b) { return a.index < b.index; });
  persist_();
  ++taken_;
  if (progress_) progress_(fmt::format("{} captured", image_id));
  return segmentation::SegmentPlant(image, options_.mask).mask;
}

void MarkPlannedViews(ScanRecord& record, const plan::FinalPlan& plan, double pose_tolerance) {
  // Captures and planned views are both in capture order; framing frames sit between them. A
  // frame at exactly a planned view's pose may take that view's marks: same pose, same picture.
  size_t next_view = 0;
  for (CaptureRecord& capture : record.captures) {
    capture.phase = "frame";
    capture.reason = "framing";
    capture.kept = false;
    if (next_view < plan.views.size() &&
        SamePose(capture, plan.views[next_view].view, pose_tolerance)) {
      const plan::PlannedView& planned = plan.views[next_view++];
      capture.phase = planned.phase;
      capture.reason = planned.reason;
      capture.kept = planned.kept;
    }
  }
}

}  // namespace avc::orchestrator
