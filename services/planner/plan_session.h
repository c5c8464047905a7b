#pragma once

// Algorithm 1 (active_vision.h) as a conversation, for avc-planner: the planner runs on its own
// thread and, each time it wants a picture, waits for the scan to say what became of that view.
// Advance() hands it the answered views of a plan job and returns when the planner asks for a
// view beyond them (the job's answer: capture this next) or has finished (the final plan).
// Between jobs the planner waits where it stopped, so a scan of N views costs one planning run,
// not N. A session that is not continued by a job (the planner restarted, the scan resumed from
// its start) is replaced by a new one, which replays the answered views without waiting: the
// planner is deterministic, so it asks for the same views again.

#include <Eigen/Geometry>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/cell/cell_model.h"
#include "core/plan/plan_exchange.h"
#include "services/planner/active_vision.h"

namespace avc::planner {

class PlanSession {
 public:
  // Starts the planner. keep_out_margin (metres) grows the proxy into the arm's keep-out.
  PlanSession(cell::CellModel cell, ActiveVisionOptions options, double keep_out_margin);
  // Stops the planner at its next request for a picture and waits for it.
  ~PlanSession();
  PlanSession(const PlanSession&) = delete;
  PlanSession& operator=(const PlanSession&) = delete;

  // True when `request` starts with every view this session has taken an answer for, with the
  // same answers: Advance() can go on from there.
  bool Continues(const plan::PlanRequest& request) const;

  // Gives the planner the request's answered views (Continues() must hold) and waits until it
  // asks for the next one or finishes. Throws std::runtime_error with the planner's own error
  // (no plant in the framing frame, say), or when it asks for another view than the request
  // answered at the same place (the request is not from this plan).
  plan::PlanAnswer Advance(const plan::PlanRequest& request);

 private:
  std::optional<cv::Mat> Capture(const CellView& view);  // the planner's thread
  void Run(const cell::CellModel& cell, const ActiveVisionOptions& options);

  const double keep_out_margin_;
  const Eigen::Isometry3d T_base_table_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<plan::AnsweredView> answered_;
  size_t consumed_ = 0;                     // answers the planner has taken
  std::optional<plan::ViewRequest> asked_;  // the view it waits for (index consumed_)
  plan::PlanPhase phase_ = plan::PlanPhase::kFrame;
  kinematics::PlantKeepOut keep_out_;
  std::optional<ActiveVisionResult> result_;
  std::string failure_;
  bool cancelled_ = false;
  std::thread thread_;
};

// The plan's final form for the scan.
plan::FinalPlan FinalPlanOf(const ActiveVisionResult& result);

}  // namespace avc::planner
