#pragma once

// Where a process's bus traffic goes: the control URL, the bulk URL and the cell id. Resolved
// from command-line flags, then the environment, then defaults.

#include <cstddef>
#include <optional>
#include <string>

namespace avc::bus {

inline constexpr char kDefaultControlUrl[] = "udpm://239.255.76.67:7667?ttl=0";
// Receivers of multi-MB products need a large socket buffer (the kernel caps it at
// net.core.rmem_max).
inline constexpr char kDefaultBulkUrl[] = "udpm://239.255.76.67:7668?ttl=0&recv_buf_size=4194304";
inline constexpr char kDefaultCell[] = "cell0";
// LCM silently drops messages over 256 MiB and multi-MB datagrams are fragile; products are
// chunked below this cap.
inline constexpr size_t kDefaultMaxMessageBytes = 8'000'000;

struct BusOptions {
  std::string control_url = kDefaultControlUrl;
  // Equal to control_url (or empty) means one LCM instance carries both.
  std::string bulk_url = kDefaultBulkUrl;
  std::string cell = kDefaultCell;
  // Identity written into every header: "<service>@<host>" unless set.
  std::string source;
  size_t max_message_bytes = kDefaultMaxMessageBytes;

  // Empty when valid; otherwise a sentence naming the bad field.
  std::string Validate() const;
};

// Values given on the command line (unset = not given).
struct BusFlags {
  std::optional<std::string> lcm_url;
  std::optional<std::string> bulk_url;
  std::optional<std::string> cell;
};

// Flags win over AVC_LCM_URL / AVC_BULK_URL / AVC_CELL, which win over LCM_DEFAULT_URL (control
// only) and the defaults above. Throws std::invalid_argument naming the source of a bad value.
BusOptions ResolveBusOptions(const BusFlags& flags, const std::string& service);

// Both URLs on one in-process queue: for tests and single-process replay.
BusOptions InProcessBusOptions(const std::string& cell = kDefaultCell,
                               const std::string& source = "test");

// Cell ids are 1-16 characters of [a-z0-9_-].
bool IsValidCellId(const std::string& cell);

}  // namespace avc::bus
