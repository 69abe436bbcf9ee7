#!/usr/bin/env bash
# Noise sweep like thesis Table 4.5: the bars scenario fused with the cost-curve (Merrell, ML) and WTA models at the
# thesis' image-noise variances, through `cairn occupancy --json`. Prints a Markdown table of the final precision
# and recall per model and variance.
#
# Usage: scripts/occupancy_noise_sweep.sh [path/to/cairn] [variances...]
set -euo pipefail
cairn=${1:-build/cli/cairn}
shift || true
variances=("$@")
if [ ${#variances[@]} -eq 0 ]; then variances=(13 14 15 18 25 43 83 177 397); fi
if [ ! -x "$cairn" ]; then
  echo "occupancy_noise_sweep.sh: '$cairn' is not an executable; pass the cairn binary as the first argument" >&2
  exit 1
fi
field() { /usr/bin/python3 -c "import json,sys; print('%.4f' % json.load(sys.stdin)['$1'])"; }
echo "| noise variance | merrell precision | merrell recall | wta precision | wta recall |"
echo "|---|---|---|---|---|"
for v in "${variances[@]}"; do
  merrell=$("$cairn" occupancy --scenario bars --model merrell --noise-var "$v" --json)
  wta=$("$cairn" occupancy --scenario bars --model wta --noise-var "$v" --json)
  echo "| $v | $(field precision <<<"$merrell") | $(field recall <<<"$merrell") |" \
       "$(field precision <<<"$wta") | $(field recall <<<"$wta") |"
done
