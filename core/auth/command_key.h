#pragma once

// A cell's motion-command key: 32 random bytes, kept as 64 hex digits in a file that only its
// owner may read. Every machine that sends or obeys motion commands for the cell holds a copy;
// anyone else on the network can hear the commands but cannot make one the drivers accept.
//
// Where a cell's key lives unless a --key flag names the file:
//   $AVC_KEY_DIR/<cell>.key, else $XDG_CONFIG_HOME/avc/keys/<cell>.key, else
//   $HOME/.config/avc/keys/<cell>.key

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace avc::auth {

// A key file that is missing, readable by others, or malformed; the message names the file
// and says what to do.
class KeyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CommandKey {
  std::array<uint8_t, 32> bytes{};
  std::filesystem::path file;  // where it was read from (empty for a key made in memory)
};

std::filesystem::path DefaultKeyFile(std::string_view cell);

// Reads and checks a key file: a regular file, no permission bits for group or others, owned by
// this user, 64 hex digits (a trailing newline is allowed). Throws KeyError.
CommandKey LoadCommandKey(const std::filesystem::path& file);

// The key at DefaultKeyFile(cell), or nullopt when there is no file there. Throws KeyError for a
// file that exists but is unusable (a key with the wrong permissions is never used).
std::optional<CommandKey> FindCommandKey(std::string_view cell);

// A new random key (OpenSSL's RAND_bytes) written to `file` with mode 0600, its folder created
// with mode 0700 if missing. Never overwrites: throws KeyError when the file exists.
CommandKey GenerateCommandKey(const std::filesystem::path& file);

// The key in `file`, made there first if there is none (for simulated cells, which own theirs).
CommandKey LoadOrGenerateCommandKey(const std::filesystem::path& file);

}  // namespace avc::auth
