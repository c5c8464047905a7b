#include "tests/bench/short_scan.h"

#include "bench/devices/cell_processes.h"
#include "tests/support/test_support.h"

namespace avc::testing {

bench::ChaosScanOptions ShortScan(const std::filesystem::path& dir, const std::string& name,
                                  const bus::BusOptions& bus) {
  bench::ChaosScanOptions options;
  options.label = name;
  options.cell = bench::CellOptionsOnBus(bus, Executable("avc"), dir / name / "cell");
  options.cell.time_scale = 20;
  options.cell.plant = "strap";
  options.cell.triangles = 8000;
  options.cell.width = kShortScanWidth;
  options.cell.height = kShortScanHeight;
  options.cell.png = true;
  options.cell.extra_sim_args = {"--nominal-cell"};
  options.scan_dir = dir / name / "plant";
  options.calibration = dir / "calibration.yaml";
  options.timeout_s = 240;
  return options;
}

}  // namespace avc::testing
