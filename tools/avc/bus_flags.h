#pragma once

// The bus options every command that talks on the bus accepts: --lcm-url, --bulk-url, --cell.

#include <CLI/CLI.hpp>

#include "core/bus/bus_options.h"

namespace avc::cli {

void AddBusFlags(CLI::App* command, bus::BusFlags* flags);

}  // namespace avc::cli
