#pragma once

// `avc turntable list` and `avc camera list`: print the known USB devices plugged in now, then
// optionally report arrivals and departures for a while.

#include <string>
#include <vector>

#include "drivers/usb/usb_devices.h"

namespace avc::cli {

// what: plural noun for messages, e.g. "USB serial adapters". Returns the exit code.
int ListUsbDevices(const std::vector<usb::KnownUsbDevice>& known, const std::string& what,
                   double watch_s);

}  // namespace avc::cli
