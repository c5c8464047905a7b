#include "core/util/log.h"

#include <chrono>
#include <cstdio>
#include <mutex>

namespace avc::log {
namespace {

struct State {
  std::mutex mutex;
  std::string process = "avc";
  Level min_level = Level::kInfo;
  Sink sink;
};

State& GetState() {
  static State state;
  return state;
}

const char* LevelName(Level level) {
  switch (level) {
    case Level::kDebug:
      return "DEBUG";
    case Level::kInfo:
      return "INFO";
    case Level::kWarning:
      return "WARN";
    case Level::kError:
      return "ERROR";
  }
  return "?";
}

}  // namespace

void SetProcessName(std::string_view name) {
  std::lock_guard lock(GetState().mutex);
  GetState().process = std::string(name);
}

const std::string& ProcessName() { return GetState().process; }

void SetMinLevel(Level level) {
  std::lock_guard lock(GetState().mutex);
  GetState().min_level = level;
}

void SetSink(Sink sink) {
  std::lock_guard lock(GetState().mutex);
  GetState().sink = std::move(sink);
}

void Write(Level level, std::string_view text) {
  State& state = GetState();
  Sink sink;
  {
    std::lock_guard lock(state.mutex);
    if (level < state.min_level) return;
    const auto now = std::chrono::system_clock::now();
    const auto ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count();
    const std::time_t seconds = static_cast<std::time_t>(ms / 1000);
    std::tm tm{};
    localtime_r(&seconds, &tm);
    std::fprintf(stderr, "%02d:%02d:%02d.%03d %-5s %s: %.*s\n", tm.tm_hour, tm.tm_min, tm.tm_sec,
                 static_cast<int>(ms % 1000), LevelName(level), state.process.c_str(),
                 static_cast<int>(text.size()), text.data());
    std::fflush(stderr);
    sink = state.sink;
  }
  if (sink) sink(level, std::string(text));
}

}  // namespace avc::log
