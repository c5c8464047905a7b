#pragma once

// The short scan the multi-process scan tests run (the strap plant, 8000 triangles, 1280x960
// PNG, the nominal cell, a 20x clock: about 20 s): the same options give the same images and
// mesh, byte for byte, so each test compares its disturbed scans with an undisturbed one.

#include <filesystem>
#include <string>

#include "bench/chaos/chaos_scan.h"
#include "core/bus/bus_options.h"

namespace avc::testing {

inline constexpr int kShortScanWidth = 1280, kShortScanHeight = 960;

// The scan called `name` on `bus`, its cell and scan directory under dir/name, planned with the
// calibration at dir/calibration.yaml (bench::WriteNominalCalibration).
bench::ChaosScanOptions ShortScan(const std::filesystem::path& dir, const std::string& name,
                                  const bus::BusOptions& bus);

}  // namespace avc::testing
