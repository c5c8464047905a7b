#!/usr/bin/env bash
# The configure-time layer checks (cmake/AvcLayers.cmake) on a tiny project whose rules are the
# Layers table of layers/layers.md: the clean project configures; each wrong dependency is
# refused with a message naming the targets (and the chain, for a rule on named targets).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake -S "$here/layers" -B "$work/clean" >"$work/clean.log" 2>&1 ||
  { cat "$work/clean.log"; echo "FAIL: the clean project was refused"; exit 1; }

# refused VIOLATION EXPECTED_TEXT...: configuring with the violation fails, saying each text.
refused() {
  local violation=$1
  shift
  if cmake -S "$here/layers" -B "$work/$violation" -DAVC_TEST_VIOLATE="$violation" \
      >"$work/$violation.log" 2>&1; then
    echo "FAIL: the '$violation' violation was accepted"
    exit 1
  fi
  for text in "$@"; do
    grep -qF "$text" "$work/$violation.log" ||
      { cat "$work/$violation.log"; echo "FAIL: '$violation' refused without saying: $text"; exit 1; }
  done
}
refused table "Layer violation: avc_planner (services/) links avc_sim_scene (sim/)" \
  "\`services\` may use only core"
refused chain "Layer violation: avc_cli_scan (tools/) depends on avc_planner" \
  "avc_cli_scan -> avc_helper -> avc_planner"
refused folder "avc_extra is in extra/, which no row of the Layers"
echo "layer checks: clean project accepted, 3 violations refused"
