#include "orchestrator/scan_run.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/calibration/cell/calibration_yaml.h"
#include "core/camera/camera_io.h"
#include "core/kinematics/row_major_pose.h"
#include "core/plan/plan_exchange.h"
#include "core/stage/stage_files.h"
#include "core/stage/stage_names.h"
#include "core/util/clock.h"
#include "core/util/file_io.h"
#include "core/util/sha256.h"
#include "orchestrator/scan_planner_settings.h"
#include "orchestrator/scan_stage_jobs.h"
#include "report/report_html.h"

namespace avc::orchestrator {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

constexpr char kCalibrationName[] = "calibration.yaml";

ScanState StateOfPhase(plan::PlanPhase phase) {
  switch (phase) {
    case plan::PlanPhase::kFrame:
      return ScanState::kFrame;
    case plan::PlanPhase::kInitialCapture:
      return ScanState::kInitialCapture;
    case plan::PlanPhase::kActiveVision:
      return ScanState::kActiveVision;
    case plan::PlanPhase::kPruneViews:
      return ScanState::kPruneViews;
  }
  throw std::logic_error("unknown planner phase");
}

// One run of the scan: the record, the machine and what the steps hand each other.
class ScanRun {
 public:
  ScanRun(client::CellClient& cell, stage::StageClient& stages, const ScanRunOptions& options,
          const std::function<void(const ScanProgress&)>& progress)
      : cell_(cell),
        stages_(stages),
        options_(options),
        progress_(progress),
        dir_(options.scan_dir),
        model_dir_(dir_ / "model"),
        started_us_(clock_.NowMicros()) {}

  ScanOutcome Run() {
    OpenRecord();
    outcome_.scan_dir = dir_;
    if (machine_.state() == ScanState::kDone || machine_.state() == ScanState::kAborted) {
      outcome_.state = machine_.state();
      Report(fmt::format("scan already {}", StateName(machine_.state())));
      return outcome_;
    }
    try {
      if (machine_.interrupted()) {
        Enter(*machine_.interrupted(), "resumed");
      } else if (machine_.state() == ScanState::kIdle) {
        Enter(ScanState::kCheckDevices, "");
      } else {
        Report("resuming in " + std::string(StateName(machine_.state())));
      }
      while (machine_.state() != ScanState::kDone && !StopRequested()) Step(machine_.state());
      if (StopRequested()) {
        Interrupt(ScanState::kPaused, "stop requested");
      } else {
        record_.EndPhase(clock_.NowMicros());
        Persist();
      }
    } catch (const std::exception& error) {
      // A stop makes the step in progress fail (its waits end): that is a pause, not a fault.
      if (StopRequested()) {
        Interrupt(ScanState::kPaused,
                  std::string("stop requested during the step: ") + error.what());
      } else {
        Interrupt(ScanState::kFault, error.what());
      }
    }
    outcome_.state = machine_.state();
    return outcome_;
  }

 private:
  void OpenRecord() {
    fs::create_directories(dir_);
    if (fs::exists(dir_ / "scan.json")) {
      record_ = LoadScanRecord(dir_);
      machine_ = ScanStateMachine::Restore(record_.state, record_.interrupted);
      const PlannerSettings recorded = RecordedPlannerSettings(record_.options);
      const std::string changes = DescribePlannerChanges(recorded, options_.planner_settings,
                                                         options_.planner_settings_given);
      if (!changes.empty()) {
        throw std::runtime_error(
            fmt::format("a resumed scan keeps the planner settings it started with, so that it "
                        "asks for the same views: {}; resume without them",
                        changes));
      }
      // What the scan recorded wins; what an older scan did not record comes from the caller.
      for (const auto& [key, value] : recorded) options_.planner_settings[key] = value;
      KeepOwnConfig();
      return;
    }
    record_.scan_id =
        options_.scan_id.empty() ? fs::absolute(dir_).filename().string() : options_.scan_id;
    record_.created_utime = clock_.NowMicros();
    record_.options = {{"calibration_file", options_.calibration_file.string()}};
    RecordPlannerSettings(options_.planner_settings, &record_.options);
    KeepOwnConfig();
    Persist();
  }

  // avc scan's own configuration beside its stages' (config/), for the run that last used it.
  void KeepOwnConfig() {
    const std::string& text = options_.configuration;
    if (!text.empty()) KeepConfig("avc-scan", text, Sha256Hex(text), &record_.options);
  }

  void Step(ScanState state) {
    switch (state) {
      case ScanState::kCheckDevices:
        PowerArm();
        return Enter(ScanState::kLoadCalibration, "");
      case ScanState::kLoadCalibration:
        EnsureCalibration();
        return Enter(ScanState::kFrame, "");
      case ScanState::kFrame:
      case ScanState::kInitialCapture:
      case ScanState::kActiveVision:
      case ScanState::kPruneViews:
        CaptureViews();
        return Enter(ScanState::kBuild, "");
      case ScanState::kBuild:
        Build();
        return Enter(ScanState::kMergeCluster, "");
      case ScanState::kMergeCluster:
        MergeCluster();
        return Enter(ScanState::kSurface, "");
      case ScanState::kSurface:
        Surface();
        return Enter(ScanState::kTraits, "");
      case ScanState::kTraits:
        Traits();
        return Enter(ScanState::kReport, "");
      case ScanState::kReport:
        WriteReport();
        return Enter(ScanState::kDone, "");
      default:
        throw std::logic_error(fmt::format("no step for state {}", StateName(state)));
    }
  }

  // Starts `next` once the services it needs are READY; persisted before any of its work.
  void Enter(ScanState next, const std::string& detail) {
    const std::vector<std::string>& services = RequiredServices(next);
    if (!services.empty()) {
      Report(fmt::format("{}: waiting for {}", StateName(next), fmt::join(services, ", ")));
      cell_.WaitReady(services, options_.ready_timeout);
    }
    const int64_t now = clock_.NowMicros();
    if (const std::string refused = machine_.TryTransition(next, now, detail); !refused.empty()) {
      throw std::logic_error(refused);
    }
    record_.state = next;
    record_.interrupted.reset();
    record_.fault.clear();
    record_.detail = detail;
    if (IsWorkingState(next)) record_.StartPhase(next, now);
    Persist();
    Report(detail);
  }

  bool StopRequested() const { return options_.stop_requested && options_.stop_requested(); }

  // PAUSED or FAULT from the working state in progress, persisted, resumable.
  void Interrupt(ScanState to, const std::string& reason) {
    const int64_t now = clock_.NowMicros();
    const ScanState was = machine_.state();
    std::string why = reason;
    if (machine_.TryTransition(to, now, reason).empty()) {
      record_.state = to;
      record_.interrupted = machine_.interrupted();
      record_.fault = to == ScanState::kFault ? reason : "";
      record_.detail = reason;
      record_.EndPhase(now);
      try {
        Persist();
      } catch (const std::exception& error) {
        why += fmt::format(" (and scan.json could not be saved: {})", error.what());
      }
    }
    if (to == ScanState::kFault) outcome_.fault = fmt::format("{} failed: {}", StateName(was), why);
    Report(to == ScanState::kFault ? outcome_.fault : fmt::format("paused in {}", StateName(was)));
  }

  void Persist() { SaveScanRecord(record_, dir_); }

  void Report(const std::string& detail) {
    if (!progress_) return;
    ScanProgress p;
    p.scan_id = record_.scan_id;
    p.scan_dir = dir_;
    p.state = machine_.state();
    p.interrupted = machine_.interrupted();
    p.detail = detail;
    p.captures = static_cast<int>(record_.captures.size());
    const ScanState on_line = machine_.interrupted().value_or(machine_.state());
    p.fraction =
        IsWorkingState(on_line) || on_line == ScanState::kIdle || on_line == ScanState::kDone
            ? MainLineFraction(on_line)
            : 0;
    p.elapsed_s = (clock_.NowMicros() - started_us_) * 1e-6;
    progress_(p);
  }

  void PowerArm() {
    cell_.Robot(avc::robot_command_t::KIND_POWER_ON, options_.ready_timeout);
    cell_.Robot(avc::robot_command_t::KIND_BRAKE_RELEASE, options_.ready_timeout);
  }

  // The scan keeps its own copy of the calibration it was planned with; a resume uses it.
  void EnsureCalibration() {
    if (calibration_) return;
    const fs::path kept = dir_ / kCalibrationName;
    const fs::path& given = options_.calibration_file;
    if (!given.empty() && fs::exists(kept) && ReadFile(given) != ReadFile(kept)) {
      throw std::runtime_error(
          fmt::format("{} differs from the calibration this scan started with ({}); resume without "
                      "--calibration, or start a new scan",
                      given.string(), kept.string()));
    }
    if (!fs::exists(kept)) {
      if (given.empty()) {
        throw std::runtime_error("no calibration: give the cell's calibration.yaml");
      }
      WriteFileAtomically(kept, ReadFile(given));
    }
    calibration_ = calibration::LoadCalibration(kept);
    if (!calibration_->turntable_calibrated) {
      throw std::runtime_error(fmt::format(
          "{} has no turntable axis (a hand-eye-only calibration): calibrate the cell with its "
          "turntable shots (`avc calibrate`)",
          kept.string()));
    }
  }

  // Algorithm 1 as plan jobs for avc-planner: each answer names the next view, which is
  // captured (or answered from disk on a resume) and sent back with its mask in the next job,
  // until the final plan.
  void CaptureViews() {
    EnsureCalibration();
    PowerArm();  // after a restart of the arm's driver or controller
    ScanCaptureOptions capture_options = options_.capture;
    capture_options.image_width = calibration_->intrinsics.width;
    capture_options.image_height = calibration_->intrinsics.height;
    ScanCapture capture(
        cell_, dir_, record_, [this] { Persist(); }, capture_options,
        [this](const std::string& line) { Report(line); });
    plan::PlanRequest request;
    plan::PlanAnswer answer;
    for (;;) {
      answer = Plan(request);
      RecordPlannerSettingsInForce(answer.settings);
      EnterPlannerPhase(answer.phase);
      capture.SetPlantKeepOut(answer.keep_out);
      if (answer.final_plan) break;
      plan::AnsweredView answered;
      answered.view = *answer.next;
      if (const std::optional<cv::Mat> mask = capture(*answer.next)) {
        answered.mask_png = plan::EncodeMask(*mask);
      }
      request.answered.push_back(std::move(answered));
    }
    EnterPlannerPhase(plan::PlanPhase::kPruneViews);
    outcome_.captured_now += capture.taken();
    outcome_.reused += capture.reused();
    const plan::FinalPlan& final_plan = *answer.final_plan;
    MarkPlannedViews(record_, final_plan, options_.capture.pose_tolerance);
    record_.options["planner_notes"] = final_plan.notes;
    record_.options["patches"] = final_plan.patches;
    record_.options["failing_patches"] = final_plan.failing_patches;
    record_.options["stages"][stage::kPlanStage] = plan_jobs_;
    WriteKeptCameras();
    Persist();
  }

  // The planner's settings in force join those the scan was given, so that a resume plans with
  // exactly them where the caller left the planner's defaults (and a later AVC changed them).
  void RecordPlannerSettingsInForce(const PlannerSettings& in_force) {
    bool added = false;
    for (const auto& [key, value] : in_force) {
      added |= options_.planner_settings.emplace(key, value).second;
    }
    if (!added) return;
    RecordPlannerSettings(options_.planner_settings, &record_.options);
    Persist();
  }

  // Enters the planner's phase and any it went through since the last answer (the orbit can
  // end the plan when it spends every view). A resumed scan replays the phases it had passed:
  // only later ones are entered.
  void EnterPlannerPhase(plan::PlanPhase phase) {
    for (int p = static_cast<int>(plan::PlanPhase::kFrame); p <= static_cast<int>(phase); ++p) {
      const ScanState state = StateOfPhase(static_cast<plan::PlanPhase>(p));
      if (Row(state).step > Row(machine_.state()).step) Enter(state, "");
    }
  }

  // One plan job: the calibration and the answered views to avc-planner, its answer back.
  plan::PlanAnswer Plan(const plan::PlanRequest& request) {
    const fs::path folder = dir_ / "plan";
    fs::remove_all(folder);
    plan::WritePlanRequest(request, folder);
    fs::copy_file(dir_ / kCalibrationName, folder / kCalibrationName);
    std::vector<std::string> inputs = plan::PlanRequestFiles(request);
    inputs.push_back(kCalibrationName);
    const stage::StageAnswer answer = stages_.Run(
        StageRequest({stage::kPlanService, stage::kPlanStage, folder, inputs},
                     PlannerAssignments(options_.planner_settings)),
        [&](const std::string& line) { Report(fmt::format("{}: {}", stage::kPlanService, line)); },
        [this] { return StopRequested(); });
    stage::UnpackFiles(answer.files, folder / "answer");
    // This run's plan jobs, summed for the report.
    const auto add = [this](const char* key, double value) {
      plan_jobs_[key] = plan_jobs_.value(key, 0.0) + value;
    };
    plan_jobs_["service"] = stage::kPlanService;
    add("jobs", 1);
    add("stage_s", answer.stage_seconds);
    add("wall_s", answer.wall_seconds);
    add("bytes_sent", static_cast<double>(answer.bytes_sent));
    add("bytes_received", static_cast<double>(answer.bytes_received));
    add("sends", answer.sends);
    KeepConfig(stage::kPlanService, answer.config_text, answer.config_sha256, &plan_jobs_);
    return plan::ReadPlanAnswer(folder / "answer");
  }

  // The configuration a stage's service ran with: its text in config/<service>.toml, named in
  // scan.json by its SHA-256, so the scan can be replayed or reconstructed with it.
  void KeepConfig(const std::string& service, const std::string& text, const std::string& sha256,
                  nlohmann::json* entry) {
    (*entry)["config_sha256"] = sha256;
    if (text.empty()) return;
    const std::string file = fmt::format("config/{}.toml", service);
    fs::create_directories(dir_ / "config");
    WriteFileAtomically(dir_ / file, text);
    (*entry)["config_file"] = file;
  }

  // cameras.json and colmap/ list the kept views, placed by the calibration from the state the
  // arm and turntable reported at each capture.
  void WriteKeptCameras() {
    std::vector<camera::NamedCamera> cameras;
    for (const CaptureRecord& c : record_.captures) {
      if (!c.kept) continue;
      const Eigen::Isometry3d T_base_flange =
          kinematics::IsometryFromRowMajor(c.reported_T_base_flange.data());
      cameras.push_back({fs::path(c.file).filename().string(),
                         calibration_->CameraAt(T_base_flange, c.reported_table_angle)});
    }
    if (cameras.size() < 2) {
      throw std::runtime_error(
          fmt::format("only {} usable views were captured; the reconstruction needs 2 or more",
                      cameras.size()));
    }
    camera::WriteCamerasJson(dir_ / "cameras.json", cameras);
    camera::WriteColmapText(dir_ / "colmap", cameras);
    if (options_.on_kept_cameras) options_.on_kept_cameras(record_.scan_id, cameras);
  }

  // Sends the stage its files, waits for its answer, and only then writes what it made into
  // `into`: a stage that fails or answers wrongly leaves nothing of its answer behind.
  stage::StageRequest StageRequest(const StageJobSpec& job,
                                   const std::vector<std::string>& settings) const {
    stage::StageRequest request;
    request.service = job.service;
    request.stage = job.stage;
    request.scan_id = record_.scan_id;
    request.settings = settings;
    request.files = stage::PackFiles(job.folder, job.inputs);
    request.timeout = options_.stage_timeout;
    request.silence_timeout = options_.stage_silence_timeout;
    return request;
  }

  void RunStage(const StageJobSpec& job, const std::vector<std::string>& settings,
                const fs::path& into) {
    const stage::StageRequest request = StageRequest(job, settings);
    Report(fmt::format("{}: {} files ({:.1f} MB) to {}", job.stage, request.files.size(),
                       stage::FileBytes(request.files) * 1e-6, job.service));
    const stage::StageAnswer answer = stages_.Run(
        request, [&](const std::string& line) { Report(fmt::format("{}: {}", job.service, line)); },
        [this] { return StopRequested(); });
    stage::UnpackFiles(answer.files, into);
    nlohmann::json entry = {{"service", job.service},
                            {"request_id", answer.request_id},
                            {"stage_s", answer.stage_seconds},
                            {"wall_s", answer.wall_seconds},
                            {"bytes_sent", answer.bytes_sent},
                            {"bytes_received", answer.bytes_received},
                            {"sends", answer.sends}};
    KeepConfig(job.service, answer.config_text, answer.config_sha256, &entry);
    record_.options["stages"][job.stage] = entry;
    Persist();
  }

  void Build() {
    // A new build replaces the whole model: nothing of an earlier one may mix with it.
    fs::remove_all(model_dir_);
    fs::create_directories(model_dir_);
    RunStage(BuildJob(dir_), options_.build_settings, model_dir_);
  }

  void MergeCluster() { RunStage(ClusterJob(model_dir_), {}, model_dir_); }

  void Surface() { RunStage(SurfaceJob(model_dir_), {}, model_dir_); }

  // The surface stage measured the traits with the mesh; a scan resumed here without them (a
  // model from an older AVC) surfaces again.
  void Traits() {
    if (!fs::exists(model_dir_ / "traits.json")) Surface();
    const nlohmann::json traits = nlohmann::json::parse(ReadFile(model_dir_ / "traits.json"));
    Report(fmt::format("traits: {:.1f} cm2 over {} clusters, {:.1f} cm tall",
                       1e4 * traits.at("total_area_m2").get<double>(), traits.at("clusters").size(),
                       1e2 * traits.at("height_m").get<double>()));
  }

  void WriteReport() {
    nlohmann::ordered_json report;
    report["scan_id"] = record_.scan_id;
    report["scan_dir"] = fs::absolute(dir_).string();
    nlohmann::ordered_json phases = nlohmann::ordered_json::array();
    for (const PhaseTiming& phase : record_.phases) {
      const int64_t end = phase.end_utime ? phase.end_utime : clock_.NowMicros();
      phases.push_back({{"state", phase.state}, {"seconds", (end - phase.start_utime) * 1e-6}});
    }
    report["phases"] = phases;
    int kept = 0;
    for (const CaptureRecord& c : record_.captures) kept += c.kept;
    report["images"] = {{"captured", record_.captures.size()}, {"kept", kept}};
    nlohmann::json planner = record_.options;
    planner.erase("stages");
    report["planner"] = planner;
    report["stages"] = record_.options.value("stages", nlohmann::json::object());
    report["build"] = nlohmann::json::parse(ReadFile(model_dir_ / "build.json"));
    report["traits"] = nlohmann::json::parse(ReadFile(model_dir_ / "traits.json"));
    report["surface"] = nlohmann::json::parse(ReadFile(model_dir_ / "surface.json"));
    report["files"] = {"images/",
                       "cameras.json",
                       "colmap/",
                       kCalibrationName,
                       "config/",
                       "plan/",
                       "model/ppr.bt",
                       "model/points.ply",
                       "model/merged.ply",
                       "model/clusters.ply",
                       "model/clusters.lcm",
                       "model/mesh.ply",
                       "model/surface.json",
                       "model/traits.csv",
                       "model/traits.json"};
    WriteFileAtomically(dir_ / "report.json", report.dump(2) + "\n");
    report::WriteReportHtml(dir_);
  }

  client::CellClient& cell_;
  stage::StageClient& stages_;
  ScanRunOptions options_;  // a copy: a resumed scan takes its planner settings from its record
  const std::function<void(const ScanProgress&)>& progress_;
  fs::path dir_;
  fs::path model_dir_;
  SystemClock clock_;
  int64_t started_us_;
  ScanRecord record_;
  ScanStateMachine machine_;
  ScanOutcome outcome_;
  std::optional<calibration::CellCalibration> calibration_;
  nlohmann::json plan_jobs_ = nlohmann::json::object();
};

}  // namespace

ScanOutcome RunScan(client::CellClient& cell, stage::StageClient& stages,
                    const ScanRunOptions& options,
                    const std::function<void(const ScanProgress&)>& progress) {
  ScanRun run(cell, stages, options, progress);
  return run.Run();
}

}  // namespace avc::orchestrator
