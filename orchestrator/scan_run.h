#pragma once

// One scan from the cell to the plant's traits, walked through the scan state machine
// (scan_states.h) and persisted in scan.json after every step (scan_record.h), so running it
// again on the same directory resumes where it stopped, without capturing again what is on disk.
//
//   CHECK_DEVICES     the drivers READY, the arm powered and its brakes released
//   LOAD_CALIBRATION  calibration.yaml read, checked against the camera, kept in the scan
//   FRAME .. PRUNE_VIEWS  Algorithm 1: plan jobs for avc-planner (core/plan/plan_exchange.h),
//                     one per view, each view captured through the drivers (scan_capture.h);
//                     the planner is deterministic, so a resumed scan plans again from the
//                     recorded images
//   BUILD             masks, plant proxy and MVS on the kept views   -> model/ppr.bt, points.ply
//   MERGE_CLUSTER     merging and Algorithm 2 from those files        -> model/clusters.ply
//   SURFACE, TRAITS   Algorithm 3 and the traits                     -> model/mesh.ply, traits.*
//                     each a job for its stage service over the bus (scan_stage_jobs.h): the
//                     scan sends the files, the service sends back what it made
//   REPORT            report.json: phases and their times, views, notes, the model's figures
//
// The scan directory: scan.json, calibration.yaml, images/, cameras.json and colmap/ (the kept
// views' cameras from the calibration, with lens distortion), model/ (what `avc reconstruct`
// writes, with undistorted cameras of its own) and report.json.
//
// A failing step (a device that stops answering, a full disk, a calibration of another camera)
// puts the scan in FAULT with the reason, keeps everything captured, and returns; a stop request
// puts it in PAUSED. The same call resumes either.

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/camera/camera_io.h"
#include "core/stage/stage_client.h"
#include "drivers/client/cell_client.h"
#include "orchestrator/scan_capture.h"
#include "orchestrator/scan_planner_settings.h"
#include "orchestrator/scan_record.h"

namespace avc::orchestrator {

struct ScanRunOptions {
  std::filesystem::path scan_dir;          // created; holds scan.json once started
  std::string scan_id;                     // default: the directory's name
  std::filesystem::path calibration_file;  // default: the scan's own calibration.yaml
  // avc-planner's settings for this scan (services/planner/plan_settings.h). A resumed scan
  // plans with the settings it started with (scan_planner_settings.h); a resume refuses to
  // change those the caller chose on purpose, named here by their keys.
  PlannerSettings planner_settings;
  std::set<std::string> planner_settings_given;
  ScanCaptureOptions capture;
  // "section.field=value" overrides of avc-builder's own configuration for this scan's build.
  std::vector<std::string> build_settings;
  // avc scan's own configuration as TOML (scan_options.h), kept as config/avc-scan.toml and
  // named in scan.json by its SHA-256; empty: not kept.
  std::string configuration;
  // The longest a stage (or one plan job) may take, and the longest its service may go without
  // a heartbeat.
  std::chrono::milliseconds stage_timeout{std::chrono::minutes(30)};
  std::chrono::milliseconds stage_silence_timeout{std::chrono::seconds(15)};
  std::chrono::milliseconds ready_timeout{30000};
  // Polled between steps and when a step fails: true (e.g. after SIGTERM) pauses the scan
  // instead of faulting it. Optional.
  std::function<bool()> stop_requested;
  // Hears the kept views' cameras once they are final, before BUILD (e.g. to publish them for
  // the log, so `avc replay` can rebuild the model). Optional.
  std::function<void(const std::string& scan_id, const std::vector<camera::NamedCamera>& cameras)>
      on_kept_cameras;
};

struct ScanProgress {
  std::string scan_id;
  std::filesystem::path scan_dir;
  ScanState state = ScanState::kIdle;
  std::optional<ScanState> interrupted;  // in PAUSED and FAULT
  std::string detail;
  int captures = 0;      // images in the scan so far
  double fraction = 0;   // of the main line
  double elapsed_s = 0;  // since this run started
};

struct ScanOutcome {
  ScanState state = ScanState::kIdle;  // DONE, PAUSED (stop requested), or FAULT with `fault`
  std::string fault;
  int captured_now = 0;  // images taken through the cell in this run
  int reused = 0;        // images answered from the scan directory
  std::filesystem::path scan_dir;
};

// Runs or resumes the scan in options.scan_dir: the cell through `cell`, the reconstruction
// through `stages` (both on the same bus and loop). `progress` hears every state change,
// capture and line of a stage's own progress. Never throws for a failing step (the outcome says
// FAULT and why); throws std::runtime_error only when the scan directory itself cannot be used
// (unreadable scan.json, no calibration given for a new scan).
ScanOutcome RunScan(client::CellClient& cell, stage::StageClient& stages,
                    const ScanRunOptions& options,
                    const std::function<void(const ScanProgress&)>& progress = {});

}  // namespace avc::orchestrator
