#include "core/calibration/pipeline/calibration_dataset.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/geometry/rigid_transform.h"

namespace avc::calibration {
namespace {

constexpr const char* kFormat = "avc-calibration-dataset";
constexpr int kVersion = 1;

const char* PurposeName(ShotPurpose purpose) {
  return purpose == ShotPurpose::kHandEye ? "hand_eye" : "turntable";
}

}  // namespace

CalibrationDataset LoadCalibrationDataset(const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / "dataset.json";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  const nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error(fmt::format("{}: {}", path.string(), what));
  };
  if (doc.is_discarded() || !doc.is_object()) fail("not valid JSON");
  if (doc.value("format", "") != kFormat) fail(fmt::format("\"format\" is not \"{}\"", kFormat));
  if (doc.value("version", 0) != kVersion) {
    fail(fmt::format("version {} is not supported (this AVC reads {})", doc.value("version", 0),
                     kVersion));
  }
  CalibrationDataset dataset;
  dataset.folder = folder;
  try {
    const nlohmann::json& board = doc.at("board");
    dataset.board.cols = board.at("cols").get<int>();
    dataset.board.rows = board.at("rows").get<int>();
    dataset.board.square_size = board.at("square").get<double>();
  } catch (const nlohmann::json::exception& error) {
    fail(std::string("board: ") + error.what());
  }
  if (const std::string problem = dataset.board.Validate(); !problem.empty()) {
    fail("board: " + problem);
  }
  if (!doc.contains("shots") || !doc["shots"].is_array()) fail("no \"shots\" list");
  for (size_t i = 0; i < doc["shots"].size(); ++i) {
    const nlohmann::json& entry = doc["shots"][i];
    if (!entry.is_object()) fail(fmt::format("shot {} is not an object", i));
    const bool named = entry.contains("image") && entry["image"].is_string();
    const std::string name = named
                                 ? fmt::format("shot {} ({})", i, entry["image"].get<std::string>())
                                 : fmt::format("shot {}", i);
    // Each missing or mistyped field is named with its shot.
    const auto field = [&](const char* key) -> const nlohmann::json& {
      if (!entry.contains(key)) fail(fmt::format("{}: no \"{}\"", name, key));
      return entry[key];
    };
    CalibrationShot shot;
    if (!field("image").is_string() || field("image").get<std::string>().empty()) {
      fail(name + ": \"image\" must be the image's file name");
    }
    shot.image = entry["image"].get<std::string>();
    const nlohmann::json& purpose = field("purpose");
    if (purpose != "hand_eye" && purpose != "turntable") {
      fail(fmt::format("shot {}: unknown purpose {} (hand_eye or turntable)", i, purpose.dump()));
    }
    shot.purpose = purpose == "hand_eye" ? ShotPurpose::kHandEye : ShotPurpose::kTurntable;
    // A hand-eye shot's table angle means nothing (the board lies still): optional there.
    if (shot.purpose == ShotPurpose::kTurntable || entry.contains("table_angle")) {
      const nlohmann::json& angle = field("table_angle");
      // JSON has no NaN: a non-finite angle was written as null.
      if (!angle.is_number()) fail(name + ": \"table_angle\" must be a finite number (radians)");
      shot.table_angle = angle.get<double>();
    }
    // JSON has no NaN: a non-finite pose was written as null.
    const nlohmann::json& pose = field("T_base_flange");
    const bool numbers =
        pose.is_array() && pose.size() == 16 &&
        std::all_of(pose.begin(), pose.end(), [](const auto& v) { return v.is_number(); });
    if (!numbers) fail(name + ": T_base_flange must be 16 finite numbers");
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        shot.T_base_flange.matrix()(r, c) = pose[static_cast<size_t>(4 * r + c)].get<double>();
      }
    }
    if (!std::isfinite(shot.table_angle)) {
      fail(fmt::format("shot {} ({}): table angle is not finite", i, shot.image));
    }
    if (auto problem = geometry::RigidTransformProblem(
            shot.T_base_flange, fmt::format("shot {} ({}): T_base_flange", i, shot.image));
        !problem.empty()) {
      fail(problem);
    }
    if (!std::filesystem::exists(folder / shot.image)) {
      fail(fmt::format("shot {}: image {} does not exist", i, (folder / shot.image).string()));
    }
    dataset.shots.push_back(std::move(shot));
  }
  return dataset;
}

void SaveCalibrationDataset(const CalibrationDataset& dataset) {
  nlohmann::ordered_json doc;
  doc["format"] = kFormat;
  doc["version"] = kVersion;
  doc["board"] = {{"cols", dataset.board.cols},
                  {"rows", dataset.board.rows},
                  {"square", dataset.board.square_size}};
  doc["shots"] = nlohmann::ordered_json::array();
  for (const CalibrationShot& shot : dataset.shots) {
    std::vector<double> m;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) m.push_back(shot.T_base_flange.matrix()(r, c));
    }
    doc["shots"].push_back({{"image", shot.image},
                            {"purpose", PurposeName(shot.purpose)},
                            {"table_angle", shot.table_angle},
                            {"T_base_flange", m}});
  }
  const std::filesystem::path path = dataset.folder / "dataset.json";
  std::ofstream out(path, std::ios::trunc);
  out << doc.dump(1) << "\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace avc::calibration
