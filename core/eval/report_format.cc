#include "core/eval/report_format.h"

#include <fmt/format.h>

namespace avc::eval {

std::string FormatMillimetres(const nlohmann::json& stats, const char* key) {
  const auto it = stats.find(key);
  return it == stats.end() || !it->is_number() ? "-"
                                               : fmt::format("{:.3f}", it->get<double>() * 1e3);
}

std::string FormatPercent(const nlohmann::json& fraction) {
  return fmt::format("{:.1f}", fraction.get<double>() * 100);
}

}  // namespace avc::eval
