#pragma once

// The USB serial adapters an LT360 is plugged in through, as data for usb::UsbDeviceWatcher.

#include <vector>

#include "drivers/usb/usb_devices.h"

namespace avc::turntable {

// FTDI FT232R, Prolific PL2303, WCH CH340, Silicon Labs CP210x, FTDI FT2232/FT4232/FT231X.
const std::vector<usb::KnownUsbDevice>& DefaultKnownAdapters();

}  // namespace avc::turntable
