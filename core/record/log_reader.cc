#include "core/record/log_reader.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>

namespace avc::record {
namespace {

// Every event starts with this sync word, then eventnum, timestamp, channel and data lengths,
// all big-endian (docs: lcm-proj/lcm log-file-format.md).
constexpr std::array<uint8_t, 4> kMagic = {0xED, 0xA1, 0xDA, 0x01};
constexpr int64_t kEventHeaderBytes = 4 + 8 + 8 + 4 + 4;
// lcm::LogFile's own sanity limit on channel names.
constexpr int32_t kMaxChannelBytes = 1000;

uint64_t BigEndian(const uint8_t* bytes, int size) {
  uint64_t value = 0;
  for (int i = 0; i < size; ++i) value = (value << 8) | bytes[i];
  return value;
}

}  // namespace

LogReader::LogReader(std::filesystem::path path) : path_(std::move(path)) {
  std::error_code error;
  const auto status = std::filesystem::status(path_, error);
  if (!std::filesystem::exists(status)) {
    throw LogError(fmt::format("{}: no such file", path_.string()));
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw LogError(fmt::format("{}: not a regular file", path_.string()));
  }
  fd_ = open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) {
    throw LogError(fmt::format("{}: cannot open: {}", path_.string(), std::strerror(errno)));
  }
}

LogReader::~LogReader() {
  if (fd_ >= 0) close(fd_);
}

bool LogReader::ReadAt(int64_t offset, void* out, size_t size) const {
  auto* bytes = static_cast<uint8_t*>(out);
  size_t done = 0;
  while (done < size) {
    const ssize_t n = pread(fd_, bytes + done, size - done, offset + static_cast<int64_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

LogReader::Shape LogReader::ShapeAt(int64_t offset, int64_t* end) const {
  std::array<uint8_t, kEventHeaderBytes> header{};
  const int64_t available = std::min<int64_t>(kEventHeaderBytes, file_size_ - offset);
  if (available < 4 || !ReadAt(offset, header.data(), static_cast<size_t>(available)) ||
      !std::equal(kMagic.begin(), kMagic.end(), header.begin())) {
    return Shape::kNoSyncWord;
  }
  if (available < kEventHeaderBytes) return Shape::kShortHeader;
  const auto channel_bytes = static_cast<int32_t>(BigEndian(header.data() + 20, 4));
  const auto data_bytes = static_cast<int32_t>(BigEndian(header.data() + 24, 4));
  if (channel_bytes <= 0 || channel_bytes >= kMaxChannelBytes || data_bytes < 0) {
    return Shape::kBadLengths;
  }
  *end = offset + kEventHeaderBytes + channel_bytes + data_bytes;
  return *end <= file_size_ ? Shape::kFits : Shape::kPastEnd;
}

bool LogReader::SyncWordCutAt(int64_t offset) const {
  const int64_t left = file_size_ - offset;
  if (left <= 0 || left >= 4) return false;
  std::array<uint8_t, 4> word{};
  return ReadAt(offset, word.data(), static_cast<size_t>(left)) &&
         std::equal(word.begin(), word.begin() + left, kMagic.begin());
}

bool LogReader::PlausibleAt(int64_t offset) const {
  int64_t end = 0;
  if (ShapeAt(offset, &end) != Shape::kFits) return false;
  std::array<uint8_t, kEventHeaderBytes> header{};
  if (!ReadAt(offset, header.data(), header.size())) return false;
  std::vector<uint8_t> channel(static_cast<size_t>(BigEndian(header.data() + 20, 4)));
  return ReadAt(offset + kEventHeaderBytes, channel.data(), channel.size()) &&
         std::all_of(channel.begin(), channel.end(),
                     [](uint8_t c) { return c >= 0x20 && c < 0x7f; });
}

int64_t LogReader::FindSyncWord(int64_t from, int64_t limit) const {
  // Blocks overlap by three bytes so a sync word across a block boundary is found.
  constexpr int64_t kBlock = 64 * 1024;
  std::vector<uint8_t> block(static_cast<size_t>(kBlock) + kMagic.size() - 1);
  for (int64_t start = from; start < limit; start += kBlock) {
    const int64_t want = std::min<int64_t>(static_cast<int64_t>(block.size()), file_size_ - start);
    if (want < static_cast<int64_t>(kMagic.size()) ||
        !ReadAt(start, block.data(), static_cast<size_t>(want))) {
      return -1;
    }
    const auto last = block.begin() + want;
    const auto it = std::search(block.begin(), last, kMagic.begin(), kMagic.end());
    if (it == last) continue;
    const int64_t found = start + (it - block.begin());
    return found < limit ? found : -1;
  }
  return -1;
}

int64_t LogReader::FindIntactEvent(int64_t from, int64_t limit) const {
  for (int64_t at = FindSyncWord(from, limit); at >= 0; at = FindSyncWord(at + 1, limit)) {
    if (PlausibleAt(at)) return at;
  }
  return -1;
}

const lcm::LogEvent* LogReader::ReadEvent(int64_t offset, int64_t end) {
  std::array<uint8_t, kEventHeaderBytes> header{};
  if (!ReadAt(offset, header.data(), header.size())) return nullptr;
  const auto channel_size = static_cast<size_t>(BigEndian(header.data() + 20, 4));
  data_.resize(static_cast<size_t>(end - offset - kEventHeaderBytes));  // channel, then data
  if (!ReadAt(offset + kEventHeaderBytes, data_.data(), data_.size())) return nullptr;
  event_.eventnum = static_cast<int64_t>(BigEndian(header.data() + 4, 8));
  event_.timestamp = static_cast<int64_t>(BigEndian(header.data() + 12, 8));
  event_.channel.assign(reinterpret_cast<const char*>(data_.data()), channel_size);
  event_.datalen = static_cast<int32_t>(data_.size() - channel_size);
  event_.data = data_.data() + channel_size;
  offset_ = end;
  ++events_;
  return &event_;
}

const lcm::LogEvent* LogReader::Next() {
  auto truncated_at = [this](int64_t start) {
    truncated_ = true;
    warnings_.push_back(fmt::format(
        "{}: event {} at byte {} is truncated: the file ends {} bytes into it; the {} events "
        "before it are intact",
        path_.string(), events_, start, file_size_ - start, events_));
  };
  auto not_an_event_from = [this](int64_t start) {
    warnings_.push_back(fmt::format(
        "{}: the last {} bytes (from byte {}) are not an LCM event; the {} events before them "
        "are intact",
        path_.string(), file_size_ - start, start, events_));
  };
  while (!done_) {
    // Taken afresh each time, so a log that is still being written can be followed.
    struct stat info {};
    file_size_ = fstat(fd_, &info) == 0 ? static_cast<int64_t>(info.st_size) : 0;
    const int64_t start = offset_;
    if (start >= file_size_) break;  // clean end
    int64_t end = 0;
    const Shape shape = ShapeAt(start, &end);
    if (shape == Shape::kFits) {
      int64_t ignored = 0;
      const bool followed_well =
          end == file_size_ || ShapeAt(end, &ignored) != Shape::kNoSyncWord || SyncWordCutAt(end);
      // Damaged bytes after it: either it is intact and the damage follows, or it was cut
      // short and its lengths run over intact events. An event found inside it tells.
      const int64_t inside = followed_well ? -1 : FindIntactEvent(start + 1, end);
      if (inside < 0) {
        if (const lcm::LogEvent* event = ReadEvent(start, end)) return event;
        warnings_.push_back(fmt::format("{}: cannot read event {} at byte {}: {}", path_.string(),
                                        events_, start, std::strerror(errno)));
        break;
      }
      warnings_.push_back(fmt::format(
          "{}: event {} at byte {} is damaged (cut short, its lengths run over the next event); "
          "skipped {} bytes to the next intact event",
          path_.string(), events_, start, inside - start));
      offset_ = inside;
      continue;
    }
    if (shape == Shape::kNoSyncWord) {
      if (SyncWordCutAt(start)) {
        truncated_at(start);
        break;
      }
      int64_t next = FindIntactEvent(start + 1, file_size_);
      if (next < 0) next = FindSyncWord(start + 1, file_size_);  // a truncated event, perhaps
      if (next < 0) {
        not_an_event_from(start);
        break;
      }
      warnings_.push_back(
          fmt::format("{}: skipped {} bytes of damaged data at byte {} before event {}",
                      path_.string(), next - start, start, events_));
      offset_ = next;
      continue;
    }
    // A sync word, but no complete event after it: damage if an intact event follows,
    // otherwise the end of the file cut it off (or it is not an event at all).
    const int64_t next = FindIntactEvent(start + 1, file_size_);
    if (next >= 0) {
      warnings_.push_back(fmt::format(
          "{}: event {} at byte {} is damaged ({}); skipped {} bytes to the next intact event",
          path_.string(), events_, start,
          shape == Shape::kBadLengths ? "impossible lengths" : "cut short", next - start));
      offset_ = next;
      continue;
    }
    if (shape == Shape::kBadLengths) {
      not_an_event_from(start);
    } else {
      truncated_at(start);
    }
    break;
  }
  done_ = true;
  return nullptr;
}

}  // namespace avc::record
