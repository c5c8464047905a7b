#include "tools/avc/usb_listing.h"

#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <memory>
#include <thread>

namespace avc::cli {

int ListUsbDevices(const std::vector<usb::KnownUsbDevice>& known, const std::string& what,
                   double watch_s) {
  std::unique_ptr<usb::UsbDeviceWatcher> watcher;
  try {
    watcher = std::make_unique<usb::UsbDeviceWatcher>(known);
  } catch (const usb::UsbError& e) {
    // No USB stack (e.g. a container): nothing can be plugged in, which is an answer, not a fault.
    std::cout << "no " << what << " found (" << e.what() << ")\n";
    return 0;
  }
  const std::vector<usb::UsbDevice> found = watcher->List();
  if (found.empty()) {
    std::cout << "no " << what << " found (known: ";
    for (size_t i = 0; i < known.size(); ++i) {
      std::cout << fmt::format("{}{:04x}:{:04x} {}", i == 0 ? "" : ", ", known[i].vendor_id,
                               known[i].product_id, known[i].name);
    }
    std::cout << ")\n";
  }
  for (const auto& device : found) std::cout << device.Describe() << "\n";
  if (watch_s > 0) {
    const bool hotplug =
        watcher->Watch([](usb::UsbDeviceWatcher::Event event, const usb::UsbDevice& device) {
          std::cout << (event == usb::UsbDeviceWatcher::Event::kArrived ? "arrived: " : "left: ")
                    << device.Describe() << std::endl;
        });
    std::cout << fmt::format("watching for {} s ({})", watch_s,
                             hotplug ? "libusb hot-plug" : "polling")
              << std::endl;
    std::this_thread::sleep_for(std::chrono::duration<double>(watch_s));
    watcher->StopWatching();
  }
  return 0;
}

}  // namespace avc::cli
