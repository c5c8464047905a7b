#include "drivers/usb/usb_devices.h"

#include <fmt/format.h>
#include <libusb.h>

#include <algorithm>
#include <chrono>
#include <tuple>

namespace avc::usb {

std::string UsbDevice::Describe() const {
  return fmt::format("{:04x}:{:04x} {} (bus {} address {})", vendor_id, product_id, name, bus,
                     address);
}

// libusb calls a plain C function; this forwards to the object.
struct UsbHotplugTrampoline {
  static int Call(libusb_context*, libusb_device* device, libusb_hotplug_event event,
                  void* user_data) {
    auto* self = static_cast<UsbDeviceWatcher*>(user_data);
    libusb_device_descriptor descriptor{};
    if (libusb_get_device_descriptor(device, &descriptor) != 0) return 0;
    const KnownUsbDevice* known = self->Find(descriptor.idVendor, descriptor.idProduct);
    if (known == nullptr) return 0;
    const UsbDevice found{descriptor.idVendor, descriptor.idProduct, libusb_get_bus_number(device),
                          libusb_get_device_address(device), known->name};
    self->Notify(event == LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED ? UsbDeviceWatcher::Event::kArrived
                                                              : UsbDeviceWatcher::Event::kLeft,
                 found);
    return 0;  // stay registered
  }
};

UsbDeviceWatcher::UsbDeviceWatcher(std::vector<KnownUsbDevice> known) : known_(std::move(known)) {
  const int rc = libusb_init(&context_);
  if (rc != 0) {
    context_ = nullptr;
    throw UsbError(fmt::format("cannot start libusb: {}", libusb_strerror(rc)));
  }
}

UsbDeviceWatcher::~UsbDeviceWatcher() {
  StopWatching();
  if (context_ != nullptr) libusb_exit(context_);
}

const KnownUsbDevice* UsbDeviceWatcher::Find(uint16_t vendor_id, uint16_t product_id) const {
  for (const KnownUsbDevice& device : known_) {
    if (device.vendor_id == vendor_id && device.product_id == product_id) return &device;
  }
  return nullptr;
}

void UsbDeviceWatcher::Notify(Event event, const UsbDevice& device) {
  if (callback_) callback_(event, device);
}

std::vector<UsbDevice> UsbDeviceWatcher::List() {
  libusb_device** devices = nullptr;
  const ssize_t count = libusb_get_device_list(context_, &devices);
  if (count < 0) {
    throw UsbError(
        fmt::format("cannot list USB devices: {}", libusb_strerror(static_cast<int>(count))));
  }
  std::vector<UsbDevice> found;
  for (ssize_t i = 0; i < count; ++i) {
    libusb_device_descriptor descriptor{};
    if (libusb_get_device_descriptor(devices[i], &descriptor) != 0) continue;
    const KnownUsbDevice* known = Find(descriptor.idVendor, descriptor.idProduct);
    if (known == nullptr) continue;
    found.push_back({descriptor.idVendor, descriptor.idProduct, libusb_get_bus_number(devices[i]),
                     libusb_get_device_address(devices[i]), known->name});
  }
  libusb_free_device_list(devices, 1);
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
    return std::tie(a.bus, a.address) < std::tie(b.bus, b.address);
  });
  return found;
}

bool UsbDeviceWatcher::Watch(Callback callback, int poll_period_ms) {
  StopWatching();
  callback_ = std::move(callback);
  watching_ = true;
  if (libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG) != 0) {
    const int rc = libusb_hotplug_register_callback(
        context_,
        static_cast<libusb_hotplug_event>(LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED |
                                          LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT),
        LIBUSB_HOTPLUG_ENUMERATE, LIBUSB_HOTPLUG_MATCH_ANY, LIBUSB_HOTPLUG_MATCH_ANY,
        LIBUSB_HOTPLUG_MATCH_ANY, &UsbHotplugTrampoline::Call, this, &hotplug_handle_);
    if (rc == LIBUSB_SUCCESS) {
      hotplug_registered_ = true;
      thread_ = std::thread([this] {
        while (watching_) {
          timeval tv{0, 200'000};
          libusb_handle_events_timeout_completed(context_, &tv, nullptr);
        }
      });
      return true;
    }
  }
  // No hot-plug support: compare the list every period.
  thread_ = std::thread([this, poll_period_ms] {
    std::vector<UsbDevice> before;
    while (watching_) {
      std::vector<UsbDevice> now;
      try {
        now = List();
      } catch (const UsbError&) {
        now = before;  // transient; try again next period
      }
      for (const auto& device : now) {
        if (std::find(before.begin(), before.end(), device) == before.end()) {
          Notify(Event::kArrived, device);
        }
      }
      for (const auto& device : before) {
        if (std::find(now.begin(), now.end(), device) == now.end()) Notify(Event::kLeft, device);
      }
      before = std::move(now);
      for (int waited = 0; waited < poll_period_ms && watching_; waited += 50) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    }
  });
  return false;
}

void UsbDeviceWatcher::StopWatching() {
  if (!watching_.exchange(false)) return;
  if (hotplug_registered_) {
    // Deregistering wakes libusb_handle_events so the thread sees watching_ == false.
    libusb_hotplug_deregister_callback(context_, hotplug_handle_);
    hotplug_registered_ = false;
  }
  if (thread_.joinable()) thread_.join();
  callback_ = nullptr;
}

}  // namespace avc::usb
