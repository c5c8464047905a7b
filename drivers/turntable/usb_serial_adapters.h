#pragma once

// USB serial adapters on the USB bus via libusb: a list of what is plugged in now, and a watcher
// that reports arrivals and departures (libusb hot-plug callbacks where the platform has them,
// otherwise polling the device list). Which VID:PIDs count as serial adapters is data.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

struct libusb_context;

namespace avc::turntable {

struct KnownAdapter {
  uint16_t vendor_id;
  uint16_t product_id;
  std::string name;
};

// FTDI FT232R, Prolific PL2303, WCH CH340, Silicon Labs CP210x, FTDI FT2232/FT4232/FT231X.
const std::vector<KnownAdapter>& DefaultKnownAdapters();

struct UsbSerialDevice {
  uint16_t vendor_id = 0;
  uint16_t product_id = 0;
  int bus = 0;
  int address = 0;
  std::string name;  // from the known-adapter table

  std::string Describe() const;  // "0403:6001 FTDI FT232R (bus 1 address 4)"
  bool operator==(const UsbSerialDevice& other) const = default;
};

// Thrown when libusb cannot start (e.g. no USB bus in a container).
class UsbError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class UsbSerialAdapters {
 public:
  enum class Event { kArrived, kLeft };
  using Callback = std::function<void(Event, const UsbSerialDevice&)>;

  explicit UsbSerialAdapters(std::vector<KnownAdapter> known = DefaultKnownAdapters());
  ~UsbSerialAdapters();
  UsbSerialAdapters(const UsbSerialAdapters&) = delete;
  UsbSerialAdapters& operator=(const UsbSerialAdapters&) = delete;

  // The known adapters plugged in now, in bus/address order.
  std::vector<UsbSerialDevice> List();

  // Reports arrivals and departures of known adapters on a background thread until
  // StopWatching() or destruction. Returns true when libusb hot-plug is used, false when
  // polling every poll_period_ms.
  bool Watch(Callback callback, int poll_period_ms = 1000);
  void StopWatching();

 private:
  const KnownAdapter* Find(uint16_t vendor_id, uint16_t product_id) const;
  void Notify(Event event, const UsbSerialDevice& device);

  std::vector<KnownAdapter> known_;
  libusb_context* context_ = nullptr;
  Callback callback_;
  std::atomic<bool> watching_{false};
  std::thread thread_;
  int hotplug_handle_ = 0;
  bool hotplug_registered_ = false;

  friend struct UsbHotplugTrampoline;
};

}  // namespace avc::turntable
