#include "tools/avc/run_guarded.h"

#include <iostream>
#include <string>

namespace avc::cli {

void SetGuardedRun(CLI::App* command, int* exit_code, std::function<int()> run) {
  const std::string name = command->get_name();
  command->callback([name, exit_code, run = std::move(run)] {
    try {
      *exit_code = run();
    } catch (const std::exception& e) {
      std::cerr << "avc " << name << ": " << e.what() << "\n";
      *exit_code = 1;
    }
  });
}

}  // namespace avc::cli
