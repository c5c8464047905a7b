#include "core/bus/bus_options.h"

#include <cstdlib>
#include <stdexcept>

#include "core/util/host.h"

namespace avc::bus {
namespace {

std::optional<std::string> Env(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return std::nullopt;
  return std::string(value);
}

bool IsKnownProvider(const std::string& url) {
  for (const char* scheme : {"udpm://", "memq://", "file://", "tcpq://"}) {
    if (url.rfind(scheme, 0) == 0) return true;
  }
  return false;
}

}  // namespace

bool IsValidCellId(const std::string& cell) {
  if (cell.empty() || cell.size() > 16) return false;
  for (char c : cell) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

std::string BusOptions::Validate() const {
  if (!IsValidCellId(cell)) {
    return "cell id '" + cell + "' is invalid: use 1-16 characters of a-z, 0-9, '_' or '-'";
  }
  if (!IsKnownProvider(control_url)) {
    return "control URL '" + control_url +
           "' is not an LCM URL (udpm://, memq://, file://, tcpq://)";
  }
  if (!bulk_url.empty() && !IsKnownProvider(bulk_url)) {
    return "bulk URL '" + bulk_url + "' is not an LCM URL (udpm://, memq://, file://, tcpq://)";
  }
  if (max_message_bytes < 4096) return "max_message_bytes must be at least 4096";
  return "";
}

BusOptions ResolveBusOptions(const BusFlags& flags, const std::string& service) {
  BusOptions options;
  if (flags.lcm_url) {
    options.control_url = *flags.lcm_url;
  } else if (auto env = Env("AVC_LCM_URL")) {
    options.control_url = *env;
  } else if (auto lcm_env = Env("LCM_DEFAULT_URL")) {
    options.control_url = *lcm_env;
  }
  if (flags.bulk_url) {
    options.bulk_url = *flags.bulk_url;
  } else if (auto env = Env("AVC_BULK_URL")) {
    options.bulk_url = *env;
  }
  if (flags.cell) {
    options.cell = *flags.cell;
  } else if (auto env = Env("AVC_CELL")) {
    options.cell = *env;
  }
  options.source = service + "@" + HostName();
  if (const std::string error = options.Validate(); !error.empty()) {
    const bool from_flags = flags.lcm_url || flags.bulk_url || flags.cell;
    throw std::invalid_argument(error + (from_flags ? " (from the command line)"
                                                    : " (from AVC_LCM_URL/AVC_BULK_URL/AVC_CELL)"));
  }
  return options;
}

BusOptions InProcessBusOptions(const std::string& cell, const std::string& source) {
  BusOptions options;
  options.control_url = "memq://";
  options.bulk_url = "";
  options.cell = cell;
  options.source = source;
  return options;
}

}  // namespace avc::bus
