#include "core/calibration/pipeline/hand_eye_choice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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
  const hand_eye::RefinementResult refined = hand_eye::RefineOnReprojection(
      board_views, intrinsics, closed.T_board_base, closed.T_cam_flange, refinement);
  HandEyeCandidate closed_form;
  closed_form.method = "closed form";
  closed_form.T_board_base = closed.T_board_base;
  closed_form.T_cam_flange = closed.T_cam_flange;
  closed_form.view_rms_px = hand_eye::ViewReprojectionRms(board_views, intrinsics,
                                                          closed.T_board_base, closed.T_cam_flange);
  closed_form.rms_px = Rms(closed_form.view_rms_px);
  HandEyeCandidate refined_form;
  refined_form.method = "refined";
  refined_form.T_board_base = refined.T_board_base;
  refined_form.T_cam_flange = refined.T_cam_flange;
  refined_form.view_rms_px = refined.view_rms_px;
  refined_form.rms_px = refined.rms_px;

  std::vector<double> closed_rotation, closed_translation, refined_rotation, refined_translation;
  for (size_t i = 0; i < observations.size(); ++i) {
    hand_eye::HandEyeSolution fold;
    try {
      fold = hand_eye::SolveRobotWorldHandEye(Without(observations, i), diversity);
    } catch (const std::runtime_error&) {
      continue;  // the other poses alone cannot determine it
    }
    const hand_eye::RefinementResult fold_refined = hand_eye::RefineOnReprojection(
        Without(board_views, i), intrinsics, fold.T_board_base, fold.T_cam_flange, refinement);
    const hand_eye::PoseResidual closed_error =
        hand_eye::PoseResiduals({observations[i]}, fold.T_board_base, fold.T_cam_flange)[0];
    const hand_eye::PoseResidual refined_error = hand_eye::PoseResiduals(
        {observations[i]}, fold_refined.T_board_base, fold_refined.T_cam_flange)[0];
    closed_rotation.push_back(closed_error.rotation_deg);
    closed_translation.push_back(closed_error.translation_mm);
    refined_rotation.push_back(refined_error.rotation_deg);
    refined_translation.push_back(refined_error.translation_mm);
  }
  closed_form.loo_rotation_deg = Median(closed_rotation);
  closed_form.loo_translation_mm = Median(closed_translation);
  refined_form.loo_rotation_deg = Median(refined_rotation);
  refined_form.loo_translation_mm = Median(refined_translation);

  HandEyeChoice choice;
  choice.closed_form_rms_px = refined.initial_rms_px;
  const bool refined_wins = Score(refined_form) <= Score(closed_form);
  choice.chosen = refined_wins ? refined_form : closed_form;
  choice.alternative = refined_wins ? closed_form : refined_form;
  return choice;
}

}  // namespace avc::calibration
