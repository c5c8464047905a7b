#pragma once

// Signed motion commands (robot_command_t, turntable_command_t). The sender puts a strictly
// increasing counter and an HMAC-SHA256 into the command's auth fields; the driver accepts the
// command only if the MAC checks out with the cell's key, the counter is above the last one it
// accepted from that sender, and the counter (microseconds of the sender's clock) is within a
// window of its own clock, so a recorded command cannot be replayed, not even after the driver
// restarted.
//
// The MAC covers a domain tag, the full channel ("<cell>/ROBOT_COMMAND": a command signed for
// one cell or device is worthless on another) and the whole command as LCM encodes it, with
// header.utime, header.seq and the MAC itself cleared (the bus stamps the first two when it
// publishes). header.source and header.cell are covered: the signer sets them to what the bus
// will stamp, and the counters are kept per source.

#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/auth/command_key.h"
#include "core/util/clock.h"

namespace avc::auth {

using Mac = std::array<uint8_t, 32>;

Mac CommandMac(const CommandKey& key, std::string_view full_channel,
               const std::vector<uint8_t>& canonical_command);

// The bytes the MAC covers: the command encoded with utime, seq and the MAC cleared.
template <class Command>
std::vector<uint8_t> CanonicalBytes(Command command) {
  command.header.utime = 0;
  command.header.seq = 0;
  command.auth_size = 0;
  command.auth_mac.clear();
  std::vector<uint8_t> bytes(static_cast<size_t>(command.getEncodedSize()));
  command.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

class CommandSigner {
 public:
  // `source` and `cell` as the sender's bus stamps them (Bus::options().source, Bus::cell()).
  CommandSigner(CommandKey key, std::string source, std::string cell, const Clock* clock = nullptr);

  // Signs `command` for publication on `full_channel`. Every call takes a new counter, so a
  // re-sent command is signed again.
  template <class Command>
  void Sign(Command& command, std::string_view full_channel) {
    command.header.source = source_;
    command.header.cell = cell_;
    command.auth_counter = NextCounter();
    const Mac mac = CommandMac(key_, full_channel, CanonicalBytes(command));
    command.auth_mac.assign(mac.begin(), mac.end());
    command.auth_size = static_cast<int32_t>(command.auth_mac.size());
  }

 private:
  // max(last + 1, the clock's microseconds): increasing within a run and across restarts.
  int64_t NextCounter();

  CommandKey key_;
  std::string source_;
  std::string cell_;
  SystemClock system_clock_;
  const Clock* clock_;
  int64_t last_counter_ = 0;
};

struct VerifierOptions {
  std::optional<CommandKey> key;  // required unless allow_unsigned
  // Accept unsigned commands (signed ones are still checked when a key is loaded). For a cell
  // on a network nobody else uses; a driver logs a warning at start-up.
  bool allow_unsigned = false;
  // How far a counter may be from this machine's clock (the cell's machines need synchronised
  // clocks, e.g. NTP). 0 disables the check.
  std::chrono::seconds window{120};

  // Empty when usable.
  std::string Validate() const;
};

class CommandVerifier {
 public:
  // Checks commands arriving on `full_channel` for the bus's `cell`.
  CommandVerifier(VerifierOptions options, std::string full_channel, std::string cell,
                  const Clock* clock = nullptr);

  // Empty when the command may be obeyed, else why not (for the refusal and the log). A command
  // that passes advances its sender's counter. A stop needs no signature (stopping must always
  // be possible); a signed one is still checked.
  template <class Command>
  std::string Check(const Command& command, bool signature_optional = false) {
    return CheckFields(command.header.cell, command.header.source, command.auth_counter,
                       command.auth_mac, signature_optional,
                       [&] { return CanonicalBytes(command); });
  }

  // What a driver logs at start-up: the key in use, or a warning for unsigned operation.
  std::string StartupLine() const;
  void LogStartup(std::string_view service) const;
  bool requires_signature() const { return !options_.allow_unsigned; }
  int64_t rejected() const { return rejected_; }

 private:
  template <class Bytes>
  std::string CheckFields(const std::string& cell, const std::string& source, int64_t counter,
                          const std::vector<uint8_t>& mac, bool signature_optional,
                          const Bytes& canonical) {
    std::string why = CheckUnsignedParts(cell, mac, signature_optional);
    if (why.empty() && !mac.empty() && options_.key) {
      why = CheckSignature(source, counter, mac, canonical());
    }
    if (!why.empty()) ++rejected_;
    return why;
  }
  std::string CheckUnsignedParts(const std::string& cell, const std::vector<uint8_t>& mac,
                                 bool signature_optional) const;
  std::string CheckSignature(const std::string& source, int64_t counter,
                             const std::vector<uint8_t>& mac, const std::vector<uint8_t>& bytes);

  VerifierOptions options_;
  std::string channel_;
  std::string cell_;
  SystemClock system_clock_;
  const Clock* clock_;
  std::map<std::string, int64_t> last_counter_;  // by sender; only senders holding the key
  int64_t rejected_ = 0;
};

}  // namespace avc::auth
