// avc collect: a service that stores every product of its cell in a directory.

#include <fmt/format.h>

#include <filesystem>
#include <iostream>

#include "core/bus/service_runtime.h"
#include "core/products/product_archive.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct CollectOptions {
  std::string output;
  std::string receiver_name = "archive";
  bus::BusFlags bus;
};

int RunCollect(const CollectOptions& options) {
  bus::ServiceRuntime runtime("avc-collect", options.bus);
  products::ProductArchive archive(runtime.bus(), options.output, options.receiver_name);
  auto report = [&] {
    runtime.heartbeat().Set(
        bus::ServiceState::kReady,
        fmt::format("{} products in {}", archive.stored(), archive.dir().string()));
  };
  report();
  runtime.loop().AddTimer(std::chrono::milliseconds(500), report, /*repeating=*/true);
  const int code = runtime.Run();
  std::cout << fmt::format("avc collect: stored {} products in {} ({} duplicates ignored)\n",
                           archive.stored(), archive.dir().string(),
                           archive.receiver_stats().duplicates);
  return code;
}

}  // namespace

void RegisterCollect(CLI::App& root, int* exit_code) {
  auto options = std::make_shared<CollectOptions>();
  CLI::App* command = root.add_subcommand(
      "collect",
      "Store every product (images, clouds, meshes, maps) published on the cell in a directory.\n"
      "Runs until SIGINT/SIGTERM. Each product is acknowledged once it is on disk, so producers\n"
      "that require this receiver never lose one. Files: images as PNG/JPEG/PGM/PPM, meshes and\n"
      "clouds as PLY, maps as .bt, anything else as .lcm; manifest.jsonl lists them.");
  command->add_option("--output,-o", options->output, "directory to store products in")->required();
  command
      ->add_option("--receiver", options->receiver_name,
                   "name in acknowledgements (producers may require it)")
      ->capture_default_str();
  AddBusFlags(command, &options->bus);
  SetGuardedRun(command, exit_code, [options] { return RunCollect(*options); });
}

}  // namespace avc::cli
