#include "tools/avc/run_guarded.h"

#include <iostream>
#include <string>

namespace avc::cli {

void SetGuardedRun(CLI::App* command, int* exit_code, std::function<int()> run) {
  // The whole command path ("calibrate solve"), so an error names what was run.
  std::string name = command->get_name();
  for (const CLI::App* parent = command->get_parent();
       parent != nullptr && parent->get_parent() != nullptr; parent = parent->get_parent()) {
    name = parent->get_name() + " " + name;
  }
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
