#pragma once

// The scan's capture step in the live cell, with the scan's memory. Each view the planner
// (avc-planner) asks for is taken through the drivers (arm, turntable and camera over the bus);
// its image is written into the scan directory and recorded in scan.json before the planner gets
// its mask. A resumed scan plans again over the same record: the planner is deterministic, so it
// asks for the same views in the same order, and each view already on disk is answered from its
// file with no motion. Only views whose file is missing or damaged are captured again.

#include <avc/image_t.hpp>
#include <chrono>
#include <filesystem>
#include <functional>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>

#include "core/plan/plan_exchange.h"
#include "core/segmentation/plant_mask.h"
#include "drivers/client/cell_client.h"
#include "orchestrator/scan_record.h"

namespace avc::orchestrator {

struct ScanCaptureOptions {
  // PNG is lossless (the simulated camera); JPEG keeps a real camera's own file.
  int8_t encoding = avc::image_t::ENCODING_PNG;
  std::chrono::milliseconds motion_timeout{60000};
  std::chrono::milliseconds capture_timeout{60000};
  // A recorded capture answers a request only at the same joints and table angle (radians).
  double pose_tolerance = 1e-6;
  segmentation::MaskOptions mask;
  // The calibration's image size: a camera delivering another is a fault (0: not checked).
  int image_width = 0;
  int image_height = 0;
};

class ScanCapture {
 public:
  // `persist` runs after every capture is added to `record` (it saves scan.json); `progress`
  // (optional) hears one line per view.
  ScanCapture(client::CellClient& cell, std::filesystem::path scan_dir, ScanRecord& record,
              std::function<void()> persist, ScanCaptureOptions options = {},
              std::function<void(const std::string&)> progress = {});

  // The plant mask of the view, or nullopt when the arm or the turntable refused it
  // (unreachable, outside the safety envelope: the planner skips it).
  // Throws std::runtime_error when the cell failed (a timeout, a device fault, an image that
  // does not decode) or the request contradicts the record (the plan changed): the scan then
  // stops with nothing lost and can be resumed.
  std::optional<cv::Mat> operator()(const plan::ViewRequest& view);

  // The plant's space the arm must stay out of from now on (empty: no plant known yet). It
  // goes to the arm's driver before every live move, so a restarted driver gets it back and a
  // new scan never inherits the previous plant's.
  void SetPlantKeepOut(kinematics::PlantKeepOut keep_out) { plant_keep_out_ = std::move(keep_out); }

  int taken() const { return taken_; }    // captured through the cell in this run
  int reused() const { return reused_; }  // answered from the scan directory

 private:
  cv::Mat TakeLive(const plan::ViewRequest& view, int index);

  client::CellClient& cell_;
  std::filesystem::path scan_dir_;
  ScanRecord& record_;
  std::function<void()> persist_;
  ScanCaptureOptions options_;
  std::function<void(const std::string&)> progress_;
  kinematics::PlantKeepOut plant_keep_out_;
  int next_index_ = 0;
  int taken_ = 0;
  int reused_ = 0;
};

// The image id of the index-th capture of a scan: view_0000, view_0001, ...
std::string CaptureImageId(int index);

// After the final plan: each capture gets its phase ("initial" or "active"), the reason it was
// chosen and whether Phase 3 kept it, matched by pose; captures the planner did not keep as
// views (framing frames, skipped requests) become phase "frame", not kept.
void MarkPlannedViews(ScanRecord& record, const plan::FinalPlan& plan,
                      double pose_tolerance = 1e-6);

}  // namespace avc::orchestrator
