#include "core/auth/command_auth.h"

#include <fmt/format.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "core/util/log.h"

namespace avc::auth {
namespace {

// Versioned, so a later change of what is covered can never verify as this one.
constexpr std::string_view kDomain = "avc-motion-command-v1";

}  // namespace

Mac CommandMac(const CommandKey& key, std::string_view full_channel,
               const std::vector<uint8_t>& canonical_command) {
  // Length-prefixed parts: no two (channel, command) pairs give the same input.
  std::vector<uint8_t> input;
  auto append = [&input](const uint8_t* data, size_t size) {
    for (int shift = 24; shift >= 0; shift -= 8) input.push_back(uint8_t(size >> shift));
    input.insert(input.end(), data, data + size);
  };
  append(reinterpret_cast<const uint8_t*>(kDomain.data()), kDomain.size());
  append(reinterpret_cast<const uint8_t*>(full_channel.data()), full_channel.size());
  append(canonical_command.data(), canonical_command.size());
  Mac mac{};
  unsigned int size = 0;
  if (HMAC(EVP_sha256(), key.bytes.data(), static_cast<int>(key.bytes.size()), input.data(),
           input.size(), mac.data(), &size) == nullptr ||
      size != mac.size()) {
    throw std::runtime_error("HMAC-SHA256 failed in OpenSSL");
  }
  return mac;
}

CommandSigner::CommandSigner(CommandKey key, std::string source, std::string cell,
                             const Clock* clock)
    : key_(std::move(key)),
      source_(std::move(source)),
      cell_(std::move(cell)),
      clock_(clock ? clock : &system_clock_) {}

int64_t CommandSigner::NextCounter() {
  last_counter_ = std::max(last_counter_ + 1, clock_->NowMicros());
  return last_counter_;
}

std::string VerifierOptions::Validate() const {
  if (!key && !allow_unsigned) {
    return "no command key: motion commands must be signed (give the cell's key, or allow "
           "unsigned commands explicitly)";
  }
  if (window.count() < 0) return "the counter window must be >= 0 s";
  return {};
}

CommandVerifier::CommandVerifier(VerifierOptions options, std::string full_channel,
                                 std::string cell, const Clock* clock)
    : options_(std::move(options)),
      channel_(std::move(full_channel)),
      cell_(std::move(cell)),
      clock_(clock ? clock : &system_clock_) {
  if (const std::string problem = options_.Validate(); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
}

std::string CommandVerifier::StartupLine() const {
  if (options_.allow_unsigned) {
    return fmt::format(
        "WARNING: unsigned motion commands are accepted on {} (--allow-unsigned): anyone on "
        "this network can move the hardware{}",
        channel_, options_.key ? "; signed ones are still checked" : "");
  }
  return fmt::format("motion commands on {} must be signed with the key {}", channel_,
                     options_.key->file.empty() ? "given in memory" : options_.key->file.string());
}

void CommandVerifier::LogStartup(std::string_view service) const {
  if (options_.allow_unsigned) {
    log::Warn("{}: {}", service, StartupLine());
  } else {
    log::Info("{}: {}", service, StartupLine());
  }
}

std::string CommandVerifier::CheckUnsignedParts(const std::string& cell,
                                                const std::vector<uint8_t>& mac,
                                                bool signature_optional) const {
  if (cell != cell_) {
    return fmt::format("command for cell '{}' arrived on cell '{}' ({})", cell, cell_, channel_);
  }
  if (mac.empty()) {
    return options_.allow_unsigned || signature_optional
               ? ""
               : fmt::format(
                     "unsigned command: cell '{}' takes only signed motion commands (the "
                     "sender needs the cell's key, see `avc key --help`)",
                     cell_);
  }
  if (mac.size() != Mac().size()) {
    return fmt::format("signature of {} bytes (HMAC-SHA256 has {})", mac.size(), Mac().size());
  }
  return {};
}

std::string CommandVerifier::CheckSignature(const std::string& source, int64_t counter,
                                            const std::vector<uint8_t>& mac,
                                            const std::vector<uint8_t>& bytes) {
  const Mac expected = CommandMac(*options_.key, channel_, bytes);
  if (CRYPTO_memcmp(expected.data(), mac.data(), expected.size()) != 0) {
    return fmt::format("bad signature from '{}': forged, altered, or signed with another key",
                       source);
  }
  const auto last = last_counter_.find(source);
  if (last != last_counter_.end() && counter <= last->second) {
    return fmt::format("replayed command from '{}': counter {} is not above the last accepted {}",
                       source, counter, last->second);
  }
  const int64_t window_us = options_.window.count() * 1000000;
  const int64_t offset_us = counter - clock_->NowMicros();
  if (window_us > 0 && std::llabs(offset_us) > window_us) {
    return fmt::format(
        "stale command from '{}': its counter is {:.1f} s from this driver's clock (window {} "
        "s; replayed, or the machines' clocks differ)",
        source, offset_us * 1e-6, options_.window.count());
  }
  last_counter_[source] = counter;
  return {};
}

}  // namespace avc::auth
