#!/usr/bin/env bash
# Cairn's main job: builds everything, then plans footsteps and step timing for the thesis' ice-patch scenarios
# (examples/scenarios/ice_*.yaml, thesis 2.4.2): the humanoid crosses narrow ice of friction 0.12 slowly, walks
# around it at 0.06, and crosses wide ice at 0.06 slowly rather than detour far. Each plan is written as JSON and a
# top-down picture under build/plans/<scenario>/. The first run builds the robot's transition oracle (cached).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="$("$root/scripts/build.sh" | tail -n 1)"
for scenario in flat ice_narrow_012 ice_narrow_006 ice_wide_006; do
  echo
  "$build_dir/cli/cairn" plan --scenario "$root/examples/scenarios/$scenario.yaml" \
    --oracle-cache "$build_dir/oracle-cache" --out "$build_dir/plans/$scenario"
done
