// LogReader on logs damaged the ways recordings get damaged: cut off by a crash, or with a
// partly written event in the middle (a write error that later cleared).

#include "core/record/log_reader.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <lcm/lcm-cpp.hpp>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace avc::record {
namespace {

namespace fs = std::filesystem;

struct Event {
  std::string channel;
  std::string data;
};

std::vector<Event> TestEvents(int count) {
  std::vector<Event> events;
  for (int i = 0; i < count; ++i) {
    events.push_back({"cell0/CH" + std::to_string(i),
                      std::string(static_cast<size_t>(50 + 37 * i), static_cast<char>('a' + i))});
  }
  return events;
}

// The bytes of one log event as LCM writes it (big-endian fields).
std::string EncodeEvent(int64_t number, int64_t timestamp, const Event& event) {
  std::string bytes;
  auto put = [&bytes](uint64_t value, int size) {
    for (int i = size - 1; i >= 0; --i)
      bytes.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
  };
  put(0xEDA1DA01u, 4);
  put(static_cast<uint64_t>(number), 8);
  put(static_cast<uint64_t>(timestamp), 8);
  put(event.channel.size(), 4);
  put(event.data.size(), 4);
  return bytes + event.channel + event.data;
}

std::vector<Event> ReadAll(const fs::path& path, std::vector<std::string>* warnings,
                           bool* truncated = nullptr) {
  LogReader reader(path);
  std::vector<Event> events;
  while (const lcm::LogEvent* event = reader.Next()) {
    events.push_back({event->channel, std::string(static_cast<const char*>(event->data),
                                                  static_cast<size_t>(event->datalen))});
  }
  EXPECT_EQ(reader.events(), static_cast<int64_t>(events.size()));
  *warnings = reader.warnings();
  if (truncated != nullptr) *truncated = reader.truncated();
  return events;
}

void ExpectSameEvents(const std::vector<Event>& got, const std::vector<Event>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].channel, want[i].channel) << "event " << i;
    EXPECT_EQ(got[i].data, want[i].data) << "event " << i;
  }
}

TEST(LogReader, MatchesWhatLcmWrites) {
  testing::TempDir dir("avc-log-reader");
  const std::vector<Event> events = TestEvents(5);
  std::string expected;
  {
    lcm::LogFile file((dir / "a.lcmlog").string(), "w");
    for (size_t i = 0; i < events.size(); ++i) {
      lcm::LogEvent event{};
      event.timestamp = 1000 + static_cast<int64_t>(i);
      event.channel = events[i].channel;
      event.datalen = static_cast<int32_t>(events[i].data.size());
      event.data = const_cast<char*>(events[i].data.data());
      ASSERT_EQ(file.writeEvent(&event), 0);
      expected += EncodeEvent(static_cast<int64_t>(i), 1000 + static_cast<int64_t>(i), events[i]);
    }
  }
  EXPECT_EQ(testing::ReadFile(dir / "a.lcmlog"), expected);
  std::vector<std::string> warnings;
  bool truncated = true;
  ExpectSameEvents(ReadAll(dir / "a.lcmlog", &warnings, &truncated), events);
  EXPECT_TRUE(warnings.empty());
  EXPECT_FALSE(truncated);
}

// A write error in the middle of an event (full disk, file size limit) leaves its first bytes;
// recording goes on after it. The damaged event's length fields promise more bytes than it
// has, so they cover the intact events that follow: those must still be read.
TEST(LogReader, PartlyWrittenEventInTheMiddleLosesOnlyThatEvent) {
  testing::TempDir dir("avc-log-reader");
  const std::vector<Event> events = TestEvents(12);
  const Event big{"cell0/PRODUCT/IMAGE", std::string(3000, 'p')};
  for (size_t keep : {size_t{2}, size_t{20}, size_t{40}, size_t{500}}) {
    SCOPED_TRACE("damaged event cut after " + std::to_string(keep) + " bytes");
    std::string log;
    for (size_t i = 0; i < 4; ++i) log += EncodeEvent(static_cast<int64_t>(i), 1, events[i]);
    log += EncodeEvent(4, 1, big).substr(0, keep);
    for (size_t i = 4; i < events.size(); ++i) {
      log += EncodeEvent(static_cast<int64_t>(i + 1), 1, events[i]);
    }
    const fs::path path = dir / ("damaged-" + std::to_string(keep) + ".lcmlog");
    testing::WriteFile(path, log);
    std::vector<std::string> warnings;
    bool truncated = true;
    ExpectSameEvents(ReadAll(path, &warnings, &truncated), events);
    EXPECT_FALSE(truncated);
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings[0].find(path.string()), std::string::npos) << warnings[0];
  }
}

std::string EncodeLog(const std::vector<Event>& events, std::vector<int64_t>* offsets = nullptr) {
  std::string log;
  for (size_t i = 0; i < events.size(); ++i) {
    if (offsets != nullptr) offsets->push_back(static_cast<int64_t>(log.size()));
    log += EncodeEvent(static_cast<int64_t>(i), 1000 + static_cast<int64_t>(i), events[i]);
  }
  return log;
}

// A crash while recording: the file ends anywhere inside the last event.
TEST(LogReader, CutAnywhereInTheLastEventIsTruncationNamingIt) {
  testing::TempDir dir("avc-log-reader");
  const std::vector<Event> events = TestEvents(6);
  std::vector<int64_t> offsets;
  const std::string log = EncodeLog(events, &offsets);
  const std::vector<Event> intact(events.begin(), events.end() - 1);
  const fs::path path = dir / "cut.lcmlog";
  for (int64_t size = offsets.back(); size < static_cast<int64_t>(log.size()); ++size) {
    SCOPED_TRACE("cut at byte " + std::to_string(size));
    testing::WriteFile(path, log.substr(0, static_cast<size_t>(size)));
    std::vector<std::string> warnings;
    bool truncated = false;
    ExpectSameEvents(ReadAll(path, &warnings, &truncated), intact);
    if (size == offsets.back()) {
      // Cut exactly between two events: a shorter log, nothing to warn about.
      EXPECT_TRUE(warnings.empty());
      EXPECT_FALSE(truncated);
      continue;
    }
    EXPECT_TRUE(truncated);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find(fmt::format("{}: event 5 at byte {} is truncated: the file ends {} "
                                           "bytes into it",
                                           path.string(), offsets.back(), size - offsets.back())),
              std::string::npos)
        << warnings[0];
  }
}

TEST(LogReader, GarbageBeforeBetweenAndAfterEventsIsSkippedWithWarnings) {
  testing::TempDir dir("avc-log-reader");
  const std::vector<Event> events = TestEvents(4);
  std::string log = "junk before";
  log += EncodeEvent(0, 1, events[0]);
  log += EncodeEvent(1, 1, events[1]);
  log += std::string("\xED\xA1\xDA", 3) + "junk between";  // with half a sync word
  log += EncodeEvent(2, 1, events[2]);
  // A sync word with impossible lengths.
  log += std::string("\xED\xA1\xDA\x01", 4) + std::string(16, '\0') + std::string(8, '\xff');
  log += EncodeEvent(3, 1, events[3]);
  log += "junk after, long enough to be more than a sync word";
  const fs::path path = dir / "junk.lcmlog";
  testing::WriteFile(path, log);
  std::vector<std::string> warnings;
  bool truncated = true;
  ExpectSameEvents(ReadAll(path, &warnings, &truncated), events);
  EXPECT_FALSE(truncated);
  ASSERT_EQ(warnings.size(), 4u);
  EXPECT_NE(warnings[0].find("skipped 11 bytes of damaged data at byte 0 before event 0"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find("before event 2"), std::string::npos) << warnings[1];
  EXPECT_NE(warnings[2].find("event 3 at byte"), std::string::npos) << warnings[2];
  EXPECT_NE(warnings[3].find("are not an LCM event; the 4 events before them are intact"),
            std::string::npos)
      << warnings[3];

  // Text with no event at all.
  testing::WriteFile(path, "not a log\n");
  ExpectSameEvents(ReadAll(path, &warnings, &truncated), {});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("the last 10 bytes (from byte 0) are not an LCM event"),
            std::string::npos)
      << warnings[0];
}

TEST(LogReader, MissingFileIsAnErrorNamingIt) {
  testing::TempDir dir("avc-log-reader");
  try {
    LogReader reader(dir / "nope.lcmlog");
    FAIL() << "no error for a missing log";
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "nope.lcmlog").string()), std::string::npos);
  }
  EXPECT_THROW(LogReader reader(dir.path()), LogError);
}

}  // namespace
}  // namespace avc::record
