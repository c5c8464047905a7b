#pragma once

// The planner as a service (avc-planner) answers plan jobs (core/stage, stage "plan"). Each job
// carries every view the planner has asked for in this scan and what became of it (its plant
// mask, or nothing when the cell refused the view); the answer is the next view to capture, or
// the final plan. The planner is deterministic, so the same answered views always lead to the
// same next view: a re-sent job, a restarted planner or a resumed scan all continue the same
// plan. The folder layout, shared by both sides:
//   job:    plan_request.json (the answered views in order), masks/view_<n>.png (8-bit, 0/255)
//   answer: plan.json (phase, next view or final plan, the plant's keep-out, settings in force)

#include <Eigen/Geometry>
#include <filesystem>
#include <map>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/kinematics/dh_parameters.h"
#include "core/kinematics/plant_keep_out.h"

namespace avc::plan {

inline constexpr char kRequestFile[] = "plan_request.json";
inline constexpr char kAnswerFile[] = "plan.json";

// Where the arm and the turntable go for a view.
struct ViewRequest {
  kinematics::JointVector joints = kinematics::JointVector::Zero();
  double table_angle = 0;  // radians
};

struct AnsweredView {
  ViewRequest view;
  // The plant mask as PNG (EncodeMask); nullopt: the cell refused the view.
  std::optional<std::string> mask_png;
};

struct PlanRequest {
  std::vector<AnsweredView> answered;  // every view asked for so far, in the order asked
};

// The planner's stages, in order (Algorithm 1): framing, the initial orbit, next-best views,
// redundant-view removal.
enum class PlanPhase { kFrame, kInitialCapture, kActiveVision, kPruneViews };
const char* PhaseName(PlanPhase phase);

struct PlannedView {
  ViewRequest view;
  std::string phase;   // "initial" or "active"
  std::string reason;  // why it was chosen
  int patch = -1;      // active: the proxy patch it was chosen for
  double patch_score = 0;
  bool kept = true;  // false: removed as redundant
};

// The final plan, once the planner wants no more views.
struct FinalPlan {
  std::vector<PlannedView> views;  // in capture order
  int patches = 0;
  int failing_patches = 0;
  std::vector<std::string> notes;  // what could not be done, and why
  double planning_seconds_per_view = 0;
};

struct PlanAnswer {
  PlanPhase phase = PlanPhase::kFrame;
  std::optional<ViewRequest> next;              // the view to capture next; nullopt when finished
  std::optional<FinalPlan> final_plan;          // when finished
  kinematics::PlantKeepOut keep_out;            // the plant's space so far (empty before a proxy)
  std::map<std::string, std::string> settings;  // the planner's settings in force
};

// A plant mask (CV_8UC1, non-zero = plant) as PNG, and back. DecodeMask throws
// std::runtime_error naming `what` when the bytes are not an 8-bit image.
std::string EncodeMask(const cv::Mat& mask);
cv::Mat DecodeMask(const std::string& png, const std::string& what);

// The files WritePlanRequest writes for `request`, relative to its folder, in a fixed order.
std::vector<std::string> PlanRequestFiles(const PlanRequest& request);

// Both write into `folder` (created) and read from it; a reader throws std::runtime_error naming
// the file and the field that is missing or wrong (a mask's pixels are only read by DecodeMask).
void WritePlanRequest(const PlanRequest& request, const std::filesystem::path& folder);
PlanRequest ReadPlanRequest(const std::filesystem::path& folder);
void WritePlanAnswer(const PlanAnswer& answer, const std::filesystem::path& folder);
PlanAnswer ReadPlanAnswer(const std::filesystem::path& folder);

// The same pose within `tolerance` (radians, every joint and the table).
bool SameView(const ViewRequest& a, const ViewRequest& b, double tolerance = 1e-9);

}  // namespace avc::plan
