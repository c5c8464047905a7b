#pragma once

// The motion-command key flags: drivers take --key, --allow-unsigned and --auth-window-s; the
// programs that send motion commands (avc scan, avc calibrate) take --key.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "core/auth/command_auth.h"

namespace avc::cli {

struct AuthFlags {
  std::string key_file;  // "" = the cell's default key file
  bool allow_unsigned = false;
  int window_s = 120;
};

void AddDriverAuthFlags(CLI::App* command, AuthFlags* flags);
void AddSenderKeyFlag(CLI::App* command, AuthFlags* flags);

// A driver's verifier options for `cell`. Throws std::runtime_error saying how to make a key
// when none is found and unsigned commands are not allowed.
auth::VerifierOptions DriverAuth(const AuthFlags& flags, const std::string& cell);

// The key a sender signs with: --key, else the cell's default key file if it exists, else none.
std::optional<auth::CommandKey> SenderKey(const AuthFlags& flags, const std::string& cell);

}  // namespace avc::cli
