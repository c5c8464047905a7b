// A plan job's files as avc-planner reads them from the bus (plan::ReadPlanRequest, then each
// answered mask decoded as the planner takes it) and the answer as avc scan reads it
// (plan::ReadPlanAnswer). Input: plan_request.json, then plan.json, then masks/view_0000.png.

#include <cstdint>
#include <stdexcept>

#include "core/plan/plan_exchange.h"

#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto parts = avc::fuzz::SplitParts(avc::fuzz::AsText(data, size), 3);
  const auto dir = avc::fuzz::FreshDir("plan");
  avc::fuzz::WriteFile(dir, avc::plan::kRequestFile, parts[0]);
  avc::fuzz::WriteFile(dir, avc::plan::kAnswerFile, parts[1]);
  std::filesystem::create_directories(dir / "masks");
  avc::fuzz::WriteFile(dir / "masks", "view_0000.png", parts[2]);
  try {
    const avc::plan::PlanRequest request = avc::plan::ReadPlanRequest(dir);
    for (const avc::plan::AnsweredView& view : request.answered) {
      if (view.mask_png) avc::plan::DecodeMask(*view.mask_png, "a mask");
    }
  } catch (const std::runtime_error&) {  // names the file and the field
  }
  try {
    avc::plan::ReadPlanAnswer(dir);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
