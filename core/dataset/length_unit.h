#pragma once

// The length unit of an imported dataset. Inside AVC every length is in metres; a dataset in
// millimetres (ROMI scans, PhenoArch) is converted once, at import. A dataset that does not
// declare its unit gets one chosen from how far its cameras are from the scene: a scanning
// cell's cameras are between 5 cm and 20 m from the plant, and those two ranges in metres and in
// millimetres do not overlap, so the distance tells the unit or that neither fits.

#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::dataset {

enum class LengthUnit { kAuto, kMetre, kMillimetre };

// "auto", "m", "mm".
std::string LengthUnitName(LengthUnit unit);
// Throws std::invalid_argument for anything but "auto", "m" or "mm".
LengthUnit ParseLengthUnit(const std::string& text);
// 1 for metres, 0.001 for millimetres; kAuto has none (throws std::invalid_argument).
double MetresPerUnit(LengthUnit unit);

// Camera-to-scene distances that a plant-scanning set-up can have, in metres.
inline constexpr double kMinCameraDistanceM = 0.05;
inline constexpr double kMaxCameraDistanceM = 20.0;

struct UnitDecision {
  LengthUnit unit = LengthUnit::kMetre;  // never kAuto
  double camera_distance = 0;            // median camera-to-scene distance, in the file's unit
  std::string how;  // one line for the user: where the unit came from and the evidence
};

// The unit of a dataset whose cameras are given in its file's unit. `requested` is the user's
// (kAuto: none), `declared` the dataset's own (kAuto: none; `declared_by` names the file that
// declares it). The user's choice wins over the dataset's, which wins over the automatic one.
// Throws std::runtime_error naming `dataset` when the chosen unit puts the cameras at an
// implausible distance, or when no unit is given and neither metres nor millimetres fit.
UnitDecision DecideLengthUnit(const std::vector<camera::Camera>& cameras, LengthUnit requested,
                              LengthUnit declared, const std::string& declared_by,
                              const std::string& dataset);

}  // namespace avc::dataset
