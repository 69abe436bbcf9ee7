#!/usr/bin/env bash
# Cairn's main job: builds everything, then runs the example diagram — a damped pendulum held at 45 degrees by a
# discrete PD controller (through a ZeroOrderHold), simulated for 10 s, its log written as CSV.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="$("$root/scripts/build.sh" | tail -n 1)"
"$build_dir/cli/cairn" pendulum --csv "$build_dir/pendulum_log.csv"
echo
echo "The diagram that ran (Graphviz: $build_dir/cli/cairn diagram --dot | dot -Tpng > pendulum.png):"
"$build_dir/cli/cairn" diagram
