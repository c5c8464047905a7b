// avc: the one command-line tool of the Active Vision Cell.

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "core/util/log.h"
#include "tools/avc/commands.h"
#include "tools/avc/help_formatter.h"
#include "tools/avc/parse_failure.h"

int main(int argc, char** argv) {
  avc::log::SetProcessName("avc");
  CLI::App app{
      "avc - Active Vision Cell: scans a plant into a 3D surface model.\n"
      "Run 'avc COMMAND --help' for the options of a command."};
  // Before the subcommands are added: each takes its parent's formatter when it is created.
  app.formatter(std::make_shared<avc::cli::SummaryListingFormatter>());
  app.failure_message(avc::cli::ParseFailureMessage);
  app.require_subcommand(1);
  app.fallthrough(false);
  int exit_code = 0;
  avc::cli::RegisterVersion(app, &exit_code);
  avc::cli::RegisterRecord(app, &exit_code);
  avc::cli::RegisterReplay(app, &exit_code);
  avc::cli::RegisterCollect(app, &exit_code);
  avc::cli::RegisterUp(app, &exit_code);
  avc::cli::RegisterStatus(app, &exit_code);
  avc::cli::RegisterSpy(app, &exit_code);
  avc::cli::RegisterSim(app, &exit_code);
  avc::cli::RegisterBench(app, &exit_code);
  avc::cli::RegisterEval(app, &exit_code);
  avc::cli::RegisterTurntable(app, &exit_code);
  avc::cli::RegisterRobot(app, &exit_code);
  avc::cli::RegisterCamera(app, &exit_code);
  avc::cli::RegisterCalibrate(app, &exit_code);
  avc::cli::RegisterCalibrator(app, &exit_code);
  avc::cli::RegisterReconstruct(app, &exit_code);
  avc::cli::RegisterBuilder(app, &exit_code);
  avc::cli::RegisterCluster(app, &exit_code);
  avc::cli::RegisterClusterer(app, &exit_code);
  avc::cli::RegisterSurfacer(app, &exit_code);
  avc::cli::RegisterPlanner(app, &exit_code);
  avc::cli::RegisterScan(app, &exit_code);
  avc::cli::RegisterDemo(app, &exit_code);
  avc::cli::RegisterReport(app, &exit_code);
  avc::cli::RegisterKey(app, &exit_code);
  avc::cli::RegisterOptions(app, &exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "avc: " << e.what() << "\n";
    return 1;
  }
  return exit_code;
}
