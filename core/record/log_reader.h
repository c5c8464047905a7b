#pragma once

// Reads an LCM log event by event and says where it is damaged. lcm::LogFile alone returns
// nullptr both at the end and at a truncated or corrupt event, drops an intact event that is
// followed by damage, and after a partly written event (a write error in the middle of a
// recording) trusts its length fields and swallows the intact events behind it. This reader
// parses the format itself (docs: lcm-proj/lcm log-file-format.md): it tells the end from a
// truncated last event, resynchronises at the next intact event after damage, and keeps a
// warning per damaged stretch so replay can report what it could not use.

#include <cstdint>
#include <filesystem>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace avc::record {

class LogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class LogReader {
 public:
  // Throws LogError naming the file when it is missing or cannot be opened.
  explicit LogReader(std::filesystem::path path);
  ~LogReader();
  LogReader(const LogReader&) = delete;
  LogReader& operator=(const LogReader&) = delete;

  // The next intact event (valid until the next call), or nullptr at the end of the file.
  const lcm::LogEvent* Next();

  const std::filesystem::path& path() const { return path_; }
  // Intact events returned so far.
  int64_t events() const { return events_; }
  int64_t file_size() const { return file_size_; }
  // One sentence per damaged stretch, naming the file, the event number and the byte offset.
  const std::vector<std::string>& warnings() const { return warnings_; }
  // True when the file ended inside an event (the usual result of a crash while recording).
  bool truncated() const { return truncated_; }

 private:
  enum class Shape { kNoSyncWord, kShortHeader, kBadLengths, kPastEnd, kFits };
  // What starts at offset; *end is where a kFits or kPastEnd event ends.
  Shape ShapeAt(int64_t offset, int64_t* end) const;
  // A complete event at offset whose channel name is printable text: where to resume after
  // damage (a stray sync word inside data almost never passes).
  bool PlausibleAt(int64_t offset) const;
  // Offset of the first sync word in [from, limit), or -1.
  int64_t FindSyncWord(int64_t from, int64_t limit) const;
  // Offset of the first plausible event starting in [from, limit), or -1.
  int64_t FindIntactEvent(int64_t from, int64_t limit) const;
  // The first bytes at offset up to the end of the file are the start of a sync word.
  bool SyncWordCutAt(int64_t offset) const;
  bool ReadAt(int64_t offset, void* out, size_t size) const;
  const lcm::LogEvent* ReadEvent(int64_t offset, int64_t end);

  std::filesystem::path path_;
  int fd_ = -1;
  int64_t offset_ = 0;  // where the next event is expected
  lcm::LogEvent event_{};
  std::vector<uint8_t> data_;
  int64_t file_size_ = 0;
  int64_t events_ = 0;
  std::vector<std::string> warnings_;
  bool truncated_ = false;
  bool done_ = false;
};

}  // namespace avc::record
