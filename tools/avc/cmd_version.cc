#include <iostream>

#include "core/util/version.h"
#include "tools/avc/commands.h"

namespace avc::cli {

void RegisterVersion(CLI::App& root, int* exit_code) {
  CLI::App* command = root.add_subcommand("version", "Print the AVC version");
  command->callback([exit_code] {
    std::cout << "avc " << Version() << "\n";
    *exit_code = 0;
  });
}

}  // namespace avc::cli
