#include "tools/avc/demo_cell.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <csignal>
#include <deque>
#include <fstream>
#include <stdexcept>

#include "core/geometry/mesh_io.h"
#include "sim/scene/chessboard_scene.h"

namespace avc::cli {
namespace {

namespace fs = std::filesystem;

std::string Quoted(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

std::string Array(const std::vector<std::string>& items) {
  std::vector<std::string> quoted;
  for (const std::string& item : items) quoted.push_back(Quoted(item));
  return fmt::format("[{}]", fmt::join(quoted, ", "));
}

}  // namespace

std::string DemoLaunchFile(const DemoCellOptions& options, const fs::path& key_file) {
  const std::string avc = options.avc_binary.string();
  const std::string link_dir = (options.work_dir / "sim").string();
  std::vector<std::string> sim_args = {"sim", "cell", "--link-dir", link_dir};
  sim_args.insert(sim_args.end(), options.sim_args.begin(), options.sim_args.end());
  std::string text = fmt::format(
      "# Written by avc demo: the simulated cell, the three drivers, the planner and the three "
      "reconstruction stages{}.\n"
      "log_dir = {}\n\n",
      options.record_to.empty() ? "" : " and a recorder",
      Quoted((options.work_dir / "logs").string()));
  const auto process = [&](const std::string& name, const std::vector<std::string>& args) {
    text += fmt::format("[[process]]\nname = {}\ncommand = {}\nargs = {}\nstop_timeout = 5.0\n\n",
                        Quoted(name), Quoted(avc), Array(args));
  };
  process("sim", sim_args);
  std::vector<std::string> robot_args = {"robot", "--host", "127.0.0.1", "--key",
                                         key_file.string()};
  robot_args.insert(robot_args.end(), options.robot_args.begin(), options.robot_args.end());
  process("robot", robot_args);
  process("turntable", {"turntable", "--device", link_dir + "/lt360", "--key", key_file.string()});
  process("camera", {"camera", "--port", "ptpip:127.0.0.1:15740", "--no-usb-watch"});
  // The planner and the reconstruction stages, each its own process: the scan sends them jobs
  // over the bus.
  process("planner", {"planner"});
  process("builder", {"builder"});
  process("clusterer", {"clusterer"});
  process("surfacer", {"surfacer"});
  if (!options.record_to.empty())
    process("recorder", {"record", "--output", options.record_to.string()});
  return text;
}

DemoCell::DemoCell(const DemoCellOptions& options)
    : log_(options.work_dir / "up.log"),
      key_(auth::LoadOrGenerateCommandKey(fs::absolute(options.work_dir / "cell.key"))) {
  fs::create_directories(options.work_dir / "logs");
  const fs::path launch_file = options.work_dir / "launch.toml";
  std::ofstream(launch_file) << DemoLaunchFile(options, key_.file);
  launch::SpawnSpec spec;
  spec.argv = {options.avc_binary.string(), "up", launch_file.string()};
  spec.log_file = log_.string();
  spec.env["AVC_LCM_URL"] = options.bus.control_url;
  spec.env["AVC_BULK_URL"] = options.bus.bulk_url;
  spec.env["AVC_CELL"] = options.bus.cell;
  up_.emplace(launch::ChildProcess::Spawn(spec));
}

DemoCell::~DemoCell() {
  if (!up_) return;
  up_->Signal(SIGTERM);
  // avc up stops its children within their stop timeouts; ~ChildProcess kills what is left.
  up_->WaitFor(std::chrono::milliseconds(20000));
}

std::string DemoCell::LogTail(int lines) const {
  std::ifstream in(log_);
  std::deque<std::string> tail;
  for (std::string line; std::getline(in, line);) {
    tail.push_back(line);
    if (static_cast<int>(tail.size()) > lines) tail.pop_front();
  }
  return fmt::format("{}", fmt::join(tail, "\n"));
}

void WriteGroundTruthMesh(const sim::RenderDatasetOptions& scene,
                          const calibration::CellCalibration& calibration,
                          const std::filesystem::path& path) {
  geometry::Mesh mesh = sim::MakeScene(scene).mesh;
  const Eigen::Isometry3d T_calworld_simworld =
      calibration.T_table_board * sim::ChessboardSpec{}.T_world_board.inverse();
  const Eigen::Isometry3f transform = T_calworld_simworld.cast<float>();
  for (Eigen::Vector3f& vertex : mesh.vertices) vertex = transform * vertex;
  mesh.uvs.clear();
  mesh.face_materials.clear();
  geometry::WriteMeshPly(path, mesh);
}

}  // namespace avc::cli
