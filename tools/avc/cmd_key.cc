// avc key: the cell's motion-command key (core/auth/command_key.h). `generate` makes one,
// `path` says where a cell's key is looked for, `check` tells whether a key file is usable.

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "core/auth/command_key.h"
#include "core/bus/bus_options.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct KeyArgs {
  std::optional<std::string> cell;
  std::string file;
};

std::string CellOf(const KeyArgs& args) {
  bus::BusFlags flags;
  flags.cell = args.cell;
  return bus::ResolveBusOptions(flags, "avc-key").cell;
}

std::filesystem::path FileOf(const KeyArgs& args) {
  return args.file.empty() ? auth::DefaultKeyFile(CellOf(args)) : std::filesystem::path(args.file);
}

void AddKeyOptions(CLI::App* command, KeyArgs* args) {
  command->add_option("--cell", args->cell, "cell id (default: $AVC_CELL, else cell0)");
  command->add_option("--file", args->file,
                      "the key file (default: $AVC_KEY_DIR/<cell>.key, else "
                      "~/.config/avc/keys/<cell>.key)");
}

}  // namespace

void RegisterKey(CLI::App& root, int* exit_code) {
  CLI::App* key = root.add_subcommand(
      "key",
      "The cell's motion-command key. The drivers obey robot and turntable commands only when\n"
      "they are signed with it (HMAC-SHA256 with a strictly increasing counter), so nothing\n"
      "else on the network can move the hardware. Make one key per cell, copy the file with\n"
      "mode 600 to every machine of the cell that runs a driver or sends motion commands\n"
      "(avc scan, avc calibrate), and keep it private.\n"
      "  avc key generate --cell cell1      then: scp -p the file it names to the other machines");
  key->require_subcommand(1);

  auto generate_args = std::make_shared<KeyArgs>();
  CLI::App* generate = key->add_subcommand("generate", "Make a new random key (never overwrites)");
  AddKeyOptions(generate, generate_args.get());
  SetGuardedRun(generate, exit_code, [generate_args] {
    const auth::CommandKey made = auth::GenerateCommandKey(FileOf(*generate_args));
    std::cout << "wrote the motion-command key " << made.file.string() << " (mode 600)\n";
    return 0;
  });

  auto path_args = std::make_shared<KeyArgs>();
  CLI::App* path = key->add_subcommand("path", "Print where the cell's key is looked for");
  path->add_option("--cell", path_args->cell, "cell id (default: $AVC_CELL, else cell0)");
  SetGuardedRun(path, exit_code, [path_args] {
    std::cout << auth::DefaultKeyFile(CellOf(*path_args)).string() << "\n";
    return 0;
  });

  auto check_args = std::make_shared<KeyArgs>();
  CLI::App* check =
      key->add_subcommand("check", "Check that the key file is usable (exit 1 if not)");
  AddKeyOptions(check, check_args.get());
  SetGuardedRun(check, exit_code, [check_args] {
    const auth::CommandKey loaded = auth::LoadCommandKey(FileOf(*check_args));
    std::cout << loaded.file.string() << ": a usable key\n";
    return 0;
  });
}

}  // namespace avc::cli
