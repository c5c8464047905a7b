// avc spy: lcm-spy with our message types on its class path and the Java 17 workaround, so it
// decodes every AVC channel.

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "core/bus/bus_options.h"
#include "core/launch/find_program.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

namespace fs = std::filesystem;

struct SpyArgs {
  bool bulk = false;
  std::string jar;
  bool dry_run = false;
  bus::BusFlags bus;
};

// build/bin/avc → build/avc-lcmtypes.jar; an installed avc looks in ../share/avc.
fs::path DefaultJar() {
  const fs::path bin = launch::SelfExecutableDir();
  for (const fs::path& candidate :
       {bin.parent_path() / "avc-lcmtypes.jar", bin.parent_path() / "share/avc/avc-lcmtypes.jar"}) {
    if (fs::is_regular_file(candidate)) return candidate;
  }
  return bin.parent_path() / "avc-lcmtypes.jar";
}

std::string Join(const std::vector<std::string>& parts) {
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : " ") + part;
  return text;
}

int RunSpy(const SpyArgs& args) {
  const fs::path jar = args.jar.empty() ? DefaultJar() : fs::path(args.jar);
  if (!fs::is_regular_file(jar)) {
    std::cerr << "avc spy: no message types jar at " << jar.string()
              << " (it is built with the project when a JDK is present: apt-get install "
                 "default-jdk-headless liblcm-java, then re-run scripts/setup)\n";
    return 1;
  }
  const char* path_env = std::getenv("PATH");
  const std::string spy = launch::FindInPath("lcm-spy", path_env ? path_env : "");
  if (spy.empty()) {
    std::cerr
        << "avc spy: lcm-spy is not installed (apt-get install liblcm-java libjchart2d-java)\n";
    return 1;
  }
  const bus::BusOptions options = bus::ResolveBusOptions(args.bus, "avc-spy");
  const std::string url =
      args.bulk && !options.bulk_url.empty() ? options.bulk_url : options.control_url;
  const std::string class_path =
      jar.string() + (std::getenv("CLASSPATH") ? std::string(":") + std::getenv("CLASSPATH") : "");
  const std::vector<std::string> argv = {spy, "-l", url};
  if (args.bulk) {
    std::cerr << "avc spy: note: Java ignores recv_buf_size, so multi-MB products may be missed "
                 "unless net.core.rmem_default is raised (scripts/setup-lab-host)\n";
  }
  if (args.dry_run) {
    std::cout << "CLASSPATH=" << class_path
              << " JAVA_TOOL_OPTIONS=-XX:+IgnoreUnrecognizedVMOptions " << Join(argv) << "\n";
    return 0;
  }
  setenv("CLASSPATH", class_path.c_str(), 1);
  // Debian's wrapper passes -Xincgc, which Java 17 refuses without this.
  setenv("JAVA_TOOL_OPTIONS", "-XX:+IgnoreUnrecognizedVMOptions", 1);
  std::vector<char*> c_argv;
  for (const std::string& arg : argv) c_argv.push_back(const_cast<char*>(arg.c_str()));
  c_argv.push_back(nullptr);
  execv(spy.c_str(), c_argv.data());
  std::cerr << "avc spy: cannot run " << spy << ": " << std::strerror(errno) << "\n";
  return 1;
}

}  // namespace

void RegisterSpy(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<SpyArgs>();
  CLI::App* command = root.add_subcommand(
      "spy",
      "Open lcm-spy on the cell's bus with AVC's message types.\n"
      "Watches the control URL (or --bulk) with the project's types jar on the class path, so\n"
      "every channel is decoded. Needs a display (X11).");
  command->add_flag("--bulk", args->bulk, "watch the bulk URL (products) instead of control");
  command->add_option("--jar", args->jar,
                      "message types jar (default: the build's avc-lcmtypes.jar)");
  command->add_flag("--dry-run", args->dry_run, "print the command instead of running it");
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunSpy(*args); });
}

}  // namespace avc::cli
