#include "core/calibration/pipeline/hand_eye_choice.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "core/util/upper_median.h"

namespace avc::calibration {
namespace {

// No folds at all: no evidence for the candidate.
double Median(const std::vector<double>& values) {
  return values.empty() ? std::numeric_limits<double>::infinity() : UpperMedian(values);
}

template <class T>
std::vector<T> Without(const std::vector<T>& items, size_t left_out) {
  std::vector<T> kept;
  for (size_t i = 0; i < items.size(); ++i) {
    if (i != left_out) kept.push_back(items[i]);
  }
  return kept;
}

double Rms(const std::vector<double>& view_rms) {
  double squared = 0;
  for (const double rms : view_rms) squared += rms * rms;
  return view_rms.empty() ? 0 : std::sqrt(squared / static_cast<double>(view_rms.size()));
}

// The refinement's robot-pose prior widened to what the closed form's pose residuals show: each
// residual mixes the robot's error with the camera's, so half its median (per axis of the two
// poses compared) bounds the robot's from above; never tighter than the given prior.
hand_eye::RefinementOptions RobotNoiseFromResiduals(const hand_eye::HandEyeSolution& closed,
                                                    hand_eye::RefinementOptions options) {
  std::vector<double> rotation, translation;
  for (const hand_eye::PoseResidual& r : closed.residuals) {
    rotation.push_back(r.rotation_deg);
    translation.push_back(r.translation_mm);
  }
  options.robot_rotation_sigma_deg =
      std::max(options.robot_rotation_sigma_deg, UpperMedian(rotation) / 2);
  options.robot_translation_sigma_mm =
      std::max(options.robot_translation_sigma_mm, UpperMedian(translation) / 2);
  return options;
}

double Score(const HandEyeCandidate& candidate) {
  return candidate.loo_rotation_deg / 0.01 + candidate.loo_translation_mm / 0.1;
}

}  // namespace

HandEyeChoice ChooseHandEye(const std::vector<hand_eye::HandEyeObservation>& observations,
                            const std::vector<hand_eye::BoardView>& board_views,
                            const camera::Intrinsics& intrinsics,
                            const hand_eye::DiversityLimits& diversity,
                            const hand_eye::RefinementOptions& refinement) {
  const hand_eye::HandEyeSolution closed =
      hand_eye::SolveRobotWorldHandEye(observations, diversity);
  // The candidates in order of preference on a tie: nullopt = the closed form.
  std::vector<std::pair<std::string, std::optional<hand_eye::RefinementOptions>>> methods = {
      {"refined", refinement}};
  const hand_eye::RefinementOptions from_data = RobotNoiseFromResiduals(closed, refinement);
  if (from_data.robot_rotation_sigma_deg > refinement.robot_rotation_sigma_deg ||
      from_data.robot_translation_sigma_mm > refinement.robot_translation_sigma_mm) {
    methods.push_back(
        {fmt::format("refined, robot noise {:.3g} deg / {:.3g} mm from the data",
                     from_data.robot_rotation_sigma_deg, from_data.robot_translation_sigma_mm),
         from_data});
  }
  methods.push_back({"closed form", std::nullopt});

  // Each method on all poses, and without each pose in turn.
  const auto solve = [&](const std::optional<hand_eye::RefinementOptions>& method,
                         const std::vector<hand_eye::BoardView>& views,
                         const hand_eye::HandEyeSolution& start) {
    if (!method) return std::pair{start.T_board_base, start.T_cam_flange};
    const hand_eye::RefinementResult refined = hand_eye::RefineOnReprojection(
        views, intrinsics, start.T_board_base, start.T_cam_flange, *method);
    return std::pair{refined.T_board_base, refined.T_cam_flange};
  };
  std::vector<HandEyeCandidate> candidates;
  for (const auto& [name, method] : methods) {
    HandEyeCandidate candidate;
    candidate.method = name;
    std::tie(candidate.T_board_base, candidate.T_cam_flange) = solve(method, board_views, closed);
    candidate.view_rms_px = hand_eye::ViewReprojectionRms(
        board_views, intrinsics, candidate.T_board_base, candidate.T_cam_flange);
    candidate.rms_px = Rms(candidate.view_rms_px);
    candidates.push_back(std::move(candidate));
  }
  std::vector<std::vector<double>> rotation(methods.size()), translation(methods.size());
  for (size_t i = 0; i < observations.size(); ++i) {
    hand_eye::HandEyeSolution fold;
    try {
      fold = hand_eye::SolveRobotWorldHandEye(Without(observations, i), diversity);
    } catch (const std::runtime_error&) {
      continue;  // the other poses alone cannot determine it
    }
    const std::vector<hand_eye::BoardView> fold_views = Without(board_views, i);
    for (size_t m = 0; m < methods.size(); ++m) {
      const auto [X, Z] = solve(methods[m].second, fold_views, fold);
      const hand_eye::PoseResidual error = hand_eye::PoseResiduals({observations[i]}, X, Z)[0];
      rotation[m].push_back(error.rotation_deg);
      translation[m].push_back(error.translation_mm);
    }
  }
  for (size_t m = 0; m < methods.size(); ++m) {
    candidates[m].loo_rotation_deg = Median(rotation[m]);
    candidates[m].loo_translation_mm = Median(translation[m]);
  }
  // Best first; std::stable_sort keeps the order of preference on a tie.
  std::stable_sort(
      candidates.begin(), candidates.end(),
      [](const HandEyeCandidate& a, const HandEyeCandidate& b) { return Score(a) < Score(b); });
  HandEyeChoice choice;
  choice.closed_form_rms_px = Rms(hand_eye::ViewReprojectionRms(
      board_views, intrinsics, closed.T_board_base, closed.T_cam_flange));
  choice.chosen = candidates[0];
  choice.alternative = candidates[1];
  choice.candidates = candidates;
  return choice;
}

}  // namespace avc::calibration
