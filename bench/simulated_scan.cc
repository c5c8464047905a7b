#include "bench/simulated_scan.h"

#include <iostream>

#include "bench/mvs/isolated_run.h"
#include "sim/dataset/render_dataset.h"

namespace avc::bench {

std::optional<std::filesystem::path> EnsureSimulatedScan(const std::filesystem::path& work,
                                                         const std::string& preset) {
  const std::filesystem::path scan = work / preset;
  if (std::filesystem::exists(scan / "cameras.json")) return scan;
  std::cerr << "rendering " << preset << " (30 views, 1280x960)\n";
  const IsolatedResult rendered = RunIsolated([&] {
    sim::RenderDatasetOptions options;
    options.preset = sim::ParsePreset(preset);
    options.views = 30;
    options.rings = 3;
    options.noise = true;
    options.output = scan;
    sim::RenderDataset(options);
    return nlohmann::json::object();
  });
  if (!rendered.ok) {
    std::cerr << "  rendering the " << preset << " scan failed: " << rendered.error << "\n";
    return std::nullopt;
  }
  return scan;
}

}  // namespace avc::bench
