// USB serial adapter discovery with libusb: the known-adapter table, listing (works with no USB
// devices at all) and watching for arrivals, which reports the adapters already plugged in first.

#include "drivers/turntable/usb_serial_adapters.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <thread>

namespace avc::turntable {
namespace {

bool Known(const UsbSerialDevice& device) {
  const auto& known = DefaultKnownAdapters();
  return std::any_of(known.begin(), known.end(), [&](const KnownAdapter& adapter) {
    return adapter.vendor_id == device.vendor_id && adapter.product_id == device.product_id;
  });
}

TEST(UsbSerialAdapters, KnownTableHasTheCommonAdapters) {
  for (const auto& [vid, pid] :
       {std::pair<uint16_t, uint16_t>{0x0403, 0x6001}, {0x067b, 0x2303}, {0x1a86, 0x7523}}) {
    EXPECT_TRUE(Known(UsbSerialDevice{vid, pid, 0, 0, ""})) << vid << ":" << pid;
  }
  EXPECT_FALSE(Known(UsbSerialDevice{0x1234, 0x5678, 0, 0, ""}));
  const UsbSerialDevice device{0x0403, 0x6001, 1, 4, "FTDI FT232R"};
  EXPECT_EQ(device.Describe(), "0403:6001 FTDI FT232R (bus 1 address 4)");
}

TEST(UsbSerialAdapters, ListsOnlyKnownAdapters) {
  UsbSerialAdapters adapters;
  const std::vector<UsbSerialDevice> found = adapters.List();  // often empty: no USB here
  for (const auto& device : found) EXPECT_TRUE(Known(device)) << device.Describe();
  UsbSerialAdapters none(std::vector<KnownAdapter>{});
  EXPECT_TRUE(none.List().empty());
}

TEST(UsbSerialAdapters, WatchReportsWhatIsPluggedInAndStopsPromptly) {
  UsbSerialAdapters adapters;
  const std::vector<UsbSerialDevice> present = adapters.List();
  std::mutex mutex;
  std::vector<UsbSerialDevice> arrived;
  adapters.Watch(
      [&](UsbSerialAdapters::Event event, const UsbSerialDevice& device) {
        std::lock_guard lock(mutex);
        if (event == UsbSerialAdapters::Event::kArrived) arrived.push_back(device);
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
}  // namespace avc::turntable
