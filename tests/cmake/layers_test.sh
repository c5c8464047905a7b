#!/usr/bin/env bash
# The configure-time layer check (cmake/AvcLayers.cmake) on a tiny project: a clean one
# configures; the same with a production library linking the simulator's (privately, through
# another target) is refused, naming the target and the chain.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake -S "$here/layers" -B "$work/clean" >"$work/clean.log" 2>&1 ||
  { cat "$work/clean.log"; echo "FAIL: the clean project was refused"; exit 1; }
if cmake -S "$here/layers" -B "$work/bad" -DAVC_TEST_VIOLATE=ON >"$work/bad.log" 2>&1; then
  echo "FAIL: a production library linking avc_sim_scene was accepted"; exit 1
fi
grep -q "Layer violation: avc_util (core/) depends on avc_sim_scene" "$work/bad.log" ||
  { cat "$work/bad.log"; echo "FAIL: the refusal does not name the target"; exit 1; }
grep -q "avc_util -> avc_planner -> avc_sim_scene" "$work/bad.log" ||
  { cat "$work/bad.log"; echo "FAIL: the refusal does not show the chain"; exit 1; }
echo "layer check: clean project accepted, violation refused"
