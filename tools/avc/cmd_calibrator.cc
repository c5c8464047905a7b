// avc calibrator: the avc-calibrator service. Serves a calibration.yaml on the bus: the
// calibration itself, the camera of every captured image, and camera-pose queries.

#include <memory>

#include "core/bus/service_runtime.h"
#include "core/calibration/cell/calibration_yaml.h"
#include "services/calibrator/calibrator_node.h"
#include "services/calibrator/calibrator_options.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct CalibratorArgs {
  std::string calibration;
  ConfigFlags config;
  bus::BusFlags bus;
};

int RunCalibrator(const CalibratorArgs& args) {
  const auto& table = calibrator::CalibratorOptionTable();
  calibrator::CalibratorNodeOptions options = LoadOptions(table, args.config);
  calibration::CellCalibration calibration = calibration::LoadCalibration(args.calibration);
  options.source = args.calibration;
  bus::ServiceRuntime runtime(options.service, args.bus);
  runtime.PublishConfig(table.ToToml(options));
  calibrator::CalibratorNode node(runtime.bus(), runtime.loop(), runtime.heartbeat(),
                                  std::move(calibration), options);
  return runtime.Run();
}

}  // namespace

void RegisterCalibrator(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<CalibratorArgs>();
  CLI::App* command = root.add_subcommand(
      "calibrator",
      "Run the avc-calibrator service with a calibration (from `avc calibrate`).\n"
      "Publishes it on CALIBRATION, the camera of every captured image on CAMERA (from the\n"
      "arm's flange pose and the table angle when the capture was requested), and answers\n"
      "CAMERA_QUERY for any joint vector or flange pose and table angle.");
  command->add_option("calibration", args->calibration, "calibration.yaml")
      ->required()
      ->check(CLI::ExistingFile);
  AddShorthand(command, &args->config, "--camera-id", "camera_id", "camera id stamped on cameras");
  AddConfigFlags(command, &args->config, calibrator::CalibratorOptionTable().Reference({}));
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunCalibrator(*args); });
}

}  // namespace avc::cli
