#!/usr/bin/env bash
# Builds the libFuzzer targets (CAIRN_FUZZ=ON, clang, in build-fuzz/) and runs each for a while, printing per target
# the executions, executions per second and the failures found (crashes, sanitizer reports, timeouts, memory
# limits). Exits with 1 if any target failed.
#   scripts/fuzz.sh [--seconds N] [target...]     N: seconds per target (default 60); targets: all when none given
# Targets (fuzz/fuzz_harnesses.h): urdf footstep_scenario occupancy_scenario walking_model material_registry
#   builtin_segmenter onnx_segmenter transition_oracle disparity_png
# Each run starts from the repository's own files (written by cairn_fuzz_write_seeds), the hand-written seeds in
# fuzz/corpus/<target>/ and what earlier runs found (build-fuzz/corpus/<target>/). A failing input lands in
# build-fuzz/artifacts/<target>/; keep it as fuzz/regressions/<target>/<name> so that test/fuzz replays it.
# Environment: CAIRN_SHARED_DIR (default ../shared), FUZZ_JOBS (build parallelism, default nproc).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
all_targets=(urdf footstep_scenario occupancy_scenario walking_model material_registry builtin_segmenter
             onnx_segmenter transition_oracle disparity_png)

seconds=60
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds)
      [ $# -ge 2 ] || { echo "fuzz.sh: --seconds needs a number of seconds" >&2; exit 2; }
      seconds="$2"; shift 2 ;;
    --seconds=*) seconds="${1#--seconds=}"; shift ;;
    -h|--help) sed -n '2,12p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "fuzz.sh: unknown option '$1' (known: --seconds N)" >&2; exit 2 ;;
    *)
      known=0
      for t in "${all_targets[@]}"; do [ "$t" = "$1" ] && known=1; done
      [ "$known" = 1 ] || { echo "fuzz.sh: unknown target '$1' (known: ${all_targets[*]})" >&2; exit 2; }
      targets+=("$1"); shift ;;
  esac
done
case "$seconds" in
  ''|*[!0-9]*|0) echo "fuzz.sh: --seconds must be a positive whole number, got '$seconds'" >&2; exit 2 ;;
esac
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")

"$root/scripts/install_deps.sh" >&2
# libFuzzer and the sanitizer runtimes come with Debian's clang (clang 14 on Debian 12).
if ! command -v clang++ >/dev/null 2>&1 || ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "ok installed"; then
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  echo "fuzz.sh: installing clang and libclang-rt-14-dev" >&2
  ${sudo[@]+"${sudo[@]}"} apt-get update >&2
  DEBIAN_FRONTEND=noninteractive ${sudo[@]+"${sudo[@]}"} apt-get install -y --no-install-recommends clang libclang-rt-14-dev >&2
fi
build_dir="$root/build-fuzz"
shared_dir="${CAIRN_SHARED_DIR:-$root/../shared}"
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCAIRN_FUZZ=ON -DCAIRN_BUILD_TESTS=OFF -DCAIRN_BENCHMARKS=OFF -DCAIRN_SHARED_DIR="$shared_dir" >&2
fi
cmake --build "$build_dir" --parallel "${FUZZ_JOBS:-$(nproc)}" --target cairn_fuzz_all >&2

seeds="$build_dir/seeds"
rm -rf "$seeds"
"$build_dir/fuzz/cairn_fuzz_write_seeds" "$seeds" "${targets[@]}"

summary=()
failed=0
for t in "${targets[@]}"; do
  corpus="$build_dir/corpus/$t"
  artifacts="$build_dir/artifacts/$t"
  mkdir -p "$corpus" "$artifacts"
  before=$(find "$artifacts" -type f | wc -l)
  options=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 -max_total_time="$seconds"
           -timeout=10 -rss_limit_mb=2048 -max_len=65536 -artifact_prefix="$artifacts/" -print_final_stats=1)
  [ -f "$root/fuzz/dict/$t.dict" ] && options+=(-dict="$root/fuzz/dict/$t.dict")
  inputs=("$corpus" "$seeds/$t")
  [ -d "$root/fuzz/corpus/$t" ] && inputs+=("$root/fuzz/corpus/$t")
  log="$build_dir/fuzz-$t.log"
  echo "== $t: fuzzing for $seconds s (log: $log)" >&2
  start=$(date +%s)
  # New inputs go to the first folder; libFuzzer exits non-zero when it found failures (counted below).
  "$build_dir/fuzz/cairn_fuzz_$t" "${options[@]}" "${inputs[@]}" >"$log" 2>&1 || true
  elapsed=$(( $(date +%s) - start ))
  [ "$elapsed" -gt 0 ] || elapsed=1
  # Fork mode's progress lines: "#<executions>: cov: ... oom/timeout/crash: <o>/<t>/<c> time: ...".
  last=$(grep -E '^#[0-9]+: cov:' "$log" | tail -n 1 || true)
  executions=$(printf '%s' "$last" | sed -nE 's/^#([0-9]+):.*/\1/p')
  executions=${executions:-0}
  found=$(( $(find "$artifacts" -type f | wc -l) - before ))
  rate=$(( executions / elapsed ))
  line=$(printf '%-20s %12s executions %8s exec/s %4s failures  (%s s)' "$t" "$executions" "$rate" "$found" "$elapsed")
  echo "$line"
  summary+=("$line")
  if [ "$found" -gt 0 ]; then
    failed=1
    echo "   new failing inputs in $artifacts/ (first stack in $log)"
  fi
done
echo "== summary ($(date -u +%Y-%m-%dT%H:%MZ), load $(cut -d' ' -f1-3 /proc/loadavg))"
printf '%s\n' "${summary[@]}"
exit "$failed"
