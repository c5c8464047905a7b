#pragma once

// Closed form or refined robot-world/hand-eye: whichever better predicts the board pose at a
// robot pose left out of its fit (leave-one-out over the hand-eye poses). The refinement wins on
// a UR5-class arm (its robot-pose prior is that arm's repeatability), but an arm whose reported
// poses are ten times less consistent lets it bend the camera to fit them (2.8 deg about the
// optical axis on a real Franka set, worse in leave-one-out than the closed form), so the data
// decides.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/calibration/hand_eye/motion_diversity.h"
#include "core/calibration/hand_eye/reprojection_refinement.h"
#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "core/camera/pinhole_camera.h"

namespace avc::calibration {

struct HandEyeCandidate {
  std::string method;  // "refined" or "closed form"
  Eigen::Isometry3d T_board_base = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_cam_flange = Eigen::Isometry3d::Identity();
  std::vector<double> view_rms_px;  // corners through the chain, per view
  double rms_px = 0;
  // Median over the poses of the board pose predicted without that pose against the one seen.
  double loo_rotation_deg = 0;
  double loo_translation_mm = 0;
};

struct HandEyeChoice {
  HandEyeCandidate chosen;
  HandEyeCandidate alternative;              // the runner-up
  std::vector<HandEyeCandidate> candidates;  // every one tried, best first
  double closed_form_rms_px = 0;
};

// The candidates: the refinement with the given robot-pose prior; the refinement with the prior
// widened to the closed form's pose residuals when they show a noisier arm (half their median);
// the closed form. Each is solved from all poses and scored by leave-one-out (rotation in units of
// 0.01 deg plus translation in units of 0.1 mm, the targets' ratio); on a tie the earlier one in
// that order. A fold whose remaining poses the closed form refuses (too little rotation) is
// skipped. Throws what
// SolveRobotWorldHandEye and RefineOnReprojection throw for the whole set.
HandEyeChoice ChooseHandEye(const std::vector<hand_eye::HandEyeObservation>& observations,
                            const std::vector<hand_eye::BoardView>& board_views,
                            const camera::Intrinsics& intrinsics,
                            const hand_eye::DiversityLimits& diversity,
                            const hand_eye::RefinementOptions& refinement);

}  // namespace avc::calibration
