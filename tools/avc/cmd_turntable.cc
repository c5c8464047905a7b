// avc turntable: the avc-turntable service for the LinearX LT360 (real device or an in-process
// pty emulator), and `avc turntable list` to find USB serial adapters.

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <thread>

#include "core/bus/service_runtime.h"
#include "core/util/log.h"
#include "drivers/turntable/turntable_node.h"
#include "drivers/turntable/turntable_options.h"
#include "drivers/turntable/usb_serial_adapters.h"
#include "sim/emulators/lt360/lt360_emulator.h"
#include "tools/avc/auth_flags.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/usb_listing.h"

namespace avc::cli {
namespace {

struct TurntableArgs {
  std::string command_table;
  ConfigFlags config;
  bool emulate = false;
  double emulate_speed_deg_s = 90;
  double emulate_sigma_deg = 0.05;
  double emulate_accel_deg_s2 = 180;
  uint64_t emulate_seed = 1;
  AuthFlags auth;
  bus::BusFlags bus;
};

struct ListArgs {
  double watch_s = 0;
};

int RunTurntable(const TurntableArgs& args) {
  turntable::TurntableNodeOptions defaults;
  // Emulated, the driver would otherwise slow the emulator down to its own default.
  if (args.emulate) defaults.controller.default_speed_deg_s = args.emulate_speed_deg_s;
  const auto& table = turntable::TurntableOptionTable();
  turntable::TurntableNodeOptions options = LoadOptions(table, args.config, defaults);
  if (args.emulate == !options.device.empty()) {
    throw std::invalid_argument("give exactly one of --device PATH (device) or --emulate");
  }
  if (!args.command_table.empty()) {
    options.device_options.table = turntable::LoadCommandTable(args.command_table);
  }

  std::unique_ptr<sim::Lt360Emulator> emulator;
  if (args.emulate) {
    sim::Lt360EmulatorOptions emulator_options;
    emulator_options.table = options.device_options.table;
    emulator_options.speed_deg_s = args.emulate_speed_deg_s;
    emulator_options.sigma_deg = args.emulate_sigma_deg;
    emulator_options.accel_deg_s2 = args.emulate_accel_deg_s2;
    emulator_options.seed = args.emulate_seed;
    emulator = std::make_unique<sim::Lt360Emulator>(emulator_options);
    options.device = emulator->device_path();
    log::Info("LT360 emulator on {} ({} deg/s)", options.device, args.emulate_speed_deg_s);
  }

  bus::ServiceRuntime runtime(options.service, args.bus);
  runtime.PublishConfig(table.ToToml(options));
  options.auth = DriverAuth(args.auth, runtime.bus().cell());
  turntable::TurntableNode node(runtime.bus(), runtime.loop(), runtime.heartbeat(), options);
  runtime.OnStop([&] { node.Shutdown(); });
  return runtime.Run();
}

int RunList(const ListArgs& args) {
  return ListUsbDevices(turntable::DefaultKnownAdapters(), "USB serial adapters", args.watch_s);
}

}  // namespace

void RegisterTurntable(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<TurntableArgs>();
  CLI::App* command = root.add_subcommand(
      "turntable",
      "Run avc-turntable, the LinearX LT360 turntable service, on a serial device or emulated.\n"
      "Takes TURNTABLE_COMMAND, answers on ACK and publishes TURNTABLE_STATE (~10 Hz) until\n"
      "SIGINT/SIGTERM; a moving table is stopped first. --emulate starts an LT360 emulator on a\n"
      "pseudo-terminal inside the process and drives it through the real serial backend.\n"
      "Every command but STOP must be signed with the cell's key (avc key).\n"
      "Angles grow counter-clockwise seen from above.");
  ConfigFlags* config = &args->config;
  AddShorthand(command, config, "--device,-d", "device", "serial device, e.g. /dev/ttyUSB0");
  AddShorthand(command, config, "--baud", "baud", "baud rate (8N1)");
  command->add_option("--command-table", args->command_table,
                      "JSON file with the LT360 command strings (default: built-in table)");
  AddShorthand(command, config, "--command-timeout-ms", "device_options.command_timeout",
               "reply timeout");
  AddShorthand(command, config, "--speed", "controller.default_speed_deg_s",
               "default speed in deg/s (with --emulate: the emulated speed)");
  AddShorthand(command, config, "--poll-ms", "poll_period", "state poll period");
  command->add_flag("--emulate", args->emulate, "use an in-process LT360 emulator on a pty");
  command->add_option("--emulate-speed", args->emulate_speed_deg_s, "emulated speed in deg/s")
      ->capture_default_str();
  command
      ->add_option("--emulate-accel", args->emulate_accel_deg_s2,
                   "emulated acceleration in deg/s^2 (0 = full speed at once)")
      ->capture_default_str();
  command
      ->add_option("--emulate-sigma", args->emulate_sigma_deg,
                   "emulated true-angle error per move (deg, 1 sigma)")
      ->capture_default_str();
  command->add_option("--emulate-seed", args->emulate_seed, "seed of the emulated angle error")
      ->capture_default_str();
  AddConfigFlags(command, config, turntable::TurntableOptionTable().Reference({}));
  AddDriverAuthFlags(command, &args->auth);
  AddBusFlags(command, &args->bus);

  auto list_args = std::make_shared<ListArgs>();
  CLI::App* list = command->add_subcommand(
      "list", "List USB serial adapters (FTDI, Prolific, CH340, CP210x) found with libusb.");
  list->add_option("--watch", list_args->watch_s,
                   "then report arrivals and departures for this many seconds");
  SetGuardedRun(list, exit_code, [list_args] { return RunList(*list_args); });
  SetGuardedRun(command, exit_code, [args] { return RunTurntable(*args); });
}

}  // namespace avc::cli
