// avc-ur5-emulator: the UR5 protocol emulator as a standalone process, so avc-robot can run its
// real code paths with no arm. Runs until SIGINT/SIGTERM.

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <exception>

#include "sim/cell/perturbation.h"
#include "sim/emulators/ur5/ur5_emulator.h"

int main(int argc, char** argv) {
  CLI::App app{"avc-ur5-emulator: RTDE, secondary and dashboard servers of an emulated UR5"};
  avc::sim::ur5::Ur5EmulatorOptions options;
  std::optional<uint32_t> perturb_seed;
  app.add_option("--host", options.host, "IPv4 address to listen on")->capture_default_str();
  app.add_option("--rtde-port", options.rtde_port, "0 = ephemeral")->capture_default_str();
  app.add_option("--secondary-port", options.secondary_port)->capture_default_str();
  app.add_option("--dashboard-port", options.dashboard_port)->capture_default_str();
  app.add_option("--time-scale", options.time_scale, "simulated seconds per real second")
      ->capture_default_str();
  app.add_option("--encoder-noise", options.encoder_noise_rad, "rad")->capture_default_str();
  app.add_option("--seed", options.seed, "noise seed")->capture_default_str();
  app.add_option("--perturb-seed", perturb_seed, "use sim::PerturbedCell(seed) as the true arm");
  app.add_flag("--powered", options.powered, "start powered with brakes released");
  CLI11_PARSE(app, argc, argv);
  if (perturb_seed) options.cell = avc::sim::PerturbedCell(*perturb_seed);

  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);  // before the server thread starts
  try {
    avc::sim::ur5::Ur5Emulator emulator(options);
    std::printf("avc-ur5-emulator: rtde %u secondary %u dashboard %u\n", emulator.rtde_port(),
                emulator.secondary_port(), emulator.dashboard_port());
    std::fflush(stdout);
    int signal_number = 0;
    sigwait(&signals, &signal_number);
    emulator.Stop();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "avc-ur5-emulator: %s\n", error.what());
    return 1;
  }
  return 0;
}
