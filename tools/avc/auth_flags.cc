#include "tools/avc/auth_flags.h"

#include <fmt/format.h>

#include <stdexcept>

namespace avc::cli {

void AddSenderKeyFlag(CLI::App* command, AuthFlags* flags) {
  command
      ->add_option("--key", flags->key_file,
                   "the cell's motion-command key (default: $AVC_KEY_DIR/<cell>.key, else "
                   "~/.config/avc/keys/<cell>.key; make one with `avc key generate`)")
      ->group("Authentication");
}

void AddDriverAuthFlags(CLI::App* command, AuthFlags* flags) {
  AddSenderKeyFlag(command, flags);
  command
      ->add_flag("--allow-unsigned", flags->allow_unsigned,
                 "also obey unsigned motion commands (anyone on the network could move the "
                 "hardware; logged as a warning)")
      ->group("Authentication");
  command
      ->add_option("--auth-window-s", flags->window_s,
                   "largest difference between a command's counter (the sender's clock) and this "
                   "machine's clock, s; 0 = no limit")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber)
      ->group("Authentication");
}

std::optional<auth::CommandKey> SenderKey(const AuthFlags& flags, const std::string& cell) {
  if (!flags.key_file.empty()) return auth::LoadCommandKey(flags.key_file);
  return auth::FindCommandKey(cell);
}

auth::VerifierOptions DriverAuth(const AuthFlags& flags, const std::string& cell) {
  auth::VerifierOptions options;
  options.allow_unsigned = flags.allow_unsigned;
  options.window = std::chrono::seconds(flags.window_s);
  options.key = SenderKey(flags, cell);
  if (!options.key && !options.allow_unsigned) {
    throw std::runtime_error(fmt::format(
        "no motion-command key for cell '{}' at {}: make one with `avc key generate --cell {}` "
        "and copy it (mode 600) to every machine of the cell, give it with --key FILE, or run "
        "with --allow-unsigned on a network nobody else uses",
        cell, auth::DefaultKeyFile(cell).string(), cell));
  }
  return options;
}

}  // namespace avc::cli
