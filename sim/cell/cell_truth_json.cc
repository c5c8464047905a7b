#include "sim/cell/cell_truth_json.h"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace avc::sim {
namespace {

constexpr const char* kFormat = "avc-cell-truth";
constexpr int kVersion = 1;

using nlohmann::json;

json Row(const double* values, int count) {
  return json(std::vector<double>(values, values + count));
}

json PoseToJson(const Eigen::Isometry3d& pose) {
  json rotation = json::array();
  for (int r = 0; r < 3; ++r) {
    rotation.push_back(json({pose.linear()(r, 0), pose.linear()(r, 1), pose.linear()(r, 2)}));
  }
  const Eigen::Vector3d t = pose.translation();
  return {{"rotation_row_major", rotation}, {"translation_m", Row(t.data(), 3)}};
}

const json& Member(const json& object, const std::string& key, const std::string& where) {
  if (!object.is_object())
    throw std::runtime_error(fmt::format("cell truth JSON: {} is not an object", where));
  const auto found = object.find(key);
  if (found == object.end()) {
    throw std::runtime_error(fmt::format("cell truth JSON: missing key {}.{}", where, key));
  }
  return *found;
}

double Number(const json& value, const std::string& where) {
  if (!value.is_number())
    throw std::runtime_error(fmt::format("cell truth JSON: {} is not a number", where));
  return value.get<double>();
}

std::vector<double> Numbers(const json& object, const std::string& key, size_t count,
                            const std::string& where) {
  const json& array = Member(object, key, where);
  const std::string path = where + "." + key;
  if (!array.is_array() || array.size() != count) {
    throw std::runtime_error(
        fmt::format("cell truth JSON: {} must be an array of {} numbers", path, count));
  }
  std::vector<double> values;
  for (size_t i = 0; i < count; ++i)
    values.push_back(Number(array[i], fmt::format("{}[{}]", path, i)));
  return values;
}

kinematics::JointVector Joints(const json& object, const std::string& key,
                               const std::string& where) {
  const std::vector<double> values = Numbers(object, key, 6, where);
  return kinematics::JointVector(values.data());
}

Eigen::Vector3d Vector(const json& object, const std::string& key, const std::string& where) {
  const std::vector<double> values = Numbers(object, key, 3, where);
  return {values[0], values[1], values[2]};
}

Eigen::Isometry3d PoseFromJson(const json& parent, const std::string& key) {
  const json& object = Member(parent, key, "cell");
  const std::string where = "cell." + key;
  const json& rows = Member(object, "rotation_row_major", where);
  if (!rows.is_array() || rows.size() != 3) {
    throw std::runtime_error(
        fmt::format("cell truth JSON: {}.rotation_row_major must hold 3 rows", where));
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    const std::string row_path = fmt::format("{}.rotation_row_major[{}]", where, r);
    if (!rows[r].is_array() || rows[r].size() != 3) {
      throw std::runtime_error(fmt::format("cell truth JSON: {} must hold 3 numbers", row_path));
    }
    for (int c = 0; c < 3; ++c)
      pose.linear()(r, c) = Number(rows[r][c], fmt::format("{}[{}]", row_path, c));
  }
  pose.translation() = Vector(object, "translation_m", where);
  return pose;
}

int Integer(const json& object, const std::string& key, const std::string& where) {
  const json& value = Member(object, key, where);
  if (!value.is_number_integer()) {
    throw std::runtime_error(fmt::format("cell truth JSON: {}.{} is not an integer", where, key));
  }
  return value.get<int>();
}

}  // namespace

json CellTruthToJson(const CellTruth& cell) {
  const camera::Intrinsics& k = cell.intrinsics;
  return {
      {"format", kFormat},
      {"version", kVersion},
      {"robot_dh",
       {{"a_m", Row(cell.dh.a.data(), 6)},
        {"d_m", Row(cell.dh.d.data(), 6)},
        {"alpha_rad", Row(cell.dh.alpha.data(), 6)},
        {"theta_offset_rad", Row(cell.dh.theta_offset.data(), 6)}}},
      {"T_base_table", PoseToJson(cell.T_base_table)},
      {"turntable",
       {{"axis_unit_table", Row(cell.turntable_axis_table.data(), 3)},
        {"centre_table_m", Row(cell.turntable_centre_table.data(), 3)}}},
      {"T_flange_cam", PoseToJson(cell.T_flange_cam)},
      {"intrinsics",
       {{"width_px", k.width},
        {"height_px", k.height},
        {"fx_px", k.fx},
        {"fy_px", k.fy},
        {"cx_px", k.cx},
        {"cy_px", k.cy},
        {"distortion_k1_k2_p1_p2_k3", Row(k.distortion.data(), 5)}}},
  };
}

CellTruth CellTruthFromJson(const json& json_cell) {
  const json& format = Member(json_cell, "format", "cell");
  if (format != kFormat) {
    throw std::runtime_error(
        fmt::format("cell truth JSON: format is {}, expected \"{}\"", format.dump(), kFormat));
  }
  if (const int version = Integer(json_cell, "version", "cell"); version != kVersion) {
    throw std::runtime_error(fmt::format(
        "cell truth JSON: version {} is not supported (expected {})", version, kVersion));
  }
  CellTruth cell;
  const json& dh = Member(json_cell, "robot_dh", "cell");
  cell.dh.a = Joints(dh, "a_m", "cell.robot_dh");
  cell.dh.d = Joints(dh, "d_m", "cell.robot_dh");
  cell.dh.alpha = Joints(dh, "alpha_rad", "cell.robot_dh");
  cell.dh.theta_offset = Joints(dh, "theta_offset_rad", "cell.robot_dh");
  cell.T_base_table = PoseFromJson(json_cell, "T_base_table");
  const json& turntable = Member(json_cell, "turntable", "cell");
  cell.turntable_axis_table = Vector(turntable, "axis_unit_table", "cell.turntable");
  cell.turntable_centre_table = Vector(turntable, "centre_table_m", "cell.turntable");
  cell.T_flange_cam = PoseFromJson(json_cell, "T_flange_cam");
  const json& intrinsics = Member(json_cell, "intrinsics", "cell");
  const std::string where = "cell.intrinsics";
  camera::Intrinsics& k = cell.intrinsics;
  k.width = Integer(intrinsics, "width_px", where);
  k.height = Integer(intrinsics, "height_px", where);
  k.fx = Number(Member(intrinsics, "fx_px", where), where + ".fx_px");
  k.fy = Number(Member(intrinsics, "fy_px", where), where + ".fy_px");
  k.cx = Number(Member(intrinsics, "cx_px", where), where + ".cx_px");
  k.cy = Number(Member(intrinsics, "cy_px", where), where + ".cy_px");
  const std::vector<double> distortion = Numbers(intrinsics, "distortion_k1_k2_p1_p2_k3", 5, where);
  std::copy(distortion.begin(), distortion.end(), k.distortion.begin());
  if (std::string error = cell.Validate(); !error.empty()) {
    throw std::runtime_error("cell truth JSON: " + error);
  }
  return cell;
}

void SaveCellTruth(const CellTruth& cell, const std::filesystem::path& path) {
  if (std::string error = cell.Validate(); !error.empty()) {
    throw std::runtime_error(
        fmt::format("SaveCellTruth {}: invalid cell: {}", path.string(), error));
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << CellTruthToJson(cell).dump(2) << "\n";
  out.close();
  if (!out) throw std::runtime_error(fmt::format("SaveCellTruth: cannot write {}", path.string()));
}

CellTruth LoadCellTruth(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("LoadCellTruth: cannot open {}", path.string()));
  json parsed;
  try {
    parsed = json::parse(in);
  } catch (const json::parse_error& error) {
    throw std::runtime_error(
        fmt::format("LoadCellTruth {}: not valid JSON: {}", path.string(), error.what()));
  }
  try {
    return CellTruthFromJson(parsed);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(fmt::format("LoadCellTruth {}: {}", path.string(), error.what()));
  }
}

}  // namespace avc::sim
