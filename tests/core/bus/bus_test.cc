// Bus behaviour over memq:// (one process, one LCM instance, deterministic dispatch).

#include "core/bus/bus.h"

#include <gtest/gtest.h>

#include <avc/ack_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/log_text_t.hpp>

#include "core/bus/channels.h"
#include "core/bus/heartbeat.h"

namespace avc::bus {
namespace {

TEST(Bus, TypedPublishSubscribeStampsHeader) {
  ManualClock clock(1'700'000'000'000'000);
  Bus bus(InProcessBusOptions("cell7", "tester"), &clock);
  std::vector<avc::ack_t> got;
  std::vector<std::string> channels_seen;
  bus.Subscribe<avc::ack_t>(channels::kAck, [&](const avc::ack_t& ack, const RxInfo& info) {
    got.push_back(ack);
    channels_seen.push_back(info.channel);
  });
  avc::ack_t ack{};
  ack.request_id = "r1";
  ack.status = avc::ack_t::STATUS_DONE;
  bus.Publish(channels::kAck, ack);
  clock.Advance(5);
  ack.request_id = "r2";
  bus.Publish(channels::kAck, ack);
  EXPECT_EQ(bus.DispatchPending(), 2);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].request_id, "r1");
  EXPECT_EQ(got[0].header.seq, 1);
  EXPECT_EQ(got[1].header.seq, 2);
  EXPECT_EQ(got[0].header.utime, 1'700'000'000'000'000);
  EXPECT_EQ(got[1].header.utime, 1'700'000'000'000'005);
  EXPECT_EQ(got[0].header.source, "tester");
  EXPECT_EQ(got[0].header.cell, "cell7");
  EXPECT_EQ(channels_seen[0], "cell7/ACK");
}

TEST(Bus, OtherCellsAreNotHeard) {
  Bus bus(InProcessBusOptions("cell1"));
  int heard = 0;
  bus.Subscribe<avc::ack_t>(channels::kAck, [&](const avc::ack_t&, const RxInfo&) { ++heard; });
  avc::ack_t ack{};
  const int size = ack.getEncodedSize();
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  ack.encode(bytes.data(), 0, size);
  bus.PublishRaw(Link::kControl, "cell2/ACK", bytes.data(), bytes.size());
  bus.PublishRaw(Link::kControl, "cell1/ACK", bytes.data(), bytes.size());
  bus.DispatchPending();
  EXPECT_EQ(heard, 1);
}

TEST(Bus, MalformedMessagesAreCountedNotDelivered) {
  Bus bus(InProcessBusOptions());
  int heard = 0;
  bus.Subscribe<avc::ack_t>(channels::kAck, [&](const avc::ack_t&, const RxInfo&) { ++heard; });
  const std::string garbage = "definitely not an ack_t";
  bus.PublishRaw(Link::kControl, bus.FullChannel(channels::kAck), garbage.data(), garbage.size());
  bus.PublishRaw(Link::kControl, bus.FullChannel(channels::kAck), garbage.data(), 0);
  // A structurally different type on the channel fails the fingerprint check.
  avc::log_text_t wrong{};
  bus.PublishUnstamped(channels::kAck, wrong);
  bus.DispatchPending();
  EXPECT_EQ(heard, 0);
  EXPECT_EQ(bus.stats().rejected, 3);
}

TEST(Bus, ThrowingHandlerIsCountedAndOthersStillRun) {
  Bus bus(InProcessBusOptions());
  int later = 0;
  bus.Subscribe<avc::ack_t>(channels::kAck, [](const avc::ack_t&, const RxInfo&) {
    throw std::runtime_error("handler bug");
  });
  bus.Subscribe<avc::ack_t>(channels::kAck, [&](const avc::ack_t&, const RxInfo&) { ++later; });
  avc::ack_t ack{};
  bus.Publish(channels::kAck, ack);
  bus.Publish(channels::kAck, ack);
  bus.DispatchPending();
  EXPECT_EQ(later, 2);
  EXPECT_EQ(bus.stats().handler_errors, 2);
}

TEST(Bus, OversizedMessageIsRefusedBeforeSending) {
  BusOptions options = InProcessBusOptions();
  options.max_message_bytes = 10'000;
  Bus bus(options);
  avc::log_text_t big{};
  big.text.assign(20'000, 'x');
  try {
    bus.Publish(channels::kLog, big);
    FAIL() << "oversized message was published";
  } catch (const BusError& e) {
    EXPECT_NE(std::string(e.what()).find("cell0/LOG"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("product"), std::string::npos);
  }
  EXPECT_EQ(bus.stats().published, 0);
}

TEST(Bus, TooLongChannelNameIsRefused) {
  Bus bus(InProcessBusOptions());
  EXPECT_THROW(bus.FullChannel(std::string(60, 'X')), BusError);
}

TEST(Bus, InjectedLossIsSeededAndCounted) {
  auto run = [](uint64_t seed) {
    Bus bus(InProcessBusOptions());
    bus.InjectReceiveLoss(".*/ACK", 0.5, seed);
    std::vector<int64_t> seqs;
    bus.Subscribe<avc::ack_t>(
        channels::kAck, [&](const avc::ack_t& a, const RxInfo&) { seqs.push_back(a.header.seq); });
    avc::ack_t ack{};
    for (int i = 0; i < 200; ++i) bus.Publish(channels::kAck, ack);
    bus.DispatchPending();
    EXPECT_EQ(static_cast<int64_t>(seqs.size()) + bus.stats().injected_drops, 200);
    return seqs;
  };
  const auto first = run(42);
  EXPECT_GT(first.size(), 60u);
  EXPECT_LT(first.size(), 140u);
  EXPECT_EQ(first, run(42));
  EXPECT_NE(first, run(43));
}

TEST(Bus, HeartbeatPublishesOnStateChangeAndPeriodically) {
  Bus bus(InProcessBusOptions());
  EventLoop loop;
  bus.AttachTo(loop);
  std::vector<avc::heartbeat_t> beats;
  bus.Subscribe<avc::heartbeat_t>(
      channels::kHeartbeat, [&](const avc::heartbeat_t& b, const RxInfo&) { beats.push_back(b); });
  HeartbeatPublisher heartbeat(bus, loop, "svc", std::chrono::milliseconds(20));
  ASSERT_TRUE(loop.RunUntil([&] { return beats.size() == 1; }, std::chrono::seconds(2)));
  EXPECT_EQ(beats[0].state, avc::heartbeat_t::STATE_STARTING);
  heartbeat.Set(ServiceState::kReady, "idle");
  ASSERT_TRUE(loop.RunUntil([&] { return beats.size() == 2; }, std::chrono::seconds(2)));
  EXPECT_EQ(beats[1].state, avc::heartbeat_t::STATE_READY);
  EXPECT_EQ(beats[1].detail, "idle");
  EXPECT_EQ(beats[1].service, "svc");
  EXPECT_EQ(beats[1].pid, getpid());
  ASSERT_TRUE(loop.RunUntil([&] { return beats.size() >= 5; }, std::chrono::seconds(2)));
  EXPECT_EQ(beats.back().state, avc::heartbeat_t::STATE_READY);
  EXPECT_GT(beats.back().uptime_us, beats[1].uptime_us);
}

}  // namespace
}  // namespace avc::bus
