#include "services/planner/plan_session.h"

#include <fmt/format.h>

#include <exception>
#include <stdexcept>
#include <utility>

#include "core/kinematics/plant_keep_out.h"

namespace avc::planner {
namespace {

// Unwinds the planner's thread when its session is dropped.
struct Cancelled {};

plan::PlanPhase PhaseOf(ActiveVisionStage stage) {
  switch (stage) {
    case ActiveVisionStage::kFrame:
      return plan::PlanPhase::kFrame;
    case ActiveVisionStage::kInitialCapture:
      return plan::PlanPhase::kInitialCapture;
    case ActiveVisionStage::kActiveVision:
      return plan::PlanPhase::kActiveVision;
    case ActiveVisionStage::kPruneViews:
      return plan::PlanPhase::kPruneViews;
  }
  throw std::logic_error("unknown active vision stage");
}

}  // namespace

plan::FinalPlan FinalPlanOf(const ActiveVisionResult& result) {
  plan::FinalPlan plan;
  for (const PlannedView& view : result.views) {
    plan.views.push_back({{view.view.joints, view.view.turntable_angle},
                          view.phase,
                          view.reason,
                          view.patch,
                          view.patch_score,
                          view.kept});
  }
  plan.patches = result.patches;
  plan.failing_patches = result.failing_patches;
  plan.notes = result.notes;
  plan.planning_seconds_per_view = result.planning_seconds_per_view;
  return plan;
}

PlanSession::PlanSession(cell::CellModel cell, ActiveVisionOptions options, double keep_out_margin)
    : keep_out_margin_(keep_out_margin), T_base_table_(cell.T_base_table) {
  thread_ = std::thread(
      [this, cell = std::move(cell), options = std::move(options)] { Run(cell, options); });
}

PlanSession::~PlanSession() {
  {
    std::lock_guard lock(mutex_);
    cancelled_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void PlanSession::Run(const cell::CellModel& cell, const ActiveVisionOptions& options) {
  try {
    ActiveVisionResult result = RunActiveVision(
        cell, [this](const CellView& view) { return Capture(view); }, options,
        [this](ActiveVisionStage stage) {
          std::lock_guard lock(mutex_);
          phase_ = PhaseOf(stage);
        },
        [this](const ppr::PlantProxy& proxy) {
          kinematics::PlantKeepOut keep_out = kinematics::PlantKeepOutFromVoxels(
              proxy.OccupiedCentres(), proxy.voxel_size(), T_base_table_, keep_out_margin_);
          std::lock_guard lock(mutex_);
          keep_out_ = std::move(keep_out);
        });
    std::lock_guard lock(mutex_);
    phase_ = plan::PlanPhase::kPruneViews;
    result_ = std::move(result);
  } catch (const Cancelled&) {
    return;
  } catch (const std::exception& error) {
    std::lock_guard lock(mutex_);
    failure_ = error.what();
  }
  changed_.notify_all();
}

std::optional<cv::Mat> PlanSession::Capture(const CellView& view) {
  const plan::ViewRequest asked{view.joints, view.turntable_angle};
  std::unique_lock lock(mutex_);
  asked_ = asked;
  changed_.notify_all();
  changed_.wait(lock, [&] { return cancelled_ || consumed_ < answered_.size(); });
  if (cancelled_) throw Cancelled{};
  asked_.reset();
  const plan::AnsweredView& answer = answered_[consumed_];
  if (!plan::SameView(answer.view, asked)) {
    throw std::runtime_error(fmt::format(
        "the plan request's view {} is not the view the planner asks for there (table {:.4f} "
        "rad asked, {:.4f} answered): the request is from another plan",
        consumed_, asked.table_angle, answer.view.table_angle));
  }
  ++consumed_;
  if (!answer.mask_png) return std::nullopt;
  return plan::DecodeMask(*answer.mask_png,
                          fmt::format("the mask of answered view {}", consumed_ - 1));
}

bool PlanSession::Continues(const plan::PlanRequest& request) const {
  std::lock_guard lock(mutex_);
  if (!failure_.empty() || request.answered.size() < consumed_) return false;
  for (size_t i = 0; i < consumed_; ++i) {
    if (!plan::SameView(request.answered[i].view, answered_[i].view) ||
        request.answered[i].mask_png != answered_[i].mask_png) {
      return false;
    }
  }
  return true;
}

plan::PlanAnswer PlanSession::Advance(const plan::PlanRequest& request) {
  std::unique_lock lock(mutex_);
  answered_ = request.answered;
  changed_.notify_all();
  changed_.wait(lock, [&] {
    return result_.has_value() || !failure_.empty() ||
           (asked_.has_value() && consumed_ == answered_.size());
  });
  if (!failure_.empty()) throw std::runtime_error(failure_);
  plan::PlanAnswer answer;
  answer.phase = phase_;
  answer.keep_out = keep_out_;
  if (result_) {
    answer.final_plan = FinalPlanOf(*result_);
  } else {
    answer.next = asked_;
  }
  return answer;
}

}  // namespace avc::planner
