#pragma once

// Process log: one line per event on stderr, "<time> <level> <process>: <text>". Thread-safe.
// A sink can be added (the bus mirrors lines on the LOG channel).

#include <fmt/format.h>

#include <functional>
#include <string>
#include <string_view>

namespace avc::log {

enum class Level { kDebug = 0, kInfo = 1, kWarning = 2, kError = 3 };

// Name printed on every line; set once in main.
void SetProcessName(std::string_view name);
const std::string& ProcessName();
void SetMinLevel(Level level);
// An extra destination for every line at or above the minimum level (e.g. the bus).
// Called outside the log lock; must not log itself.
using Sink = std::function<void(Level, const std::string&)>;
void SetSink(Sink sink);

void Write(Level level, std::string_view text);

template <typename... Args>
void Debug(fmt::format_string<Args...> f, Args&&... args) {
  Write(Level::kDebug, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
void Info(fmt::format_string<Args...> f, Args&&... args) {
  Write(Level::kInfo, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
void Warn(fmt::format_string<Args...> f, Args&&... args) {
  Write(Level::kWarning, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
void Error(fmt::format_string<Args...> f, Args&&... args) {
  Write(Level::kError, fmt::format(f, std::forward<Args>(args)...));
}

}  // namespace avc::log
