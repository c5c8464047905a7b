#pragma once

// Known USB devices via libusb: a list of what is plugged in now, and a watcher that reports
// arrivals and departures (libusb hot-plug callbacks where the platform has them, otherwise
// polling the device list). Which VID:PIDs a driver cares about is data it passes in (the
// turntable's serial adapters, the camera's Canon bodies).

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

struct libusb_context;

namespace avc::usb {

struct KnownUsbDevice {
  uint16_t vendor_id;
  uint16_t product_id;
  std::string name;
};

struct UsbDevice {
  uint16_t vendor_id = 0;
  uint16_t product_id = 0;
  int bus = 0;
  int address = 0;
  std::string name;  // from the known-device table

  std::string Describe() const;  // "0403:6001 FTDI FT232R (bus 1 address 4)"
  bool operator==(const UsbDevice& other) const = default;
};

// Thrown when libusb cannot start (e.g. no USB bus in a container).
class UsbError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class UsbDeviceWatcher {
 public:
  enum class Event { kArrived, kLeft };
  using Callback = std::function<void(Event, const UsbDevice&)>;

  explicit UsbDeviceWatcher(std::vector<KnownUsbDevice> known);
  ~UsbDeviceWatcher();
  UsbDeviceWatcher(const UsbDeviceWatcher&) = delete;
  UsbDeviceWatcher& operator=(const UsbDeviceWatcher&) = delete;

  // The known devices plugged in now, in bus/address order.
  std::vector<UsbDevice> List();

  // Reports arrivals and departures of known devices on a background thread until
  // StopWatching() or destruction. Returns true when libusb hot-plug is used, false when
  // polling every poll_period_ms.
  bool Watch(Callback callback, int poll_period_ms = 1000);
  void StopWatching();

 private:
  const KnownUsbDevice* Find(uint16_t vendor_id, uint16_t product_id) const;
  void Notify(Event event, const UsbDevice& device);

  std::vector<KnownUsbDevice> known_;
  libusb_context* context_ = nullptr;
  Callback callback_;
  std::atomic<bool> watching_{false};
  std::thread thread_;
  int hotplug_handle_ = 0;
  bool hotplug_registered_ = false;

  friend struct UsbHotplugTrampoline;
};

}  // namespace avc::usb
