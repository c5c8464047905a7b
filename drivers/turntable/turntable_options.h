#pragma once

// avc-turntable's options (serial line, moves, polling), declared once for --config, --set, the
// configuration it publishes and --help (core/config/option_table.h). The command table (a JSON
// file) and the key are given by their own flags.

#include "core/config/option_table.h"
#include "drivers/turntable/turntable_node.h"

namespace avc::turntable {

const config::OptionTable<TurntableNodeOptions>& TurntableOptionTable();

}  // namespace avc::turntable
