#!/usr/bin/env bash
# Cairn's main job: builds everything, then runs the main diagram (`cairn run`, docs/main_diagram.md) on the
# thesis' mock-up (5.2.3): the head camera sees wood and ceramic tiles, stereo and the material segmenter make the
# friction-annotated terrain, the footstep planner plans steps and their timing on what was seen, and the whole-body
# trajectory, stabilised, is walked in the physics plant; then the mock-up with a cloth on the tiles, which the
# plan goes around (that walk ends 12 cm from the goal without a fall; docs/main_diagram.md). Each run writes
# run.json, its pictures and a 3-D viewer (run.html) under build/runs/<scenario>/.
# Last, `cairn plan` on the thesis' ice-patch scenarios (2.4.2) under build/plans/<scenario>/. The first run
# builds the robot's transition oracle (cached in build/oracle-cache/).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="$("$root/scripts/build.sh" | tail -n 1)"
for scenario in mockup mockup_cloth; do
  echo
  "$build_dir/cli/cairn" run --scenario "$root/examples/scenarios/mockup/$scenario.yaml" \
    --oracle-cache "$build_dir/oracle-cache" --out "$build_dir/runs/$scenario"
done
for scenario in flat ice_narrow_012 ice_narrow_006 ice_wide_006; do
  echo
  "$build_dir/cli/cairn" plan --scenario "$root/examples/scenarios/$scenario.yaml" \
    --oracle-cache "$build_dir/oracle-cache" --out "$build_dir/plans/$scenario"
done
