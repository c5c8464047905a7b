#include "tools/avc/run_guarded.h"

#include <iostream>
#include <string>

namespace avc::cli {

void SetGuardedRun(CLI::App* command, int* exit_code, std::function<int()> run) {
  const std::string name = command->get_name();
  command->callback([command, name, exit_code, run = std::move(run)] {
    // CLI11 runs a command's callback after its subcommand's: `avc camera list` must not go on
    // to run the camera service.
    if (!command->get_subcommands().empty()) return;
    try {
      *exit_code = run();
    } catch (const std::exception& e) {
      std::cerr << "avc " << name << ": " << e.what() << "\n";
      *exit_code = 1;
    }
  });
}

}  // namespace avc::cli
