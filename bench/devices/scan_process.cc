#include "bench/devices/scan_process.h"

#include "core/calibration/cell/calibration_yaml.h"
#include "orchestrator/scan_record.h"
#include "sim/dataset/render_dataset.h"

namespace avc::bench {
namespace fs = std::filesystem;

launch::ChildProcess StartScanProcess(const std::vector<std::string>& args,
                                      const ScanProcessOptions& options) {
  launch::SpawnSpec spec;
  spec.argv = options.prefix;
  spec.argv.insert(spec.argv.end(), {options.avc_binary.string(), "scan"});
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.argv.insert(spec.argv.end(), {"--lcm-url", options.bus.control_url, "--bulk-url",
                                     options.bus.bulk_url, "--cell", options.bus.cell});
  spec.argv.insert(spec.argv.end(), options.planner_args.begin(), options.planner_args.end());
  spec.argv.insert(spec.argv.end(), options.envelope_args.begin(), options.envelope_args.end());
  spec.argv.insert(spec.argv.end(), {"--key", options.key_file.string()});
  spec.log_file = options.log.string();
  return launch::ChildProcess::Spawn(spec);
}

void WriteNominalCalibration(const fs::path& path, int width, int height) {
  sim::RenderDatasetOptions options;
  options.width = width;
  options.height = height;
  const sim::CellTruth cell = sim::MakeCell(options);
  calibration::CellCalibration calibration;
  calibration.intrinsics = cell.intrinsics;
  calibration.T_flange_cam = cell.T_flange_cam;
  calibration.T_base_table = cell.T_base_table;
  calibration.dh = cell.dh;
  calibration.note = "nominal simulated cell";
  calibration::SaveCalibration(calibration, path);
}

size_t RecordedCaptures(const fs::path& scan_dir) {
  try {
    return orchestrator::LoadScanRecord(scan_dir).captures.size();
  } catch (const std::exception&) {
    return 0;  // not written yet
  }
}

bool WaitForCaptures(const fs::path& scan_dir, size_t count, launch::ChildProcess& scan,
                     std::chrono::milliseconds timeout) {
  constexpr std::chrono::milliseconds kPoll(100);
  for (auto waited = std::chrono::milliseconds(0); waited < timeout; waited += kPoll) {
    if (RecordedCaptures(scan_dir) >= count) return true;
    if (scan.WaitFor(kPoll).has_value()) return false;  // it ended first
  }
  return false;
}

bool WaitForScanState(const fs::path& scan_dir, const std::string& state,
                      launch::ChildProcess& scan, std::chrono::milliseconds timeout) {
  constexpr std::chrono::milliseconds kPoll(50);
  for (auto waited = std::chrono::milliseconds(0); waited < timeout; waited += kPoll) {
    try {
      if (orchestrator::StateName(orchestrator::LoadScanRecord(scan_dir).state) == state) {
        return true;
      }
    } catch (const std::exception&) {
      // not written yet
    }
    if (scan.WaitFor(kPoll).has_value()) return false;  // it ended first
  }
  return false;
}

}  // namespace avc::bench
