#include "drivers/turntable/turntable_options.h"

namespace avc::turntable {
namespace {

using Table = config::OptionTable<TurntableNodeOptions>;

Table MakeTable() {
  // The device may come from --emulate and the key from its file: both are checked when the
  // node starts, the rest here.
  Table table("turntable", [](TurntableNodeOptions o) {
    if (o.device.empty()) o.device = "(given at start)";
    o.auth.allow_unsigned = true;
    return o.Validate();
  });
  table.Add("device", [](auto& o) -> auto& { return o.device; }, {"", "serial device path"})
      .Add("baud", [](auto& o) -> auto& { return o.baud; }, {"", "baud rate (8N1)", 300, 4000000})
      .Add("device_options.command_timeout",
           [](auto& o) -> auto& { return o.device_options.command_timeout; },
           {"ms", "a reply not complete after this fails the command", 1, 600000})
      .Add("device_options.invalid_reply_retries",
           [](auto& o) -> auto& { return o.device_options.invalid_reply_retries; },
           {"", "extra attempts after an invalid reply to a repeatable command", 0, 100})
      .Add("controller.default_speed_deg_s",
           [](auto& o) -> auto& { return o.controller.default_speed_deg_s; },
           {"deg/s", "speed when a command gives 0", 0.01, 1000})
      .Add("controller.duration_margin",
           [](auto& o) -> auto& { return o.controller.duration_margin; },
           {"", "a move fails after distance / speed times this, plus the slack", 1, 100})
      .Add("controller.duration_slack_s",
           [](auto& o) -> auto& { return o.controller.duration_slack_s; },
           {"s", "... plus this", 0, 3600})
      .Add("controller.stall_timeout_s",
           [](auto& o) -> auto& { return o.controller.stall_timeout_s; },
           {"s", "a move fails when the position stays put this long", 0.01, 3600})
      .Add("controller.tolerance_tenths",
           [](auto& o) -> auto& { return o.controller.tolerance_tenths; },
           {"0.1 deg", "a move is done this close to its target", 0, 3600})
      .Add("poll_period", [](auto& o) -> auto& { return o.poll_period; },
           {"ms", "state poll period", 1, 60000})
      .Add("reconnect_min", [](auto& o) -> auto& { return o.reconnect_min; },
           {"ms", "first pause before reopening the port; doubles up to reconnect_max", 1, 600000})
      .Add("reconnect_max", [](auto& o) -> auto& { return o.reconnect_max; },
           {"ms", "longest pause between reopening attempts", 1, 600000})
      .Add("failures_before_reconnect",
           [](auto& o) -> auto& { return o.failures_before_reconnect; },
           {"", "failed polls in a row after which the port is reopened", 1, 1000});
  return table;
}

}  // namespace

const config::OptionTable<TurntableNodeOptions>& TurntableOptionTable() {
  static const Table table = MakeTable();
  return table;
}

}  // namespace avc::turntable
