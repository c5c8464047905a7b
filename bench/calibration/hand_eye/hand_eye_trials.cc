#include "bench/calibration/hand_eye/hand_eye_trials.h"

#include <tbb/parallel_for.h>

#include <array>
#include <chrono>
#include <numbers>
#include <stdexcept>

#include "bench/calibration/hand_eye/error_statistics.h"
#include "bench/calibration/hand_eye/opencv_robot_world.h"
#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "core/util/keyed_random.h"

namespace avc::bench {
namespace {

namespace he = calibration::hand_eye;

enum Method { kClosedForm, kCeres, kShah, kMethodCount };
constexpr std::array<const char*, kMethodCount> kMethodNames = {"closed_form", "ceres",
                                                                "opencv_shah"};
enum Metric {
  kHandEyeRotation,
  kHandEyeTranslation,
  kRobotWorldRotation,
  kRobotWorldTranslation,
  kMetricCount
};
constexpr std::array<const char*, kMetricCount> kMetricNames = {
    "hand_eye_rotation_deg", "hand_eye_translation_mm", "robot_world_rotation_deg",
    "robot_world_translation_mm"};

using Errors = std::array<double, kMetricCount>;

struct TrialOutcome {
  std::string failure;  // empty when every method ran
  std::array<Errors, kMethodCount> errors{};
  Errors closed_form_vs_shah{};
  double closed_form_rms_px = 0;
  double ceres_rms_px = 0;
};

// Rotation angle (deg) and translation distance (mm) between two poses.
std::pair<double, double> Difference(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::AngleAxisd relative(Eigen::Matrix3d(a.linear() * b.linear().transpose()));
  return {relative.angle() * 180 / std::numbers::pi,
          (a.translation() - b.translation()).norm() * 1e3};
}

// Errors of an estimate (X = T_board_base, Z = T_cam_flange) against a reference, compared as
// T_flange_cam and T_base_board.
Errors Compare(const Eigen::Isometry3d& T_board_base, const Eigen::Isometry3d& T_cam_flange,
               const Eigen::Isometry3d& reference_T_base_board,
               const Eigen::Isometry3d& reference_T_flange_cam) {
  const auto [he_rotation, he_translation] =
      Difference(T_cam_flange.inverse(), reference_T_flange_cam);
  const auto [rw_rotation, rw_translation] =
      Difference(T_board_base.inverse(), reference_T_base_board);
  return {he_rotation, he_translation, rw_rotation, rw_translation};
}

// Well-separated per-trial seeds from one case seed.
uint64_t TrialSeed(uint64_t seed, int trial) {
  return util::MixSeed(seed, static_cast<uint64_t>(trial));
}

TrialOutcome RunTrial(const HandEyeTrialOptions& options, int trial) {
  TrialOutcome outcome;
  try {
    const HandEyeScenario scenario =
        MakeHandEyeScenario(options.scenario, TrialSeed(options.seed, trial));
    const auto observations = scenario.Observations();
    const he::HandEyeSolution closed = he::SolveRobotWorldHandEye(observations);
    const he::RefinementResult refined =
        he::RefineOnReprojection(scenario.BoardViews(), scenario.intrinsics, closed.T_board_base,
                                 closed.T_cam_flange, options.refinement);
    const RobotWorldEstimate shah = SolveWithOpenCvShah(observations);
    const Eigen::Isometry3d& true_base_board = scenario.true_T_base_board;
    const Eigen::Isometry3d& true_flange_cam = scenario.true_T_flange_cam;
    outcome.errors[kClosedForm] =
        Compare(closed.T_board_base, closed.T_cam_flange, true_base_board, true_flange_cam);
    outcome.errors[kCeres] =
        Compare(refined.T_board_base, refined.T_cam_flange, true_base_board, true_flange_cam);
    outcome.errors[kShah] =
        Compare(shah.T_board_base, shah.T_cam_flange, true_base_board, true_flange_cam);
    outcome.closed_form_vs_shah = Compare(closed.T_board_base, closed.T_cam_flange,
                                          shah.T_board_base.inverse(), shah.T_cam_flange.inverse());
    outcome.closed_form_rms_px = refined.initial_rms_px;
    outcome.ceres_rms_px = refined.rms_px;
  } catch (const std::exception& error) {
    outcome.failure = error.what();
  }
  return outcome;
}

nlohmann::json MetricsJson(const std::vector<Errors>& errors) {
  nlohmann::json json = nlohmann::json::object();
  for (int metric = 0; metric < kMetricCount; ++metric) {
    std::vector<double> values;
    for (const Errors& e : errors) values.push_back(e[metric]);
    json[kMetricNames[metric]] = ToJson(DescribeErrors(values));
  }
  return json;
}

double Median(const nlohmann::json& metrics, int metric) {
  return metrics[kMetricNames[metric]]["median"].get<double>();
}

nlohmann::json Acceptance(const nlohmann::json& result, const HandEyeAcceptance& targets) {
  const nlohmann::json& closed = result["methods"]["closed_form"];
  const nlohmann::json& ceres = result["methods"]["ceres"];
  const nlohmann::json& agreement = result["closed_form_vs_shah"];
  const auto within = [&](const nlohmann::json& metrics, int rotation, int translation) {
    return Median(metrics, rotation) <= targets.median_rotation_deg &&
           Median(metrics, translation) <= targets.median_translation_mm;
  };
  bool ceres_no_worse = true;
  for (int metric = 0; metric < kMetricCount; ++metric) {
    const bool is_rotation = metric == kHandEyeRotation || metric == kRobotWorldRotation;
    const double slack = is_rotation ? targets.ceres_slack_deg : targets.ceres_slack_mm;
    ceres_no_worse = ceres_no_worse && Median(ceres, metric) <= Median(closed, metric) + slack;
  }
  const auto worst = [&](int metric) {
    return agreement[kMetricNames[metric]]["max"].get<double>();
  };
  const bool matches_shah = worst(kHandEyeRotation) < targets.shah_agreement_deg &&
                            worst(kRobotWorldRotation) < targets.shah_agreement_deg &&
                            worst(kHandEyeTranslation) < targets.shah_agreement_mm &&
                            worst(kRobotWorldTranslation) < targets.shah_agreement_mm;
  // The calibration's result is the refined one; the closed form's accuracy is reported beside
  // it but does not gate "all" (it is the refinement's starting point).
  nlohmann::json gates = {
      {"refined_hand_eye_median_within_target",
       within(ceres, kHandEyeRotation, kHandEyeTranslation)},
      {"refined_robot_world_median_within_target",
       within(ceres, kRobotWorldRotation, kRobotWorldTranslation)},
      {"closed_form_matches_shah_every_trial", matches_shah},
      {"ceres_median_no_worse_than_closed_form", ceres_no_worse},
      {"no_failed_trials", result["failed_trials"].get<int>() == 0},
  };
  bool all = true;
  for (const auto& [key, value] : gates.items()) all = all && value.get<bool>();
  nlohmann::json acceptance = gates;
  acceptance["closed_form_hand_eye_median_within_target"] =
      within(closed, kHandEyeRotation, kHandEyeTranslation);
  acceptance["closed_form_robot_world_median_within_target"] =
      within(closed, kRobotWorldRotation, kRobotWorldTranslation);
  acceptance["all"] = all;
  acceptance["targets"] = {{"median_rotation_deg", targets.median_rotation_deg},
                           {"median_translation_mm", targets.median_translation_mm},
                           {"shah_agreement_deg", targets.shah_agreement_deg},
                           {"shah_agreement_mm", targets.shah_agreement_mm}};
  return acceptance;
}

}  // namespace

HandEyeTrialOptions NoiseFreeHandEyeCase() {
  HandEyeTrialOptions options;
  options.name = "noise-free";
  options.seed = 20261123;
  return options;
}

HandEyeTrialOptions NoisyHandEyeCase() {
  HandEyeTrialOptions options;
  options.name = "0.5 px, 0.005 deg / 0.05 mm";
  options.seed = 20261124;
  options.scenario.pixel_sigma_px = 0.5;
  options.scenario.robot_rotation_sigma_deg = 0.005;
  options.scenario.robot_translation_sigma_mm = 0.05;
  return options;
}

HandEyeTrialOptions HighResolutionHandEyeCase() {
  HandEyeTrialOptions options = NoisyHandEyeCase();
  options.name = "650D-like camera, 30 mm squares, 0.35-0.6 m";
  options.seed = 20261125;
  camera::Intrinsics camera;
  camera.width = 5184;
  camera.height = 3456;
  camera.fx = camera.fy = 4186;
  camera.cx = 2591.5;
  camera.cy = 1727.5;
  options.scenario.intrinsics = camera;
  options.scenario.square_m = 0.03;
  options.scenario.min_distance_m = 0.35;
  options.scenario.max_distance_m = 0.6;
  return options;
}

nlohmann::json RunHandEyeTrials(const HandEyeTrialOptions& options) {
  if (options.trials < 1) throw std::invalid_argument("RunHandEyeTrials: trials must be >= 1");
  const auto start = std::chrono::steady_clock::now();
  std::vector<TrialOutcome> outcomes(static_cast<size_t>(options.trials));
  tbb::parallel_for(0, options.trials, [&](int trial) {
    outcomes[static_cast<size_t>(trial)] = RunTrial(options, trial);
  });

  std::array<std::vector<Errors>, kMethodCount> errors;
  std::vector<Errors> agreement;
  std::vector<double> closed_rms, ceres_rms;
  nlohmann::json failures = nlohmann::json::array();
  for (size_t trial = 0; trial < outcomes.size(); ++trial) {
    const TrialOutcome& outcome = outcomes[trial];
    if (!outcome.failure.empty()) {
      failures.push_back({{"trial", trial}, {"reason", outcome.failure}});
      continue;
    }
    for (int method = 0; method < kMethodCount; ++method) {
      errors[method].push_back(outcome.errors[method]);
    }
    agreement.push_back(outcome.closed_form_vs_shah);
    closed_rms.push_back(outcome.closed_form_rms_px);
    ceres_rms.push_back(outcome.ceres_rms_px);
  }

  nlohmann::json result;
  result["case"] = options.name;
  result["trials"] = options.trials;
  result["poses"] = options.scenario.poses;
  result["pixel_sigma_px"] = options.scenario.pixel_sigma_px;
  result["robot_rotation_sigma_deg"] = options.scenario.robot_rotation_sigma_deg;
  result["robot_translation_sigma_mm"] = options.scenario.robot_translation_sigma_mm;
  result["board"] = {{"columns", options.scenario.board_columns},
                     {"rows", options.scenario.board_rows},
                     {"square_mm", options.scenario.square_m * 1e3}};
  result["seed"] = options.seed;
  result["refinement"] = {
      {"huber_px", options.refinement.huber_px},
      {"pixel_sigma_px", options.refinement.pixel_sigma_px},
      {"robot_rotation_sigma_deg", options.refinement.robot_rotation_sigma_deg},
      {"robot_translation_sigma_mm", options.refinement.robot_translation_sigma_mm}};
  if (options.scenario.intrinsics) {
    result["camera"] = {{"width", options.scenario.intrinsics->width},
                        {"height", options.scenario.intrinsics->height},
                        {"fx", options.scenario.intrinsics->fx}};
  }
  result["failed_trials"] = static_cast<int>(failures.size());
  result["failures"] = failures;
  for (int method = 0; method < kMethodCount; ++method) {
    result["methods"][kMethodNames[method]] = MetricsJson(errors[method]);
  }
  result["closed_form_vs_shah"] = MetricsJson(agreement);
  result["reprojection_rms_px"] = {{"closed_form", ToJson(DescribeErrors(closed_rms))},
                                   {"ceres", ToJson(DescribeErrors(ceres_rms))}};
  result["acceptance"] = Acceptance(result, options.acceptance);
  result["seconds"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

nlohmann::json RunHandEyeBenchmark(int trials) {
  const auto start = std::chrono::steady_clock::now();
  nlohmann::json result;
  bool all = true;
  for (const HandEyeTrialOptions& options :
       {NoiseFreeHandEyeCase(), NoisyHandEyeCase(), HighResolutionHandEyeCase()}) {
    HandEyeTrialOptions with_trials = options;
    with_trials.trials = trials;
    nlohmann::json one = RunHandEyeTrials(with_trials);
    all = all && one["acceptance"]["all"].get<bool>();
    result["cases"].push_back(std::move(one));
  }
  result["acceptance_met"] = all;
  result["seconds"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace avc::bench
