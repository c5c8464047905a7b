#pragma once

// What the PTP/IP camera emulator exposes of a shot: the exposure settings a client chose and the
// encoded image the simulated cell hands back for them.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim/emulators/ptpip/ptp_codes.h"

namespace avc::sim {

// Current exposure settings (PTP ExposureIndex, ExposureTime, FNumber).
struct EmulatedSettings {
  uint32_t iso = 0;
  double shutter_s = 0;
  double f_number = 0;
};

// One encoded image as the camera would store it.
struct EmulatedFrame {
  std::vector<uint8_t> data;
  uint16_t object_format = ptp::kFormatExifJpeg;  // kFormatExifJpeg or kFormatPng
  std::string file_name;                          // e.g. "IMG_0001.JPG"
  uint32_t width = 0;                             // 0 = not told (allowed by PTP)
  uint32_t height = 0;
};

// Called at each accepted InitiateCapture, on the emulator thread.
using FrameSource = std::function<EmulatedFrame(const EmulatedSettings&)>;

}  // namespace avc::sim
