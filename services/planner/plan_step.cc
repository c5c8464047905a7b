#include "services/planner/plan_step.h"

#include <fmt/format.h>

#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "core/calibration/cell/calibration_yaml.h"
#include "core/plan/plan_exchange.h"
#include "core/util/file_io.h"
#include "services/planner/calibrated_cell.h"
#include "services/planner/plan_session.h"
#include "services/planner/plan_settings.h"

namespace avc::planner {
namespace {

// Scans planned at once by one planner are rare; a few sessions cover a resumed scan beside a
// new one.
constexpr size_t kSessionsKept = 3;

struct Session {
  std::string scan_id;
  std::string calibration;            // calibration.yaml's bytes
  std::vector<std::string> settings;  // the job's, as given
  std::unique_ptr<PlanSession> session;
};

class PlanJobs {
 public:
  explicit PlanJobs(PlanSettings base) : base_(std::move(base)) {}

  void Run(const stage::StageWork& work) {
    const std::string calibration = ReadFile(work.input_dir / kCalibrationFile);
    const PlanSettings settings = ParsePlanSettings(work.settings, base_);
    const plan::PlanRequest request = plan::ReadPlanRequest(work.input_dir);
    PlanSession& session = SessionFor(work, calibration, settings, request);
    if (work.progress) {
      work.progress(fmt::format("planning after {} answered views", request.answered.size()));
    }
    plan::PlanAnswer answer = session.Advance(request);
    answer.settings = DescribePlanSettings(settings);
    plan::WritePlanAnswer(answer, work.output_dir);
  }

 private:
  PlanSession& SessionFor(const stage::StageWork& work, const std::string& calibration,
                          const PlanSettings& settings, const plan::PlanRequest& request) {
    for (auto it = sessions_.begin(); it != sessions_.end(); ++it) {
      if (it->scan_id != work.scan_id) continue;
      if (it->calibration == calibration && it->settings == work.settings &&
          it->session->Continues(request)) {
        return *it->session;
      }
      sessions_.erase(it);  // stops its planner
      break;
    }
    const std::filesystem::path calibration_file = work.input_dir / kCalibrationFile;
    const cell::CellModel cell =
        CellModelFromCalibration(calibration::LoadCalibration(calibration_file));
    if (work.progress && !request.answered.empty()) {
      work.progress(fmt::format("new plan for scan {}: replaying {} answered views", work.scan_id,
                                request.answered.size()));
    }
    if (sessions_.size() >= kSessionsKept) sessions_.pop_front();
    sessions_.push_back(
        {work.scan_id, calibration, work.settings,
         std::make_unique<PlanSession>(cell, settings.planner, settings.keep_out_margin)});
    return *sessions_.back().session;
  }

  PlanSettings base_;
  std::deque<Session> sessions_;
};

}  // namespace

stage::StageHandler PlanStageHandler(const PlanSettings& settings) {
  // The stage server runs one job at a time; the mutex only guards against a handler copied
  // into two servers.
  auto jobs = std::make_shared<PlanJobs>(settings);
  auto mutex = std::make_shared<std::mutex>();
  return [jobs, mutex](const stage::StageWork& work) {
    std::lock_guard lock(*mutex);
    jobs->Run(work);
  };
}

}  // namespace avc::planner
