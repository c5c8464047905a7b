#include <fmt/format.h>

#include <string>

#include "bench/calibration/hand_eye/hand_eye_trials.h"

namespace avc::bench {
namespace {

// "median (p90)" of one metric.
std::string Cell(const nlohmann::json& metrics, const char* metric) {
  const nlohmann::json& statistics = metrics[metric];
  return fmt::format("{:.4g} ({:.4g})", statistics["median"].get<double>(),
                     statistics["p90"].get<double>());
}

std::string Row(const std::string& label, const nlohmann::json& metrics) {
  return fmt::format(
      "  {:<22} {:>22} {:>22} {:>22} {:>22}\n", label, Cell(metrics, "hand_eye_rotation_deg"),
      Cell(metrics, "hand_eye_translation_mm"), Cell(metrics, "robot_world_rotation_deg"),
      Cell(metrics, "robot_world_translation_mm"));
}

std::string CaseTable(const nlohmann::json& result) {
  std::string text = fmt::format(
      "hand-eye case '{}': {} trials x {} poses, corners {} px, robot {} deg / {} mm, seed {}, "
      "{:.1f} s\n",
      result["case"].get<std::string>(), result["trials"].get<int>(), result["poses"].get<int>(),
      result["pixel_sigma_px"].get<double>(), result["robot_rotation_sigma_deg"].get<double>(),
      result["robot_translation_sigma_mm"].get<double>(), result["seed"].get<uint64_t>(),
      result["seconds"].get<double>());
  text +=
      fmt::format("  {:<22} {:>22} {:>22} {:>22} {:>22}\n", "median (p90)", "hand-eye rot [deg]",
                  "hand-eye trans [mm]", "robot-world rot [deg]", "robot-world trans [mm]");
  const nlohmann::json& methods = result["methods"];
  text += Row("D&H closed form", methods["closed_form"]);
  text += Row("Ceres reprojection", methods["ceres"]);
  text += Row("OpenCV SHAH", methods["opencv_shah"]);
  text += Row("closed form vs SHAH", result["closed_form_vs_shah"]);
  const nlohmann::json& rms = result["reprojection_rms_px"];
  text +=
      fmt::format("  reprojection RMS [px] median: closed form {:.4g}, Ceres {:.4g}\n",
                  rms["closed_form"]["median"].get<double>(), rms["ceres"]["median"].get<double>());
  text += fmt::format("  failed trials: {}\n", result["failed_trials"].get<int>());
  const nlohmann::json& acceptance = result["acceptance"];
  for (const auto& [key, value] : acceptance.items()) {
    if (value.is_boolean())
      text += fmt::format("  {:<46} {}\n", key, value.get<bool>() ? "met" : "NOT MET");
  }
  return text;
}

}  // namespace

std::string FormatHandEyeTable(const nlohmann::json& results) {
  if (!results.contains("cases")) return CaseTable(results);
  std::string text;
  for (const nlohmann::json& result : results["cases"]) text += CaseTable(result) + "\n";
  text += fmt::format("hand-eye acceptance: {} ({:.1f} s)\n",
                      results["acceptance_met"].get<bool>() ? "all targets met" : "NOT MET",
                      results["seconds"].get<double>());
  return text;
}

}  // namespace avc::bench
