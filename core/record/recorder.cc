#include "core/record/recorder.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <avc/product_chunk_t.hpp>
#include <avc/run_info_t.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/bus/channels.h"
#include "core/bus/decode.h"
#include "core/util/host.h"
#include "core/util/log.h"
#include "core/util/version.h"

namespace avc::record {
namespace {

// Creates path only if it does not exist, so two recorders (or a typo) never clobber a log.
void CreateExclusively(const std::filesystem::path& path) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd >= 0) {
    close(fd);
    return;
  }
  if (errno == EEXIST) {
    throw RecordError(
        fmt::format("{} already exists; refusing to overwrite it (choose a new "
                    "output file)",
                    path.string()));
  }
  throw RecordError(fmt::format("cannot create {}: {}", path.string(), std::strerror(errno)));
}

bool HasSeparateBulk(const bus::BusOptions& options) {
  return !options.bulk_url.empty() && options.bulk_url != options.control_url;
}

}  // namespace

Recorder::Recorder(bus::Bus& bus, bus::EventLoop& loop, RecorderOptions options)
    : bus_(bus), loop_(loop), options_(std::move(options)) {
  if (options_.output.empty()) throw RecordError("no output file given");
  if (options_.flush_interval < std::chrono::milliseconds(1)) {
    throw RecordError("the flush interval must be at least 1 ms");
  }
  CreateExclusively(options_.output);
  file_ = std::make_unique<lcm::LogFile>(options_.output.string(), "w");
  if (!file_->good()) {
    const std::string why = std::strerror(errno);
    file_.reset();
    throw RecordError(fmt::format("cannot open {} for writing: {}", options_.output.string(), why));
  }
  WriteRunInfo();
  Flush();

  // cell is [a-z0-9_-], so it needs no regex escaping.
  const std::string pattern = options_.all_cells ? ".*" : bus_.cell() + "/.*";
  auto on_message = [this](const uint8_t* data, size_t size, const bus::RxInfo& info) {
    Write(info.channel, info.recv_utime, data, size);
  };
  // Capacity 0 = unlimited: a recorder must never drop, even when the disk stalls.
  subscriptions_.push_back(
      bus_.SubscribeRegex(bus::Link::kControl, pattern, on_message, /*queue_capacity=*/0));
  if (HasSeparateBulk(bus_.options())) {
    subscriptions_.push_back(
        bus_.SubscribeRegex(bus::Link::kBulk, pattern, on_message, /*queue_capacity=*/0));
  }
  // After the raw subscription: LCM calls handlers in subscription order, so every chunk is
  // written (or has failed to be) before this receiver can acknowledge its product. A product
  // with a chunk that did not reach the file is refused: not acknowledged, so sent again.
  product_receiver_ = std::make_unique<products::ProductReceiver>(
      bus_, "recorder", std::string(channels::kProductPrefix) + ".*",
      [this](const products::Product& product, const bus::RxInfo&) {
        if (unlogged_products_.erase(product.product_id) > 0) {
          throw RecordError(fmt::format("chunks of product '{}' could not be written to {}",
                                        product.name, options_.output.string()));
        }
      });
  flush_timer_ = loop_.AddTimer(
      options_.flush_interval, [this] { Flush(); }, /*repeating=*/true);
}

Recorder::~Recorder() { Stop(); }

void Recorder::WriteRunInfo() {
  avc::run_info_t info;
  info.header.utime = bus_.clock().NowMicros();
  info.header.seq = 1;
  info.header.source = bus_.options().source;
  info.header.cell = bus_.cell();
  info.version = std::string(Version());
  info.command_line = options_.command_line;
  info.control_url = bus_.options().control_url;
  info.bulk_url =
      HasSeparateBulk(bus_.options()) ? bus_.options().bulk_url : bus_.options().control_url;
  info.hosts = {HostName()};
  info.num_hosts = static_cast<int32_t>(info.hosts.size());
  info.config_format = options_.config_format;
  info.config_text = options_.config_text;
  std::vector<uint8_t> buffer(static_cast<size_t>(info.getEncodedSize()));
  info.encode(buffer.data(), 0, static_cast<int>(buffer.size()));
  Write(bus_.FullChannel(channels::kRunInfo), info.header.utime, buffer.data(), buffer.size());
  if (stats_.write_errors > 0) {
    throw RecordError("cannot write the run_info_t header to " + options_.output.string());
  }
}

void Recorder::Write(const std::string& channel, int64_t utime, const uint8_t* data, size_t size) {
  if (!file_) return;
  lcm::LogEvent event{};
  event.timestamp = utime;
  event.channel = channel;
  event.datalen = static_cast<int32_t>(size);
  event.data = const_cast<uint8_t*>(data);  // LogFile only reads it
  const bool product_chunk = channel.find(channels::kProductPrefix) != std::string::npos;
  bool written = file_->writeEvent(&event) == 0;
  // A product chunk goes to the kernel at once: "recorder" acknowledges the product right after
  // this returns, and a crash must not lose what was acknowledged.
  if (written && product_chunk) written = std::fflush(file_->getFilePtr()) == 0;
  if (!written) {
    // Counted and logged sparsely: a full disk must not flood stderr.
    if (++stats_.write_errors == 1 || stats_.write_errors % 1000 == 0) {
      log::Error("cannot write to {}: {} ({} events lost so far)", options_.output.string(),
                 std::strerror(errno), stats_.write_errors);
    }
    // Its product must not be acknowledged (the receiver's handler runs after this one).
    avc::product_chunk_t chunk{};
    if (product_chunk && bus::DecodeMessage(data, size, &chunk)) {
      unlogged_products_.insert(chunk.product_id);
    }
    return;
  }
  ++stats_.events;
  stats_.bytes += static_cast<int64_t>(size);
  dirty_ = true;
}

void Recorder::Flush() {
  if (!file_ || !dirty_) return;
  FILE* f = file_->getFilePtr();
  if (std::fflush(f) != 0 || fsync(fileno(f)) != 0) {
    ++stats_.write_errors;
    log::Error("cannot flush {}: {}", options_.output.string(), std::strerror(errno));
    return;
  }
  dirty_ = false;
  ++stats_.flushes;
}

void Recorder::Stop() {
  if (!file_) return;
  loop_.CancelTimer(flush_timer_);
  product_receiver_.reset();
  for (bus::Bus::SubscriptionId id : subscriptions_) bus_.Unsubscribe(id);
  subscriptions_.clear();
  Flush();
  file_.reset();  // fclose
}

}  // namespace avc::record
