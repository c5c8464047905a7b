#include "core/bus/bus.h"

#include <fmt/format.h>

#include "core/util/log.h"

namespace avc::bus {

struct Bus::Instance {
  explicit Instance(const std::string& lcm_url) : lcm(lcm_url), url(lcm_url) {}
  lcm::LCM lcm;
  std::string url;
};

struct Bus::Subscription {
  Bus* bus;
  RawHandler handler;
  Instance* instance = nullptr;
  lcm::Subscription* lcm_subscription = nullptr;
};

namespace {
constexpr size_t kMaxChannelLength = 63;  // LCM's limit
}  // namespace

Bus::Bus(BusOptions options, const Clock* clock)
    : options_(std::move(options)), clock_(clock ? clock : &system_clock_) {
  if (const std::string error = options_.Validate(); !error.empty()) throw BusError(error);
  if (options_.source.empty()) options_.source = log::ProcessName();
  control_ = std::make_unique<Instance>(options_.control_url);
  if (!control_->lcm.good()) {
    throw BusError("cannot open the LCM control URL '" + options_.control_url +
                   "'. For udpm:// a multicast route is required: "
                   "ip route add 224.0.0.0/4 dev lo (or scripts/setup-lab-host)");
  }
  if (!options_.bulk_url.empty() && options_.bulk_url != options_.control_url) {
    bulk_ = std::make_unique<Instance>(options_.bulk_url);
    if (!bulk_->lcm.good()) {
      throw BusError("cannot open the LCM bulk URL '" + options_.bulk_url + "'");
    }
  }
}

Bus::~Bus() = default;

std::string Bus::FullChannel(std::string_view name) const {
  std::string channel = options_.cell + "/" + std::string(name);
  if (channel.size() > kMaxChannelLength) {
    throw BusError(fmt::format("channel '{}' is {} characters; LCM allows {}", channel,
                               channel.size(), kMaxChannelLength));
  }
  return channel;
}

Bus::Instance& Bus::InstanceFor(Link link) {
  return (link == Link::kBulk && bulk_) ? *bulk_ : *control_;
}

void Bus::PublishRaw(Link link, const std::string& full_channel, const void* data, size_t size) {
  if (size > options_.max_message_bytes) {
    throw BusError(
        fmt::format("message on {} is {} bytes, over the bus cap of {} bytes; send it as a product "
                    "(core/products) so it is chunked",
                    full_channel, size, options_.max_message_bytes));
  }
  Instance& instance = InstanceFor(link);
  std::lock_guard lock(publish_mutex_);
  if (instance.lcm.publish(full_channel, data, static_cast<unsigned int>(size)) != 0) {
    throw BusError(fmt::format("LCM refused to publish {} bytes on {} ({})", size, full_channel,
                               instance.url));
  }
  ++stats_.published;
}

int64_t Bus::NextSeq(const std::string& channel) {
  std::lock_guard lock(publish_mutex_);
  return ++seq_[channel];
}

Bus::SubscriptionId Bus::SubscribeRegex(Link link, const std::string& channel_regex,
                                        RawHandler handler, int queue_capacity) {
  auto subscription = std::make_unique<Subscription>();
  subscription->bus = this;
  subscription->handler = std::move(handler);
  subscription->instance = &InstanceFor(link);
  subscription->lcm_subscription = subscription->instance->lcm.subscribeFunction(
      channel_regex, &Bus::Trampoline, subscription.get());
  if (subscription->lcm_subscription == nullptr) {
    throw BusError("LCM refused the subscription '" + channel_regex + "'");
  }
  subscription->lcm_subscription->setQueueCapacity(queue_capacity);
  const SubscriptionId id = next_subscription_id_++;
  subscriptions_.emplace(id, std::move(subscription));
  return id;
}

void Bus::Unsubscribe(SubscriptionId id) {
  auto it = subscriptions_.find(id);
  if (it == subscriptions_.end()) return;
  it->second->instance->lcm.unsubscribe(it->second->lcm_subscription);
  subscriptions_.erase(it);
}

void Bus::Trampoline(const lcm::ReceiveBuffer* rbuf, const std::string& channel,
                     Subscription* subscription) {
  Bus& bus = *subscription->bus;
  RxInfo info{channel, rbuf->recv_utime, rbuf->data_size};
  if (bus.loss_ && bus.ShouldInjectDrop(channel)) return;
  // Exceptions must not unwind through LCM's C frames.
  try {
    subscription->handler(static_cast<const uint8_t*>(rbuf->data), rbuf->data_size, info);
  } catch (const std::exception& e) {
    ++bus.stats_.handler_errors;
    log::Error("handler for {} failed: {}", channel, e.what());
  } catch (...) {
    ++bus.stats_.handler_errors;
    log::Error("handler for {} failed with an unknown exception", channel);
  }
}

void Bus::Reject(const RxInfo& info, const std::string& why) {
  ++stats_.rejected;
  const int64_t count = ++rejects_per_channel_[info.channel];
  // The first few, then every 100th: a flood of garbage must not flood the log.
  if (count <= 5 || count % 100 == 0) {
    log::Warn("rejected a {}-byte message on {}: {} ({} rejected on this channel)", info.size,
              info.channel, why, count);
  }
}

void Bus::AttachTo(EventLoop& loop) {
  loop.WatchFd(control_->lcm.getFileno(), [this] { control_->lcm.handleTimeout(0); });
  if (bulk_) loop.WatchFd(bulk_->lcm.getFileno(), [this] { bulk_->lcm.handleTimeout(0); });
}

int Bus::DispatchPending() {
  int dispatched = 0;
  bool progress = true;
  while (progress) {
    progress = false;
    for (Instance* instance : {control_.get(), bulk_.get()}) {
      if (instance == nullptr) continue;
      while (instance->lcm.handleTimeout(0) > 0) {
        ++dispatched;
        progress = true;
      }
    }
  }
  return dispatched;
}

void Bus::InjectReceiveLoss(const std::string& channel_regex, double probability, uint64_t seed) {
  loss_ = std::make_unique<LossInjection>(
      LossInjection{std::regex(channel_regex), probability, std::mt19937_64(seed)});
}

bool Bus::ShouldInjectDrop(const std::string& channel) {
  if (!std::regex_match(channel, loss_->channel)) return false;
  const bool drop = std::uniform_real_distribution<double>(0, 1)(loss_->rng) < loss_->probability;
  if (drop) ++stats_.injected_drops;
  return drop;
}

BusStats Bus::stats() const {
  return BusStats{stats_.received.load(), stats_.rejected.load(), stats_.handler_errors.load(),
                  stats_.published.load(), stats_.injected_drops.load()};
}

}  // namespace avc::bus
