#pragma once

// Every `avc` subcommand registers itself on the root app. A command's callback stores its
// process exit code in *exit_code; main returns it.

#include <CLI/CLI.hpp>

namespace avc::cli {

void RegisterVersion(CLI::App& root, int* exit_code);
void RegisterRecord(CLI::App& root, int* exit_code);
void RegisterReplay(CLI::App& root, int* exit_code);
void RegisterCollect(CLI::App& root, int* exit_code);
void RegisterUp(CLI::App& root, int* exit_code);
void RegisterBench(CLI::App& root, int* exit_code);
void RegisterStatus(CLI::App& root, int* exit_code);
void RegisterSpy(CLI::App& root, int* exit_code);
void RegisterSim(CLI::App& root, int* exit_code);
void RegisterSimCell(CLI::App& sim, int* exit_code);  // under `avc sim`
void RegisterEval(CLI::App& root, int* exit_code);
void RegisterTurntable(CLI::App& root, int* exit_code);
void RegisterCamera(CLI::App& root, int* exit_code);
void RegisterRobot(CLI::App& root, int* exit_code);
void RegisterCalibrate(CLI::App& root, int* exit_code);
void RegisterCalibrator(CLI::App& root, int* exit_code);
void RegisterReconstruct(CLI::App& root, int* exit_code);
void RegisterBuilder(CLI::App& root, int* exit_code);
void RegisterCluster(CLI::App& root, int* exit_code);
void RegisterClusterer(CLI::App& root, int* exit_code);
void RegisterSurfacer(CLI::App& root, int* exit_code);
void RegisterPlanner(CLI::App& root, int* exit_code);
void RegisterScan(CLI::App& root, int* exit_code);
void RegisterDemo(CLI::App& root, int* exit_code);
void RegisterReport(CLI::App& root, int* exit_code);
void RegisterKey(CLI::App& root, int* exit_code);
void RegisterOptions(CLI::App& root, int* exit_code);

}  // namespace avc::cli
