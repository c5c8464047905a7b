#include "core/plan/plan_exchange.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "core/kinematics/row_major_pose.h"
#include "core/util/file_io.h"

namespace avc::plan {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kPhaseNames[] = {"FRAME", "INITIAL_CAPTURE", "ACTIVE_VISION", "PRUNE_VIEWS"};

json ViewJson(const ViewRequest& view) {
  return {{"joints", std::vector<double>(view.joints.data(), view.joints.data() + 6)},
          {"table_angle", view.table_angle}};
}

// Reads `file`'s JSON; `what` names the place in it for errors.
class Reader {
 public:
  explicit Reader(fs::path file) : file_(std::move(file)) {
    try {
      root_ = json::parse(ReadFile(file_));
    } catch (const json::exception& error) {
      throw std::runtime_error(fmt::format("{}: not JSON: {}", file_.string(), error.what()));
    }
  }
  const json& root() const { return root_; }

  [[noreturn]] void Fail(const std::string& where, const std::string& what) const {
    throw std::runtime_error(fmt::format("{}: {} {}", file_.string(), where, what));
  }

  const json& Field(const json& object, const char* key, const std::string& where) const {
    if (!object.is_object() || !object.contains(key)) Fail(where, fmt::format("has no '{}'", key));
    return object.at(key);
  }

  double Number(const json& object, const char* key, const std::string& where) const {
    const json& value = Field(object, key, where);
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
      Fail(where + "." + key, "must be a finite number, got " + value.dump());
    }
    return value.get<double>();
  }

  std::string Text(const json& object, const char* key, const std::string& where) const {
    const json& value = Field(object, key, where);
    if (!value.is_string()) Fail(where + "." + key, "must be a string, got " + value.dump());
    return value.get<std::string>();
  }

  std::vector<double> Numbers(const json& object, const char* key, const std::string& where,
                              std::optional<size_t> size = std::nullopt) const {
    const json& value = Field(object, key, where);
    if (!value.is_array() || (size && value.size() != *size)) {
      Fail(where + "." + key,
           size ? fmt::format("must be {} numbers", *size) : std::string("must be an array"));
    }
    std::vector<double> numbers;
    for (const json& item : value) {
      if (!item.is_number() || !std::isfinite(item.get<double>())) {
        Fail(where + "." + key, "holds a value that is not a finite number: " + item.dump());
      }
      numbers.push_back(item.get<double>());
    }
    return numbers;
  }

  ViewRequest View(const json& object, const std::string& where) const {
    ViewRequest view;
    const std::vector<double> q = Numbers(object, "joints", where, 6);
    for (int i = 0; i < 6; ++i) view.joints[i] = q[i];
    view.table_angle = Number(object, "table_angle", where);
    return view;
  }

 private:
  fs::path file_;
  json root_;
};

std::string MaskFile(size_t index) { return fmt::format("masks/view_{:04d}.png", index); }

}  // namespace

const char* PhaseName(PlanPhase phase) { return kPhaseNames[static_cast<int>(phase)]; }

bool SameView(const ViewRequest& a, const ViewRequest& b, double tolerance) {
  return (a.joints - b.joints).cwiseAbs().maxCoeff() <= tolerance &&
         std::abs(a.table_angle - b.table_angle) <= tolerance;
}

std::string EncodeMask(const cv::Mat& mask) {
  std::vector<uint8_t> png;
  if (mask.type() != CV_8UC1 || !cv::imencode(".png", mask, png)) {
    throw std::invalid_argument("a plant mask must be an 8-bit, one-channel image");
  }
  return {png.begin(), png.end()};
}

cv::Mat DecodeMask(const std::string& png, const std::string& what) {
  const cv::Mat bytes(1, static_cast<int>(png.size()), CV_8UC1, const_cast<char*>(png.data()));
  cv::Mat mask = png.empty() ? cv::Mat() : cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  if (mask.empty() || mask.type() != CV_8UC1) {
    throw std::runtime_error(what + " is not an 8-bit one-channel image");
  }
  return mask;
}

std::vector<std::string> PlanRequestFiles(const PlanRequest& request) {
  std::vector<std::string> files = {kRequestFile};
  for (size_t i = 0; i < request.answered.size(); ++i) {
    if (request.answered[i].mask_png) files.push_back(MaskFile(i));
  }
  return files;
}

void WritePlanRequest(const PlanRequest& request, const fs::path& folder) {
  fs::create_directories(folder / "masks");
  json answered = json::array();
  for (size_t i = 0; i < request.answered.size(); ++i) {
    const AnsweredView& view = request.answered[i];
    json entry = ViewJson(view.view);
    if (view.mask_png) {
      WriteFileAtomically(folder / MaskFile(i), *view.mask_png);
      entry["mask"] = MaskFile(i);
    } else {
      entry["mask"] = nullptr;
    }
    answered.push_back(std::move(entry));
  }
  WriteFileAtomically(folder / kRequestFile, json{{"answered", answered}}.dump(1) + "\n");
}

PlanRequest ReadPlanRequest(const fs::path& folder) {
  const Reader reader(folder / kRequestFile);
  const json& answered = reader.Field(reader.root(), "answered", "the request");
  if (!answered.is_array()) reader.Fail("answered", "must be an array");
  PlanRequest request;
  for (size_t i = 0; i < answered.size(); ++i) {
    const std::string where = fmt::format("answered[{}]", i);
    AnsweredView view;
    view.view = reader.View(answered[i], where);
    const json& mask = reader.Field(answered[i], "mask", where);
    if (!mask.is_null()) {
      if (!mask.is_string() || mask.get<std::string>() != MaskFile(i)) {
        reader.Fail(where + ".mask", fmt::format("must be \"{}\" or null", MaskFile(i)));
      }
      try {
        view.mask_png = ReadFile(folder / MaskFile(i));
      } catch (const std::runtime_error& error) {
        reader.Fail(where + ".mask", std::string("cannot be read: ") + error.what());
      }
    }
    request.answered.push_back(std::move(view));
  }
  return request;
}

void WritePlanAnswer(const PlanAnswer& answer, const fs::path& folder) {
  json root = {{"phase", PhaseName(answer.phase)}, {"settings", answer.settings}};
  root["next"] = answer.next ? ViewJson(*answer.next) : json(nullptr);
  if (answer.keep_out.empty()) {
    root["keep_out"] = nullptr;
  } else {
    std::vector<double> T(16);
    kinematics::RowMajorFromIsometry(answer.keep_out.T_base_table, T.data());
    root["keep_out"] = {{"T_base_table", T},
                        {"z0_m", answer.keep_out.z0_m},
                        {"slab_m", answer.keep_out.slab_m},
                        {"radius_m", answer.keep_out.radius_m}};
  }
  if (answer.final_plan) {
    const FinalPlan& plan = *answer.final_plan;
    json views = json::array();
    for (const PlannedView& view : plan.views) {
      json entry = ViewJson(view.view);
      entry.update({{"phase", view.phase},
                    {"reason", view.reason},
                    {"patch", view.patch},
                    {"patch_score", view.patch_score},
                    {"kept", view.kept}});
      views.push_back(std::move(entry));
    }
    root["final"] = {{"views", views},
                     {"patches", plan.patches},
                     {"failing_patches", plan.failing_patches},
                     {"notes", plan.notes},
                     {"planning_seconds_per_view", plan.planning_seconds_per_view}};
  } else {
    root["final"] = nullptr;
  }
  fs::create_directories(folder);
  WriteFileAtomically(folder / kAnswerFile, root.dump(1) + "\n");
}

PlanAnswer ReadPlanAnswer(const fs::path& folder) {
  const Reader reader(folder / kAnswerFile);
  const json& root = reader.root();
  PlanAnswer answer;
  const std::string phase = reader.Text(root, "phase", "the answer");
  const auto* found = std::find(std::begin(kPhaseNames), std::end(kPhaseNames), phase);
  if (found == std::end(kPhaseNames)) reader.Fail("phase", "is not a planner phase: " + phase);
  answer.phase = static_cast<PlanPhase>(found - std::begin(kPhaseNames));
  const json& settings = reader.Field(root, "settings", "the answer");
  if (!settings.is_object()) reader.Fail("settings", "must be an object");
  for (const auto& [key, value] : settings.items()) {
    if (!value.is_string()) reader.Fail("settings." + key, "must be a string");
    answer.settings[key] = value.get<std::string>();
  }
  if (const json& next = reader.Field(root, "next", "the answer"); !next.is_null()) {
    answer.next = reader.View(next, "next");
  }
  if (const json& keep_out = reader.Field(root, "keep_out", "the answer"); !keep_out.is_null()) {
    answer.keep_out.T_base_table = kinematics::IsometryFromRowMajor(
        reader.Numbers(keep_out, "T_base_table", "keep_out", 16).data());
    answer.keep_out.z0_m = reader.Number(keep_out, "z0_m", "keep_out");
    answer.keep_out.slab_m = reader.Number(keep_out, "slab_m", "keep_out");
    answer.keep_out.radius_m = reader.Numbers(keep_out, "radius_m", "keep_out");
    if (const std::string problem = answer.keep_out.Validate(); !problem.empty()) {
      reader.Fail("keep_out", "is not usable: " + problem);
    }
  }
  if (const json& plan = reader.Field(root, "final", "the answer"); !plan.is_null()) {
    FinalPlan final_plan;
    const json& views = reader.Field(plan, "views", "final");
    if (!views.is_array()) reader.Fail("final.views", "must be an array");
    for (size_t i = 0; i < views.size(); ++i) {
      const std::string where = fmt::format("final.views[{}]", i);
      PlannedView view;
      view.view = reader.View(views[i], where);
      view.phase = reader.Text(views[i], "phase", where);
      view.reason = reader.Text(views[i], "reason", where);
      view.patch = static_cast<int>(reader.Number(views[i], "patch", where));
      view.patch_score = reader.Number(views[i], "patch_score", where);
      const json& kept = reader.Field(views[i], "kept", where);
      if (!kept.is_boolean()) reader.Fail(where + ".kept", "must be true or false");
      view.kept = kept.get<bool>();
      final_plan.views.push_back(std::move(view));
    }
    final_plan.patches = static_cast<int>(reader.Number(plan, "patches", "final"));
    final_plan.failing_patches = static_cast<int>(reader.Number(plan, "failing_patches", "final"));
    const json& notes = reader.Field(plan, "notes", "final");
    if (!notes.is_array()) reader.Fail("final.notes", "must be an array");
    for (const json& note : notes) {
      if (!note.is_string()) reader.Fail("final.notes", "must hold strings");
      final_plan.notes.push_back(note.get<std::string>());
    }
    final_plan.planning_seconds_per_view =
        reader.Number(plan, "planning_seconds_per_view", "final");
    answer.final_plan = std::move(final_plan);
  }
  if (answer.next.has_value() == answer.final_plan.has_value()) {
    reader.Fail("the answer", "must have either a next view or a final plan");
  }
  return answer;
}

}  // namespace avc::plan
