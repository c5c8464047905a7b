#pragma once

// The one way AVC processes talk: typed publish/subscribe over LCM with the project's rules
// built in:
//  - owns its lcm::LCM instances and cannot be copied;
//  - every channel is prefixed "<cell>/" so cells sharing a network never hear each other;
//  - publishing is serialised by a mutex and refused above the message cap;
//  - subscribe takes a std::function with an explicit queue capacity;
//  - bad input is decoded by us, so it is counted and logged instead of printed by LCM, and a
//    throwing handler is logged and counted and never unwinds through LCM's C frames;
//  - handle() runs only on the EventLoop thread it is attached to (LCM is not thread-safe).

#include <atomic>
#include <cstdint>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <regex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/bus/bus_options.h"
#include "core/bus/decode.h"
#include "core/bus/event_loop.h"
#include "core/util/clock.h"

namespace avc::bus {

enum class Link { kControl, kBulk };

class BusError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a handler learns about a message besides its contents.
struct RxInfo {
  std::string channel;     // full channel name, "<cell>/NAME"
  int64_t recv_utime = 0;  // receive time (log time when read from a log)
  size_t size = 0;         // encoded bytes
};

struct SubscribeOptions {
  Link link = Link::kControl;
  // Messages LCM may queue for this subscription before dropping the oldest. 0 = unlimited, for
  // commands and products that must not be lost; 1 for state channels where only the latest
  // matters.
  int queue_capacity = 0;
};

struct BusStats {
  int64_t received = 0;        // messages decoded and handed to a handler
  int64_t rejected = 0;        // undecodable or malformed
  int64_t handler_errors = 0;  // handlers that threw
  int64_t published = 0;
  int64_t injected_drops = 0;  // dropped on purpose by InjectReceiveLoss
};

using RawHandler = std::function<void(const uint8_t* data, size_t size, const RxInfo& info)>;

class Bus {
 public:
  // Connects to the URLs in options. Throws BusError naming the URL when LCM cannot start (for
  // udpm that usually means no multicast route: see README "Networking").
  explicit Bus(BusOptions options, const Clock* clock = nullptr);
  ~Bus();
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;

  const BusOptions& options() const { return options_; }
  const std::string& cell() const { return options_.cell; }
  const Clock& clock() const { return *clock_; }
  // "<cell>/<name>"; throws BusError if the result exceeds LCM's 63 characters.
  std::string FullChannel(std::string_view name) const;

  // Stamps msg.header (time, per-channel sequence, source, cell) and publishes it. Throws
  // BusError when the encoded message is over the cap or LCM refuses it.
  template <class T>
  void Publish(std::string_view name, T& msg, Link link = Link::kControl) {
    const std::string channel = FullChannel(name);
    StampHeader(channel, msg.header);
    PublishEncodedMessage(link, channel, msg);
  }

  // Publishes msg exactly as it is (header untouched): for forwarding and replay.
  template <class T>
  void PublishUnstamped(std::string_view name, const T& msg, Link link = Link::kControl) {
    PublishEncodedMessage(link, FullChannel(name), msg);
  }

  // Publishes encoded bytes on a full channel name (recorder, replay, bridges).
  void PublishRaw(Link link, const std::string& full_channel, const void* data, size_t size);

  // Identifies a subscription for Unsubscribe.
  using SubscriptionId = uint64_t;

  // Calls handler with each message on "<cell>/<name>" that decodes as T. The subscription
  // lives until Unsubscribe or the Bus's end: objects that subscribe and die before the Bus
  // must unsubscribe in their destructor.
  template <class T>
  SubscriptionId Subscribe(std::string_view name,
                           std::function<void(const T&, const RxInfo&)> handler,
                           SubscribeOptions options = {}) {
    const std::string channel = FullChannel(name);
    return SubscribeRegex(
        options.link, std::regex_replace(channel, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)"),
        [this, handler = std::move(handler)](const uint8_t* data, size_t size, const RxInfo& info) {
          T msg;
          if (!DecodeMessage(data, size, &msg)) {
            Reject(info, "does not decode as " + std::string(T::getTypeName()));
            return;
          }
          ++stats_.received;
          handler(msg, info);
        },
        options.queue_capacity);
  }

  // Raw bytes of every message whose full channel name matches the regex (LCM anchors it).
  SubscriptionId SubscribeRegex(Link link, const std::string& channel_regex, RawHandler handler,
                                int queue_capacity = 0);
  // Ends a subscription. Not from inside that subscription's own handler.
  void Unsubscribe(SubscriptionId id);

  // Records a malformed message: counted, logged (rate-limited), never fatal.
  void Reject(const RxInfo& info, const std::string& why);

  // Watches the LCM file descriptors on loop; handlers then run on the loop thread.
  void AttachTo(EventLoop& loop);
  // Dispatches every message already waiting, without blocking. For single-threaded drivers
  // such as replay and bus tests. Returns the number dispatched.
  int DispatchPending();

  // Test fault injection: drops received messages whose full channel matches the regex with
  // the given probability (seeded, so a test run is repeatable).
  void InjectReceiveLoss(const std::string& channel_regex, double probability, uint64_t seed);

  BusStats stats() const;

 private:
  struct Subscription;
  struct Instance;

  static void Trampoline(const lcm::ReceiveBuffer* rbuf, const std::string& channel,
                         Subscription* subscription);
  template <class T>
  void PublishEncodedMessage(Link link, const std::string& channel, const T& msg) {
    const int size = msg.getEncodedSize();
    if (size < 0) throw BusError("cannot encode message for " + channel);
    std::vector<uint8_t> buffer(static_cast<size_t>(size));
    if (msg.encode(buffer.data(), 0, size) != size) {
      throw BusError("cannot encode message for " + channel);
    }
    PublishRaw(link, channel, buffer.data(), buffer.size());
  }
  void StampHeader(const std::string& channel, auto& header) {
    header.utime = clock_->NowMicros();
    header.seq = NextSeq(channel);
    header.source = options_.source;
    header.cell = options_.cell;
  }
  int64_t NextSeq(const std::string& channel);
  Instance& InstanceFor(Link link);
  bool ShouldInjectDrop(const std::string& channel);

  BusOptions options_;
  SystemClock system_clock_;
  const Clock* clock_;
  std::unique_ptr<Instance> control_;
  std::unique_ptr<Instance> bulk_;  // null when both links share control_
  std::map<SubscriptionId, std::unique_ptr<Subscription>> subscriptions_;
  SubscriptionId next_subscription_id_ = 1;

  std::mutex publish_mutex_;
  std::map<std::string, int64_t> seq_;  // guarded by publish_mutex_

  struct AtomicStats {
    std::atomic<int64_t> received{0}, rejected{0}, handler_errors{0}, published{0},
        injected_drops{0};
  } stats_;
  std::map<std::string, int64_t> rejects_per_channel_;  // loop thread only

  struct LossInjection {
    std::regex channel;
    double probability = 0;
    std::mt19937_64 rng;
  };
  std::unique_ptr<LossInjection> loss_;
};

}  // namespace avc::bus
