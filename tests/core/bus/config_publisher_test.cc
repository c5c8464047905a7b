// A service's configuration in force goes out on CONFIG at once and again every period, so a log
// or a scan that starts after the service still hears it.

#include "core/bus/config_publisher.h"

#include <gtest/gtest.h>

#include <avc/config_t.hpp>
#include <vector>

#include "core/bus/channels.h"
#include "core/util/sha256.h"

namespace avc::bus {
namespace {

using std::chrono::milliseconds;

TEST(ConfigPublisher, PublishesTheTextAndItsShaAtOnceAndEveryPeriod) {
  Bus bus(InProcessBusOptions("cellc", "config-test"));
  EventLoop loop;
  bus.AttachTo(loop);
  std::vector<avc::config_t> heard;
  bus.Subscribe<avc::config_t>(channels::kConfig, [&](const avc::config_t& config, const RxInfo&) {
    heard.push_back(config);
  });
  const std::string text = "[patch]\nwindow = 5\n";
  {
    ConfigPublisher publisher(bus, loop, "avc-builder", text, milliseconds(50));
    EXPECT_EQ(publisher.sha256(), Sha256Hex(text));
    loop.RunUntil([] { return false; }, milliseconds(20));
    ASSERT_EQ(heard.size(), 1u);
    loop.RunUntil([] { return false; }, milliseconds(230));
  }
  loop.RunUntil([] { return false; }, milliseconds(20));  // what was sent before it went
  ASSERT_GE(heard.size(), 4u);
  ASSERT_LE(heard.size(), 7u);
  for (const avc::config_t& config : heard) {
    EXPECT_EQ(config.service, "avc-builder");
    EXPECT_EQ(config.format, "toml");
    EXPECT_EQ(config.text, text);
    EXPECT_EQ(config.sha256, Sha256Hex(text));
  }
  // Gone with its publisher.
  const size_t before = heard.size();
  loop.RunUntil([] { return false; }, milliseconds(120));
  EXPECT_EQ(heard.size(), before);
}

}  // namespace
}  // namespace avc::bus
