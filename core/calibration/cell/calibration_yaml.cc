#include "core/calibration/cell/calibration_yaml.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace avc::calibration {
namespace {

void EmitMatrix(YAML::Emitter& out, const char* key, const Eigen::Isometry3d& pose) {
  out << YAML::Key << key << YAML::Comment("row-major 4x4") << YAML::Value << YAML::Flow
      << YAML::BeginSeq;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) out << pose.matrix()(r, c);
  }
  out << YAML::EndSeq;
}

template <class Vector>
void EmitVector(YAML::Emitter& out, const char* key, const Vector& values) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (const auto value : values) out << value;
  out << YAML::EndSeq;
}

// Reading with the file and line of every problem.
class Reader {
 public:
  explicit Reader(std::string where) : where_(std::move(where)) {}

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& what) const {
    const int line = node.Mark().line;
    throw std::runtime_error(line >= 0 ? fmt::format("{}:{}: {}", where_, line + 1, what)
                                       : fmt::format("{}: {}", where_, what));
  }

  YAML::Node Child(const YAML::Node& parent, const char* key) const {
    const YAML::Node child = parent[key];
    if (!child) Fail(parent, fmt::format("missing '{}'", key));
    return child;
  }

  double Number(const YAML::Node& parent, const char* key) const {
    const YAML::Node node = Child(parent, key);
    try {
      return node.as<double>();
    } catch (const YAML::Exception&) {
      Fail(node, fmt::format("'{}' is not a number", key));
    }
  }

  // A whole number that fits an int (a cast of 1e20 or NaN to int is undefined behaviour).
  int Integer(const YAML::Node& parent, const char* key) const {
    const double value = Number(parent, key);
    if (!(value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max()) ||
        value != std::floor(value)) {
      Fail(Child(parent, key), fmt::format("'{}' must be a whole number, not {}", key, value));
    }
    return static_cast<int>(value);
  }

  std::vector<double> Numbers(const YAML::Node& parent, const char* key, size_t count) const {
    const YAML::Node node = Child(parent, key);
    if (!node.IsSequence() || node.size() != count) {
      Fail(node, fmt::format("'{}' must be a list of {} numbers", key, count));
    }
    std::vector<double> values;
    for (const YAML::Node& item : node) {
      try {
        values.push_back(item.as<double>());
      } catch (const YAML::Exception&) {
        Fail(item, fmt::format("'{}' holds something that is not a number", key));
      }
    }
    return values;
  }

  Eigen::Isometry3d Pose(const YAML::Node& parent, const char* key) const {
    const std::vector<double> m = Numbers(parent, key, 16);
    Eigen::Isometry3d pose;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) pose.matrix()(r, c) = m[static_cast<size_t>(4 * r + c)];
    }
    return pose;
  }

  kinematics::JointVector Joints(const YAML::Node& parent, const char* key) const {
    const std::vector<double> v = Numbers(parent, key, 6);
    return Eigen::Map<const kinematics::JointVector>(v.data());
  }

 private:
  std::string where_;
};

}  // namespace

std::string CalibrationToYaml(const CellCalibration& calibration) {
  if (const std::string problem = calibration.Validate(); !problem.empty()) {
    throw std::invalid_argument("calibration: " + problem);
  }
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::Comment(
      "AVC cell calibration: T_cam_world(q, angle) = inverse(T_flange_cam) * "
      "inverse(T_base_flange(q)) * T_base_table * Rz(angle)");
  out << YAML::BeginMap;
  out << YAML::Key << "format_version" << YAML::Value << CellCalibration::kFormatVersion;
  out << YAML::Key << "note" << YAML::Value << calibration.note;
  const camera::Intrinsics& k = calibration.intrinsics;
  out << YAML::Key << "camera" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "width" << YAML::Value << k.width;
  out << YAML::Key << "height" << YAML::Value << k.height;
  out << YAML::Key << "fx" << YAML::Value << k.fx << YAML::Key << "fy" << YAML::Value << k.fy;
  out << YAML::Key << "cx" << YAML::Value << k.cx << YAML::Key << "cy" << YAML::Value << k.cy;
  EmitVector(out, "distortion", k.distortion);
  out << YAML::EndMap;
  EmitMatrix(out, "T_flange_cam", calibration.T_flange_cam);
  out << YAML::Key << "turntable_calibrated" << YAML::Value << calibration.turntable_calibrated;
  if (!calibration.turntable_calibrated) {
    out << YAML::Comment("no turntable shots: T_base_table is the board in the base frame");
  }
  EmitMatrix(out, "T_base_table", calibration.T_base_table);
  EmitMatrix(out, "T_table_board", calibration.T_table_board);
  out << YAML::Key << "kinematics" << YAML::Value << YAML::BeginMap;
  EmitVector(out, "a", calibration.dh.a);
  EmitVector(out, "d", calibration.dh.d);
  EmitVector(out, "alpha", calibration.dh.alpha);
  EmitVector(out, "theta_offset", calibration.dh.theta_offset);
  out << YAML::EndMap;
  const CalibrationResiduals& r = calibration.residuals;
  out << YAML::Key << "residuals" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "intrinsics_rms_px" << YAML::Value << r.intrinsics_rms_px;
  out << YAML::Key << "hand_eye_rms_px" << YAML::Value << r.hand_eye_rms_px;
  out << YAML::Key << "hand_eye_rotation_deg" << YAML::Value << r.hand_eye_rotation_deg;
  out << YAML::Key << "hand_eye_translation_mm" << YAML::Value << r.hand_eye_translation_mm;
  out << YAML::Key << "turntable_centre_rms_mm" << YAML::Value << r.turntable_centre_rms_mm;
  out << YAML::Key << "turntable_angles" << YAML::Value << r.turntable_angles;
  if (!r.hand_eye_method.empty()) {
    out << YAML::Key << "hand_eye_method" << YAML::Value << r.hand_eye_method;
    out << YAML::Key << "hand_eye_loo_rotation_deg" << YAML::Value << r.hand_eye_loo_rotation_deg;
    out << YAML::Key << "hand_eye_loo_translation_mm" << YAML::Value
        << r.hand_eye_loo_translation_mm;
    out << YAML::Key << "alternative" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "method" << YAML::Value << r.alternative_method;
    out << YAML::Key << "rms_px" << YAML::Value << r.alternative_rms_px;
    out << YAML::Key << "loo_rotation_deg" << YAML::Value << r.alternative_loo_rotation_deg;
    out << YAML::Key << "loo_translation_mm" << YAML::Value << r.alternative_loo_translation_mm;
    out << YAML::EndMap;
  }
  out << YAML::Key << "views" << YAML::Value << YAML::BeginSeq;
  for (size_t i = 0; i < r.view_names.size(); ++i) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << r.view_names[i]
        << YAML::Key << "rms_px" << YAML::Value
        << (i < r.view_rms_px.size() ? r.view_rms_px[i] : 0.0) << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "rejected" << YAML::Value << YAML::BeginSeq;
  for (const std::string& why : r.rejected) out << why;
  out << YAML::EndSeq;
  out << YAML::EndMap;
  out << YAML::EndMap;
  if (!out.good()) throw std::runtime_error("calibration: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

CellCalibration CalibrationFromYaml(const std::string& text, const std::string& where) {
  YAML::Node doc;
  try {
    doc = YAML::Load(text);
  } catch (const YAML::ParserException& error) {
    throw std::runtime_error(
        fmt::format("{}:{}: not valid YAML: {}", where, error.mark.line + 1, error.msg));
  }
  const Reader read(where);
  if (!doc.IsMap()) read.Fail(doc, "not a calibration (expected a mapping)");
  const double version = read.Number(doc, "format_version");
  if (version != CellCalibration::kFormatVersion) {
    read.Fail(doc["format_version"],
              fmt::format("format_version {} is not supported (this AVC reads {})", version,
                          CellCalibration::kFormatVersion));
  }
  CellCalibration calibration;
  if (doc["note"]) calibration.note = doc["note"].as<std::string>("");
  const YAML::Node camera = read.Child(doc, "camera");
  camera::Intrinsics& k = calibration.intrinsics;
  k.width = read.Integer(camera, "width");
  k.height = read.Integer(camera, "height");
  k.fx = read.Number(camera, "fx");
  k.fy = read.Number(camera, "fy");
  k.cx = read.Number(camera, "cx");
  k.cy = read.Number(camera, "cy");
  const std::vector<double> distortion = read.Numbers(camera, "distortion", 5);
  std::copy(distortion.begin(), distortion.end(), k.distortion.begin());
  calibration.T_flange_cam = read.Pose(doc, "T_flange_cam");
  // Absent in files from before partial calibrations, which always had the turntable.
  if (const YAML::Node turntable = doc["turntable_calibrated"]) {
    if (!YAML::convert<bool>::decode(turntable, calibration.turntable_calibrated)) {
      read.Fail(turntable, "turntable_calibrated must be true or false");
    }
  }
  calibration.T_base_table = read.Pose(doc, "T_base_table");
  calibration.T_table_board = read.Pose(doc, "T_table_board");
  const YAML::Node kinematics = read.Child(doc, "kinematics");
  calibration.dh.a = read.Joints(kinematics, "a");
  calibration.dh.d = read.Joints(kinematics, "d");
  calibration.dh.alpha = read.Joints(kinematics, "alpha");
  calibration.dh.theta_offset = read.Joints(kinematics, "theta_offset");
  if (const YAML::Node residuals = doc["residuals"]) {
    CalibrationResiduals& r = calibration.residuals;
    r.intrinsics_rms_px = read.Number(residuals, "intrinsics_rms_px");
    r.hand_eye_rms_px = read.Number(residuals, "hand_eye_rms_px");
    r.hand_eye_rotation_deg = read.Number(residuals, "hand_eye_rotation_deg");
    r.hand_eye_translation_mm = read.Number(residuals, "hand_eye_translation_mm");
    r.turntable_centre_rms_mm = read.Number(residuals, "turntable_centre_rms_mm");
    r.turntable_angles = read.Integer(residuals, "turntable_angles");
    if (const YAML::Node method = residuals["hand_eye_method"]) {  // absent in older files
      r.hand_eye_method = method.as<std::string>("");
      r.hand_eye_loo_rotation_deg = read.Number(residuals, "hand_eye_loo_rotation_deg");
      r.hand_eye_loo_translation_mm = read.Number(residuals, "hand_eye_loo_translation_mm");
      const YAML::Node alternative = read.Child(residuals, "alternative");
      r.alternative_method = read.Child(alternative, "method").as<std::string>("");
      r.alternative_rms_px = read.Number(alternative, "rms_px");
      r.alternative_loo_rotation_deg = read.Number(alternative, "loo_rotation_deg");
      r.alternative_loo_translation_mm = read.Number(alternative, "loo_translation_mm");
    }
    for (const YAML::Node& view : read.Child(residuals, "views")) {
      r.view_names.push_back(read.Child(view, "name").as<std::string>());
      r.view_rms_px.push_back(read.Number(view, "rms_px"));
    }
    for (const YAML::Node& why : read.Child(residuals, "rejected")) {
      r.rejected.push_back(why.as<std::string>());
    }
  }
  if (const std::string problem = calibration.Validate(); !problem.empty()) {
    read.Fail(doc, problem);
  }
  return calibration;
}

void SaveCalibration(const CellCalibration& calibration, const std::filesystem::path& path) {
  const std::string text = CalibrationToYaml(calibration);
  std::ofstream out(path, std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

CellCalibration LoadCalibration(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::stringstream text;
  text << in.rdbuf();
  return CalibrationFromYaml(text.str(), path.string());
}

}  // namespace avc::calibration
