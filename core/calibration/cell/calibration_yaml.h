#pragma once

// calibration.yaml: one CellCalibration on disk, versioned (format_version), human-readable,
// doubles written with round-trip precision so save -> load -> save gives the same bytes.
// The reader names the file, the line and the field of any problem and refuses unknown format
// versions.

#include <filesystem>
#include <string>

#include "core/calibration/cell/cell_calibration.h"

namespace avc::calibration {

std::string CalibrationToYaml(const CellCalibration& calibration);
CellCalibration CalibrationFromYaml(const std::string& text, const std::string& where);

// Throw std::runtime_error naming the path.
void SaveCalibration(const CellCalibration& calibration, const std::filesystem::path& path);
CellCalibration LoadCalibration(const std::filesystem::path& path);

}  // namespace avc::calibration
