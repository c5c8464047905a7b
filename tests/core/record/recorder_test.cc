// The recorder over an in-process bus (memq://): what it writes, what it leaves out, when it
// acknowledges products, and that a stopped recording reads back completely.

#include "core/record/recorder.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <avc/heartbeat_t.hpp>
#include <avc/log_text_t.hpp>
#include <avc/product_ack_t.hpp>
#include <avc/product_chunk_t.hpp>
#include <avc/run_info_t.hpp>
#include <csignal>
#include <cstring>
#include <map>
#include <optional>
#include <random>
#include <set>

#include "core/bus/bus.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/products/chunking.h"
#include "core/products/product_sender.h"
#include "core/record/log_reader.h"
#include "core/util/clock.h"
#include "core/util/sha256.h"
#include "core/util/version.h"
#include "tests/support/test_support.h"

namespace avc::record {
namespace {

using testing::Encode;
using testing::RandomBytes;

using std::chrono::milliseconds;

struct LoggedEvent {
  std::string channel;
  int64_t timestamp = 0;
  std::string data;
};

struct LogContents {
  std::vector<LoggedEvent> events;
  std::vector<std::string> warnings;
  bool truncated = false;
};

LogContents ReadLog(const std::filesystem::path& path) {
  LogContents contents;
  LogReader reader(path);
  while (const lcm::LogEvent* event = reader.Next()) {
    contents.events.push_back(
        {event->channel, event->timestamp,
         std::string(static_cast<const char*>(event->data), static_cast<size_t>(event->datalen))});
  }
  contents.warnings = reader.warnings();
  contents.truncated = reader.truncated();
  return contents;
}

template <class T>
T Decode(const std::string& bytes) {
  T msg{};
  EXPECT_GE(msg.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0)
      << "does not decode as " << T::getTypeName();
  return msg;
}

std::vector<std::string> Channels(const LogContents& log) {
  std::vector<std::string> channels;
  for (const LoggedEvent& event : log.events) channels.push_back(event.channel);
  return channels;
}

struct Harness {
  explicit Harness(size_t cap = bus::kDefaultMaxMessageBytes) : bus(Options(cap)) {
    bus.AttachTo(loop);
  }
  static bus::BusOptions Options(size_t cap) {
    bus::BusOptions options = bus::InProcessBusOptions("cell0", "tester");
    options.max_message_bytes = cap;
    return options;
  }
  RecorderOptions Recording(const std::string& name = "run.lcmlog") const {
    RecorderOptions options;
    options.output = dir / name;
    options.flush_interval = milliseconds(20);
    return options;
  }
  testing::TempDir dir{"avc-recorder"};
  bus::Bus bus;
  bus::EventLoop loop;
};

avc::log_text_t LogLine(const std::string& text) {
  avc::log_text_t line{};
  line.level = avc::log_text_t::LEVEL_INFO;
  line.text = text;
  return line;
}

TEST(Recorder, RunInfoIsTheFirstEventAndCarriesTheSetUp) {
  Harness h;
  RecorderOptions options = h.Recording();
  options.command_line = "avc record -o run.lcmlog --config 'cell 0.yaml'";
  options.config_format = "yaml";
  options.config_text = "cell: cell0\nrobot:\n  speed: 0.25\n";
  const int64_t before = SystemClock().NowMicros();
  Recorder recorder(h.bus, h.loop, options);
  // Something after it, so "first" means something.
  avc::log_text_t line = LogLine("hello");
  h.bus.Publish(channels::kLog, line);
  h.bus.DispatchPending();
  recorder.Stop();
  const int64_t after = SystemClock().NowMicros();

  const LogContents log = ReadLog(options.output);
  EXPECT_TRUE(log.warnings.empty()) << log.warnings.front();
  ASSERT_EQ(log.events.size(), 2u);
  EXPECT_EQ(log.events[0].channel, "cell0/RUN_INFO");
  EXPECT_EQ(log.events[1].channel, "cell0/LOG");
  const auto info = Decode<avc::run_info_t>(log.events[0].data);
  EXPECT_EQ(info.version, std::string(Version()));
  EXPECT_FALSE(info.version.empty());
  EXPECT_EQ(info.command_line, options.command_line);
  EXPECT_EQ(info.config_format, "yaml");
  EXPECT_EQ(info.config_text, options.config_text);
  EXPECT_EQ(info.header.cell, "cell0");
  EXPECT_EQ(info.header.source, "tester");
  EXPECT_EQ(info.header.seq, 1);
  EXPECT_EQ(info.control_url, "memq://");
  EXPECT_EQ(info.bulk_url, "memq://") << "one in-process link carries both";
  ASSERT_EQ(info.num_hosts, 1);
  ASSERT_EQ(info.hosts.size(), 1u);
  EXPECT_FALSE(info.hosts[0].empty());
  EXPECT_GE(info.header.utime, before);
  EXPECT_LE(info.header.utime, after);
  EXPECT_EQ(log.events[0].timestamp, info.header.utime);
}

TEST(Recorder, RecordsItsOwnCellOnlyWithReceiveTimesAndExactBytes) {
  Harness h;
  const RecorderOptions options = h.Recording();
  const int64_t before = SystemClock().NowMicros();
  Recorder recorder(h.bus, h.loop, options);

  std::vector<std::string> sent;
  for (int i = 0; i < 3; ++i) {
    avc::log_text_t line = LogLine("line " + std::to_string(i));
    h.bus.Publish(channels::kLog, line);
    sent.push_back(Encode(line));
  }
  avc::heartbeat_t beat{};
  beat.service = "avc-robot";
  beat.state = avc::heartbeat_t::STATE_READY;
  h.bus.Publish(channels::kHeartbeat, beat);
  sent.push_back(Encode(beat));
  // Other cells, including one whose id starts with ours, and a channel without a cell.
  const std::string other = Encode(LogLine("not ours"));
  for (const char* channel : {"cell1/LOG", "cell01/LOG", "cell0", "CELL0/LOG", "x/cell0/LOG"}) {
    h.bus.PublishRaw(bus::Link::kControl, channel, other.data(), other.size());
  }
  ASSERT_TRUE(
      h.loop.RunUntil([&] { return recorder.stats().events == 5; }, std::chrono::seconds(5)))
      << recorder.stats().events << " events";
  h.bus.DispatchPending();
  recorder.Stop();
  const int64_t after = SystemClock().NowMicros();

  const LogContents log = ReadLog(options.output);
  EXPECT_TRUE(log.warnings.empty());
  EXPECT_EQ(Channels(log), (std::vector<std::string>{"cell0/RUN_INFO", "cell0/LOG", "cell0/LOG",
                                                     "cell0/LOG", "cell0/HEARTBEAT"}));
  ASSERT_EQ(log.events.size(), 5u);
  for (size_t i = 1; i < log.events.size(); ++i) {
    EXPECT_EQ(log.events[i].data, sent[i - 1]) << "event " << i;
    EXPECT_GE(log.events[i].timestamp, log.events[i - 1].timestamp) << "event " << i;
    EXPECT_GE(log.events[i].timestamp, before);
    EXPECT_LE(log.events[i].timestamp, after);
  }
  EXPECT_EQ(recorder.stats().events, 5);
}

TEST(Recorder, AllCellsRecordsEveryCell) {
  Harness h;
  RecorderOptions options = h.Recording();
  options.all_cells = true;
  Recorder recorder(h.bus, h.loop, options);
  const std::string line = Encode(LogLine("x"));
  for (const char* channel : {"cell0/LOG", "cell1/LOG", "cell01/PROGRESS"}) {
    h.bus.PublishRaw(bus::Link::kControl, channel, line.data(), line.size());
  }
  ASSERT_TRUE(
      h.loop.RunUntil([&] { return recorder.stats().events == 4; }, std::chrono::seconds(5)));
  recorder.Stop();
  const LogContents log = ReadLog(options.output);
  EXPECT_EQ(Channels(log), (std::vector<std::string>{"cell0/RUN_INFO", "cell0/LOG", "cell1/LOG",
                                                     "cell01/PROGRESS"}));
}

TEST(Recorder, AcknowledgesProductsOnlyOnceTheirChunksAreInTheLog) {
  // A small cap, so every product is several chunks.
  Harness h(16 * 1024);
  const RecorderOptions options = h.Recording();
  Recorder recorder(h.bus, h.loop, options);
  products::SenderOptions sender_options;
  sender_options.required_receivers = {"recorder"};
  sender_options.initial_timeout = milliseconds(50);
  sender_options.max_timeout = milliseconds(200);
  products::ProductSender sender(h.bus, h.loop, sender_options);

  struct Sent {
    std::string name;
    std::string sha256;
    std::string channel;
  };
  std::map<std::string, Sent> sent;  // by product id
  std::vector<std::string> acked_in_order;
  std::vector<std::string> failures;
  const std::vector<std::pair<std::string_view, size_t>> plan = {{channels::kProductImage, 70'001},
                                                                 {channels::kProductCloud, 33'333},
                                                                 {channels::kProductMesh, 5'555}};
  // One at a time, so nothing written after a product's last chunk pushes it out to the file
  // before its acknowledgement: only the recorder's own flush can.
  for (size_t i = 0; i < plan.size(); ++i) {
    const auto [channel, size] = plan[i];
    std::vector<uint8_t> payload = RandomBytes(size, static_cast<uint32_t>(i + 1));
    const std::string sha = Sha256Hex(payload);
    const std::string name = "product_" + std::to_string(i);
    const std::string id = sender.Send(
        channel, name, "avc.test_blob_t", std::move(payload), [&](const products::SendResult& r) {
          if (!r.ok) {
            failures.push_back(r.error);
            return;
          }
          acked_in_order.push_back(r.product_id);
          // At the moment "recorder" acknowledged, every chunk must already be on disk: read
          // the file as it is now and put the product together from it.
          products::Reassembler reassembler;
          bool complete = false;
          LogReader reader(options.output);
          while (const lcm::LogEvent* event = reader.Next()) {
            if (event->channel != "cell0/" + sent.at(r.product_id).channel) continue;
            avc::product_chunk_t chunk{};
            ASSERT_GE(chunk.decode(event->data, 0, event->datalen), 0);
            if (chunk.product_id != r.product_id) continue;
            const auto outcome = reassembler.Add(chunk);
            if (outcome.status == products::Reassembler::Status::kComplete) {
              complete = true;
              EXPECT_EQ(Sha256Hex(outcome.product->payload), sent.at(r.product_id).sha256);
            }
          }
          EXPECT_TRUE(complete) << r.name << " was acknowledged before its chunks were on disk";
        });
    sent[id] = Sent{name, sha, std::string(channel)};
    ASSERT_TRUE(h.loop.RunUntil([&] { return acked_in_order.size() + failures.size() == i + 1; },
                                std::chrono::seconds(10)));
  }
  ASSERT_TRUE(failures.empty()) << failures.front();
  EXPECT_EQ(sender.stats().products_acknowledged, 3);
  EXPECT_EQ(sender.pending(), 0u);
  h.bus.DispatchPending();
  recorder.Stop();

  // In the finished log: every chunk of every product, and each product's COMPLETE ack from
  // "recorder" after its last chunk.
  const LogContents log = ReadLog(options.output);
  EXPECT_TRUE(log.warnings.empty());
  std::map<std::string, size_t> last_chunk_at, first_complete_ack_at;
  std::map<std::string, std::set<int32_t>> chunk_indices;
  std::map<std::string, int32_t> chunk_counts;
  products::Reassembler reassembler;
  std::set<std::string> reassembled;
  for (size_t i = 0; i < log.events.size(); ++i) {
    const LoggedEvent& event = log.events[i];
    if (event.channel.starts_with("cell0/PRODUCT/")) {
      const auto chunk = Decode<avc::product_chunk_t>(event.data);
      ASSERT_TRUE(sent.contains(chunk.product_id)) << chunk.product_id;
      EXPECT_EQ(event.channel, "cell0/" + sent.at(chunk.product_id).channel);
      last_chunk_at[chunk.product_id] = i;
      chunk_indices[chunk.product_id].insert(chunk.chunk_index);
      chunk_counts[chunk.product_id] = chunk.chunk_count;
      const auto outcome = reassembler.Add(chunk);
      if (outcome.status == products::Reassembler::Status::kComplete) {
        EXPECT_EQ(outcome.product->sha256, sent.at(chunk.product_id).sha256);
        EXPECT_EQ(outcome.product->name, sent.at(chunk.product_id).name);
        reassembled.insert(chunk.product_id);
      }
    } else if (event.channel == "cell0/PRODUCT_ACK") {
      const auto ack = Decode<avc::product_ack_t>(event.data);
      EXPECT_EQ(ack.receiver, "recorder");
      if (ack.status == avc::product_ack_t::STATUS_COMPLETE) {
        first_complete_ack_at.emplace(ack.product_id, i);
      }
    }
  }
  EXPECT_EQ(reassembled.size(), 3u);
  for (const auto& [id, info] : sent) {
    ASSERT_TRUE(chunk_counts.contains(id)) << info.name << " has no chunk in the log";
    EXPECT_EQ(chunk_indices[id].size(), static_cast<size_t>(chunk_counts[id])) << info.name;
    ASSERT_TRUE(first_complete_ack_at.contains(id)) << info.name << " has no COMPLETE ack";
    EXPECT_GT(first_complete_ack_at[id], last_chunk_at[id]) << info.name;
  }
  int32_t most_chunks = 0;
  for (const auto& [id, count] : chunk_counts) most_chunks = std::max(most_chunks, count);
  EXPECT_GE(most_chunks, 4) << "the cap should have split the largest product into chunks";
}

// Lowers RLIMIT_FSIZE so writes past a size fail with EFBIG (SIGXFSZ ignored): a full disk
// in miniature. Restores both when lifted or destroyed.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    EXPECT_EQ(sigaction(SIGXFSZ, &ignore, &saved_action_), 0);
    EXPECT_EQ(getrlimit(RLIMIT_FSIZE, &saved_limit_), 0);
    rlimit limited = saved_limit_;
    limited.rlim_cur = bytes;
    active_ = setrlimit(RLIMIT_FSIZE, &limited) == 0;
    EXPECT_TRUE(active_) << std::strerror(errno);
  }
  ~FileSizeLimit() { Lift(); }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  void Lift() {
    if (!active_) return;
    active_ = false;
    setrlimit(RLIMIT_FSIZE, &saved_limit_);
    sigaction(SIGXFSZ, &saved_action_, nullptr);
  }
  bool active() const { return active_; }

 private:
  struct sigaction saved_action_ {};
  rlimit saved_limit_{};
  bool active_ = false;
};

TEST(Recorder, AProductWhoseChunksWereNotWrittenIsNotAcknowledged) {
  Harness h(16 * 1024);
  RecorderOptions options = h.Recording();
  options.flush_interval = std::chrono::seconds(30);  // only product chunks are flushed here
  Recorder recorder(h.bus, h.loop, options);
  products::SenderOptions sender_options;
  sender_options.required_receivers = {"recorder"};
  sender_options.initial_timeout = milliseconds(30);
  sender_options.max_timeout = milliseconds(60);
  products::ProductSender sender(h.bus, h.loop, sender_options);
  // One chunk: it is both the chunk that fails and the one that completes the product, so the
  // recorder must have tried to write it before its receiver sees it.
  std::vector<uint8_t> payload = RandomBytes(5'000, 9);
  const std::string sha = Sha256Hex(payload);

  // The disk "fills up" 100 bytes into the chunk, and is freed once that write failed.
  FileSizeLimit limit(static_cast<rlim_t>(std::filesystem::file_size(options.output) + 100));
  ASSERT_TRUE(limit.active());
  std::optional<products::SendResult> result;
  const std::string id =
      sender.Send(channels::kProductImage, "full_disk", "avc.test_blob_t", std::move(payload),
                  [&](const products::SendResult& r) { result = r; });
  ASSERT_TRUE(h.loop.RunUntil(
      [&] {
        if (limit.active() && recorder.stats().write_errors > 0) limit.Lift();
        return result.has_value();
      },
      std::chrono::seconds(10)));
  limit.Lift();
  ASSERT_TRUE(result->ok) << result->error;
  EXPECT_GE(recorder.stats().write_errors, 1);
  EXPECT_GE(result->attempts, 2) << "acknowledged although a chunk never reached the file";
  h.bus.DispatchPending();
  recorder.Stop();

  // The log: the partly written chunk is reported as damage, and the retransmitted chunks
  // before the first COMPLETE acknowledgement make up the whole product.
  const LogContents log = ReadLog(options.output);
  EXPECT_FALSE(log.warnings.empty());
  products::Reassembler reassembler;
  bool complete = false;
  bool acknowledged = false;
  for (const LoggedEvent& event : log.events) {
    if (event.channel == "cell0/PRODUCT/IMAGE") {
      const auto outcome = reassembler.Add(Decode<avc::product_chunk_t>(event.data));
      if (outcome.status == products::Reassembler::Status::kComplete) {
        EXPECT_EQ(Sha256Hex(outcome.product->payload), sha);
        complete = true;
      }
    } else if (event.channel == "cell0/PRODUCT_ACK") {
      const auto ack = Decode<avc::product_ack_t>(event.data);
      if (ack.product_id == id && ack.status == avc::product_ack_t::STATUS_COMPLETE) {
        EXPECT_TRUE(complete) << "acknowledged before the log held the whole product";
        acknowledged = true;
      }
    }
  }
  EXPECT_TRUE(complete);
  EXPECT_TRUE(acknowledged);
}

TEST(Recorder, FlushesPeriodicallyAndStopLeavesACompleteLog) {
  Harness h;
  RecorderOptions options = h.Recording();
  options.flush_interval = milliseconds(10);
  Recorder recorder(h.bus, h.loop, options);
  EXPECT_EQ(recorder.output(), options.output);
  EXPECT_FALSE(recorder.stopped());

  avc::log_text_t line = LogLine("before the flush");
  h.bus.Publish(channels::kLog, line);
  ASSERT_TRUE(
      h.loop.RunUntil([&] { return recorder.stats().events == 2; }, std::chrono::seconds(5)));
  // Without Stop(): the periodic flush alone must put the event on disk.
  const int64_t flushes = recorder.stats().flushes;
  ASSERT_TRUE(
      h.loop.RunUntil([&] { return recorder.stats().flushes > flushes; }, std::chrono::seconds(5)));
  EXPECT_EQ(ReadLog(options.output).events.size(), 2u);

  int64_t payload_bytes = 0;
  for (int i = 0; i < 50; ++i) {
    line = LogLine(std::string(static_cast<size_t>(100 + i), static_cast<char>('a' + i % 26)));
    h.bus.Publish(channels::kLog, line);
    payload_bytes += line.getEncodedSize();
  }
  ASSERT_TRUE(
      h.loop.RunUntil([&] { return recorder.stats().events == 52; }, std::chrono::seconds(5)));
  const int64_t bytes_before_stop = recorder.stats().bytes;
  recorder.Stop();
  EXPECT_TRUE(recorder.stopped());
  recorder.Stop();  // idempotent

  // Nothing is written once stopped.
  line = LogLine("after stop");
  h.bus.Publish(channels::kLog, line);
  h.bus.DispatchPending();
  EXPECT_EQ(recorder.stats().events, 52);
  EXPECT_EQ(recorder.stats().bytes, bytes_before_stop);
  EXPECT_EQ(recorder.stats().write_errors, 0);

  const LogContents log = ReadLog(options.output);
  EXPECT_TRUE(log.warnings.empty()) << log.warnings.front();
  EXPECT_FALSE(log.truncated);
  EXPECT_EQ(static_cast<int64_t>(log.events.size()), recorder.stats().events);
  int64_t logged_bytes = 0;
  for (const LoggedEvent& event : log.events)
    logged_bytes += static_cast<int64_t>(event.data.size());
  EXPECT_EQ(logged_bytes, recorder.stats().bytes);
  EXPECT_EQ(logged_bytes - static_cast<int64_t>(log.events[0].data.size()) -
                static_cast<int64_t>(log.events[1].data.size()),
            payload_bytes);
  EXPECT_EQ(Decode<avc::log_text_t>(log.events.back().data).text, std::string(149, 'x'));
}

TEST(Recorder, RefusesAnExistingOutputAndNamesIt) {
  Harness h;
  const RecorderOptions options = h.Recording("precious.lcmlog");
  testing::WriteFile(options.output, "an earlier run");
  try {
    Recorder recorder(h.bus, h.loop, options);
    FAIL() << "an existing output was accepted";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find(options.output.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("exists"), std::string::npos) << e.what();
  }
  EXPECT_EQ(testing::ReadFile(options.output), "an earlier run");

  // A second recorder on a log another one is writing is refused as well.
  const RecorderOptions fresh = h.Recording("fresh.lcmlog");
  Recorder first(h.bus, h.loop, fresh);
  EXPECT_THROW(Recorder(h.bus, h.loop, fresh), RecordError);
  first.Stop();
  EXPECT_EQ(ReadLog(fresh.output).events.size(), 1u);

  // A directory that does not exist: the error names the file.
  RecorderOptions nowhere = h.Recording("missing/dir/run.lcmlog");
  try {
    Recorder recorder(h.bus, h.loop, nowhere);
    FAIL() << "a log in a missing directory was accepted";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find(nowhere.output.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace avc::record
