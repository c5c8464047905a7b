#include "sim/emulators/cell/simulated_cell.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <system_error>

#include "core/camera/camera_io.h"

namespace avc::sim {
namespace fs = std::filesystem;

std::string SimulatedCellOptions::Validate() const {
  if (const std::string problem = cell.Validate(); !problem.empty()) return "cell: " + problem;
  if (scene.mesh.faces.empty()) return "the scene has no triangles";
  if (!(time_scale > 0 && time_scale <= 1000)) {
    return fmt::format("time scale {} is outside (0, 1000]", time_scale);
  }
  if (jpeg_quality < 1 || jpeg_quality > 100) {
    return fmt::format("JPEG quality {} is outside 1..100", jpeg_quality);
  }
  return ValidateRenderOptions(render);
}

SimulatedCell::SimulatedCell(SimulatedCellOptions options) : options_(std::move(options)) {
  if (const std::string problem = options_.Validate(); !problem.empty()) {
    throw std::invalid_argument("simulated cell: " + problem);
  }
  clock_ = std::make_shared<ScaledEmulatorClock>(options_.time_scale);
  options_.arm.cell = options_.cell;
  arm_ = std::make_unique<ur5::Ur5Emulator>(options_.arm, clock_);
  table_ = std::make_unique<Lt360Emulator>(options_.table, clock_);
  if (!options_.link_dir.empty()) {
    fs::create_directories(options_.link_dir);
    table_link_ = options_.link_dir / "lt360";
    std::error_code ignored;
    fs::remove(table_link_, ignored);
    fs::create_symlink(table_->device_path(), table_link_);
    const fs::path truth_path = options_.link_dir / "truth.jsonl";
    // Appended to, so a simulator restarted during a scan keeps the frames it rendered before.
    truth_log_.open(truth_path, std::ios::app);
    if (!truth_log_) throw std::runtime_error("cannot write " + truth_path.string());
  }
  PtpIpCameraOptions camera_options = options_.camera;
  camera_options.frame_source = [this](const EmulatedSettings&) { return RenderFrame(); };
  camera_ = std::make_unique<PtpIpCamera>(std::move(camera_options), clock_);
}

SimulatedCell::~SimulatedCell() {
  camera_.reset();  // no frame is rendered while the rest goes away
  if (!table_link_.empty()) {
    std::error_code ignored;
    fs::remove(table_link_, ignored);
  }
}

std::string SimulatedCell::turntable_device() const {
  return table_link_.empty() ? table_->device_path() : table_link_.string();
}

std::string SimulatedCell::camera_port() const {
  return fmt::format("ptpip:127.0.0.1:{}", camera_->port());
}

std::string SimulatedCell::Describe() const {
  return fmt::format(
      "UR5 emulator: RTDE {} primary {} secondary {} dashboard {}\n"
      "LT360 emulator: {}{}\n"
      "camera (PTP/IP, model \"PTP/IP Camera\"): {}\n"
      "clock: {}x real time",
      arm_->rtde_port(), arm_->primary_port(), arm_->secondary_port(), arm_->dashboard_port(),
      turntable_device(), table_link_.empty() ? std::string() : " -> " + table_->device_path(),
      camera_port(), options_.time_scale);
}

camera::Camera SimulatedCell::TrueCameraNow() {
  const kinematics::JointVector q = arm_->Snapshot().true_q;
  const double angle = table_->TrueAngleDeg() * std::numbers::pi / 180;
  return CameraAt(options_.cell, q, angle);
}

int64_t SimulatedCell::frames_rendered() const {
  std::lock_guard lock(render_mutex_);
  return frames_rendered_;
}

EmulatedFrame SimulatedCell::RenderFrame() {
  std::lock_guard lock(render_mutex_);
  const camera::Camera camera = TrueCameraNow();
  RenderResult result;
  renderer_.Render(options_.scene, camera, options_.render, &result);
  const int64_t index = ++frames_rendered_;
  if (options_.noise) {
    ApplyImageNoise(result.color, ImageNoise{}, options_.noise_seed + static_cast<uint64_t>(index));
  }
  EmulatedFrame frame;
  frame.width = static_cast<uint32_t>(result.color.cols);
  frame.height = static_cast<uint32_t>(result.color.rows);
  frame.file_name = fmt::format("IMG_{:04d}.{}", index % 10000, options_.png ? "PNG" : "JPG");
  frame.object_format = options_.png ? ptp::kFormatPng : ptp::kFormatExifJpeg;
  const bool encoded =
      options_.png
          ? cv::imencode(".png", result.color, frame.data, {cv::IMWRITE_PNG_COMPRESSION, 1})
          : cv::imencode(".jpg", result.color, frame.data,
                         {cv::IMWRITE_JPEG_QUALITY, options_.jpeg_quality});
  if (!encoded) throw std::runtime_error("simulated camera: could not encode the frame");
  if (truth_log_.is_open()) {
    nlohmann::ordered_json line;
    line["frame"] = index;
    line["file_name"] = frame.file_name;
    line["time_s"] = clock_->NowSeconds();
    line["camera"] = camera::CameraToJson({frame.file_name, camera});
    truth_log_ << line.dump() << "\n" << std::flush;
  }
  return frame;
}

std::vector<camera::NamedCamera> ReadTruthLog(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::vector<camera::NamedCamera> frames;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const nlohmann::json entry = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    try {
      if (entry.is_discarded() || !entry.contains("camera")) {
        throw std::runtime_error("not a frame record");
      }
      frames.push_back(camera::CameraFromJson(entry["camera"], entry.value("file_name", "")));
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(fmt::format("{}:{}: {}", path.string(), line_number, error.what()));
    }
  }
  return frames;
}

}  // namespace avc::sim
