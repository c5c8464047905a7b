#include "bench/calibration/hand_eye/hand_eye_comparison.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <vector>

#include "bench/calibration/hand_eye/opencv_robot_world.h"
#include "bench/calibration/hand_eye/visp_hand_eye_set.h"
#include "core/calibration/pipeline/hand_eye_choice.h"
#include "core/geometry/pose_mean.h"
#include "core/util/upper_median.h"

namespace avc::bench {
namespace {

namespace hand_eye = calibration::hand_eye;
using Observations = std::vector<hand_eye::HandEyeObservation>;
using Solver = std::function<RobotWorldEstimate(const Observations&)>;

constexpr double kRadToDeg = 180.0 / M_PI;

// The fixed frame's pose (the tag in the flange, in the solver's T_base_board slot) from each
// shot through the solution, and its spread about the chordal mean: rms rotation (deg), rms and
// largest translation (mm).
nlohmann::json Spread(const Observations& observations, const RobotWorldEstimate& estimate) {
  std::vector<Eigen::Isometry3d> poses;
  for (const hand_eye::HandEyeObservation& o : observations) {
    poses.push_back(o.T_base_flange * estimate.T_cam_flange.inverse() * o.T_cam_board);
  }
  const Eigen::Isometry3d mean = geometry::PoseMean(poses);
  double rotation_squared = 0, translation_squared = 0, largest = 0;
  for (const Eigen::Isometry3d& pose : poses) {
    const double angle = Eigen::AngleAxisd(mean.linear().transpose() * pose.linear()).angle();
    rotation_squared += angle * angle;
    const double distance = (pose.translation() - mean.translation()).norm();
    translation_squared += distance * distance;
    largest = std::max(largest, distance);
  }
  const double n = static_cast<double>(poses.size());
  return {{"rotation_rms_deg", std::sqrt(rotation_squared / n) * kRadToDeg},
          {"translation_rms_mm", std::sqrt(translation_squared / n) * 1e3},
          {"translation_max_mm", largest * 1e3}};
}

// Leave-one-out as ChooseHandEye measures it (hand_eye_choice.h): fit without each pose, the
// left-out pose's residual; medians over the folds.
nlohmann::json LeaveOneOut(const Observations& observations, const Solver& solve) {
  std::vector<double> rotation, translation;
  for (size_t i = 0; i < observations.size(); ++i) {
    Observations fold;
    for (size_t j = 0; j < observations.size(); ++j) {
      if (j != i) fold.push_back(observations[j]);
    }
    const RobotWorldEstimate estimate = solve(fold);
    const hand_eye::PoseResidual error =
        hand_eye::PoseResiduals({observations[i]}, estimate.T_board_base, estimate.T_cam_flange)[0];
    rotation.push_back(error.rotation_deg);
    translation.push_back(error.translation_mm);
  }
  return {{"loo_rotation_deg", UpperMedian(rotation)},
          {"loo_translation_mm", UpperMedian(translation)},
          {"folds", rotation.size()}};
}

nlohmann::json Method(const std::string& name, const std::string& source, const nlohmann::json& loo,
                      const nlohmann::json& spread) {
  nlohmann::json method = {{"method", name}, {"source", source}};
  method.update(loo);
  method["spread"] = spread;
  return method;
}

}  // namespace

nlohmann::json CompareHandEyeMethods(const Observations& observations,
                                     const std::vector<hand_eye::BoardView>& board_views,
                                     const camera::Intrinsics& intrinsics,
                                     const hand_eye::DiversityLimits& diversity,
                                     const hand_eye::RefinementOptions& refinement) {
  nlohmann::json methods = nlohmann::json::array();
  // Ours, as `avc calibrate solve` chooses.
  const calibration::HandEyeChoice choice =
      calibration::ChooseHandEye(observations, board_views, intrinsics, diversity, refinement);
  for (const calibration::HandEyeCandidate& candidate : choice.candidates) {
    const RobotWorldEstimate estimate{candidate.T_board_base, candidate.T_cam_flange};
    methods.push_back(Method(candidate.method, "ours",
                             {{"loo_rotation_deg", candidate.loo_rotation_deg},
                              {"loo_translation_mm", candidate.loo_translation_mm}},
                             Spread(observations, estimate)));
    methods.back()["written"] = candidate.method == choice.chosen.method;
  }
  const std::vector<std::pair<std::string, int>> hand_eye_methods = {
      {"Tsai", cv::CALIB_HAND_EYE_TSAI},
      {"Park", cv::CALIB_HAND_EYE_PARK},
      {"Horaud", cv::CALIB_HAND_EYE_HORAUD},
      {"Andreff", cv::CALIB_HAND_EYE_ANDREFF},
      {"Daniilidis", cv::CALIB_HAND_EYE_DANIILIDIS}};
  for (const auto& [name, flag] : hand_eye_methods) {
    const Solver solve = [flag = flag](const Observations& o) {
      return SolveWithOpenCvHandEye(o, flag);
    };
    methods.push_back(Method(name, "OpenCV calibrateHandEye", LeaveOneOut(observations, solve),
                             Spread(observations, solve(observations))));
  }
  const std::vector<std::pair<std::string, int>> robot_world_methods = {
      {"Shah", cv::CALIB_ROBOT_WORLD_HAND_EYE_SHAH}, {"Li", cv::CALIB_ROBOT_WORLD_HAND_EYE_LI}};
  for (const auto& [name, flag] : robot_world_methods) {
    const Solver solve = [flag = flag](const Observations& o) {
      return SolveWithOpenCvRobotWorld(o, flag);
    };
    methods.push_back(Method(name, "OpenCV calibrateRobotWorldHandEye",
                             LeaveOneOut(observations, solve),
                             Spread(observations, solve(observations))));
  }
  return {{"poses", observations.size()}, {"methods", methods}};
}

nlohmann::json RunRealEyeToHand(const std::filesystem::path& folder) {
  const VispHandEyeSet set = ReadVispHandEyeSet(folder, "franka", 10);
  // The default refinement options (a UR5's prior), as `avc calibrate solve` would use them.
  nlohmann::json result = CompareHandEyeMethods(EyeToHandObservations(set),
                                                EyeToHandBoardViews(set), set.intrinsics, {}, {});
  double max_rms = 0;
  for (const VispShot& shot : set.shots) max_rms = std::max(max_rms, shot.tag.rms_px);
  result["dataset"] = folder.string();
  result["tag_rms_px_max"] = max_rms;
  return result;
}

std::string FormatHandEyeComparison(const nlohmann::json& result, const std::string& title) {
  std::string text = fmt::format("{} ({} poses):\n  {:<66} {:>9} {:>9}   {:>9} {:>9} {:>9}\n",
                                 title, result["poses"].get<int>(), "method", "LOO deg", "LOO mm",
                                 "spread deg", "rms mm", "max mm");
  for (const nlohmann::json& m : result["methods"]) {
    const std::string name =
        fmt::format("{} ({}){}", m["method"].get<std::string>(), m["source"].get<std::string>(),
                    m.value("written", false) ? " *written*" : "");
    text += fmt::format("  {:<66} {:>9.4f} {:>9.3f}   {:>9.4f} {:>9.3f} {:>9.3f}\n", name,
                        m["loo_rotation_deg"].get<double>(), m["loo_translation_mm"].get<double>(),
                        m["spread"]["rotation_rms_deg"].get<double>(),
                        m["spread"]["translation_rms_mm"].get<double>(),
                        m["spread"]["translation_max_mm"].get<double>());
  }
  return text;
}

std::string FormatRealEyeToHand(const nlohmann::json& result) {
  return FormatHandEyeComparison(
      result,
      fmt::format("Real eye-to-hand set ({}; tag corners fit to {:.2f} px at worst)",
                  result["dataset"].get<std::string>(), result["tag_rms_px_max"].get<double>()));
}

}  // namespace avc::bench
