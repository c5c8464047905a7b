// Known USB devices with libusb: the drivers' tables, listing (works with no USB devices at all)
// and watching for arrivals, which reports the devices already plugged in first.

#include "drivers/usb/usb_devices.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <thread>

#include "drivers/turntable/usb_serial_adapters.h"

namespace avc::usb {
namespace {

bool Known(const UsbDevice& device,
           const std::vector<KnownUsbDevice>& known = turntable::DefaultKnownAdapters()) {
  return std::any_of(known.begin(), known.end(), [&](const KnownUsbDevice& entry) {
    return entry.vendor_id == device.vendor_id && entry.product_id == device.product_id;
  });
}

TEST(UsbDevices, TurntableTableHasTheCommonSerialAdapters) {
  for (const auto& [vid, pid] :
       {std::pair<uint16_t, uint16_t>{0x0403, 0x6001}, {0x067b, 0x2303}, {0x1a86, 0x7523}}) {
    EXPECT_TRUE(Known(UsbDevice{vid, pid, 0, 0, ""})) << vid << ":" << pid;
  }
  EXPECT_FALSE(Known(UsbDevice{0x1234, 0x5678, 0, 0, ""}));
  const UsbDevice device{0x0403, 0x6001, 1, 4, "FTDI FT232R"};
  EXPECT_EQ(device.Describe(), "0403:6001 FTDI FT232R (bus 1 address 4)");
}

TEST(UsbDevices, ListsOnlyKnownDevices) {
  UsbDeviceWatcher adapters(turntable::DefaultKnownAdapters());
  const std::vector<UsbDevice> found = adapters.List();  // often empty: no USB here
  for (const auto& device : found) EXPECT_TRUE(Known(device)) << device.Describe();
  UsbDeviceWatcher none(std::vector<KnownUsbDevice>{});
  EXPECT_TRUE(none.List().empty());
}

TEST(UsbDevices, WatchReportsWhatIsPluggedInAndStopsPromptly) {
  UsbDeviceWatcher adapters(turntable::DefaultKnownAdapters());
  const std::vector<UsbDevice> present = adapters.List();
  std::mutex mutex;
  std::vector<UsbDevice> arrived;
  adapters.Watch(
      [&](UsbDeviceWatcher::Event event, const UsbDevice& device) {
        std::lock_guard lock(mutex);
        if (event == UsbDeviceWatcher::Event::kArrived) arrived.push_back(device);
      },
      /*poll_period_ms=*/50);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto start = std::chrono::steady_clock::now();
  adapters.StopWatching();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  std::lock_guard lock(mutex);
  std::sort(arrived.begin(), arrived.end(), [](const auto& a, const auto& b) {
    return std::tie(a.bus, a.address) < std::tie(b.bus, b.address);
  });
  EXPECT_EQ(arrived, present);
}

}  // namespace
}  // namespace avc::usb
