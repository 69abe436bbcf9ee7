#!/usr/bin/env bash
# Configures and builds Cairn (RelWithDebInfo; Ninja and ccache when present), installing Debian packages first
# when any is missing.
#   scripts/build.sh [--sanitize]     --sanitize: AddressSanitizer + UndefinedBehaviorSanitizer, in build-sanitize/
# Prints the build folder's path as its last line.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

sanitize=OFF
benchmarks=ON
build_dir="$root/build"
# RelWithDebInfo's own flags for the plain build.
config_flags="-O2 -g -DNDEBUG"
for arg in "$@"; do
  case "$arg" in
    # Benchmarks measure nothing useful under the sanitizers: the sanitized build leaves them out. It compiles at
    # -O1 with line tables only (-g1): half the compile time of -O2 -g (measured on walking_model.cc, dynamics.cc
    # and a test), and the sanitizers' reports still name file and line.
    --sanitize) sanitize=ON; benchmarks=OFF; build_dir="$root/build-sanitize"; config_flags="-O1 -g1 -DNDEBUG" ;;
    *) echo "build.sh: unknown option '$arg' (known: --sanitize)" >&2; exit 2 ;;
  esac
done

"$root/scripts/install_deps.sh" >&2

# ccache keys on the compiler's command line, which names absolute paths: without a base folder a second clone of
# the repository (CI's fresh clone) missed every object and compiled both builds cold (measured: 75 of CI's 90
# minutes). Paths below the root are hashed relative to it, and the working folder is left out of the hash (the
# debug info then names the first clone's folder, which is harmless). Measured: a fresh clone's plain build hit
# 92 % of ccache and built in 200 s instead of about 25 min; the plain build's objects take 0.6 GB of the cache.
# The misses are the few sources still given an absolute path as a definition (the CLI's data folder, benchmarks,
# examples, fuzz harnesses); tests take theirs from a generated source (test/support/test_paths.h).
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"

generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAIRN_SANITIZE="$sanitize" \
    -DCAIRN_BENCHMARKS="$benchmarks" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$config_flags" \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="$config_flags" >&2
else
  cmake "$build_dir" -DCAIRN_SANITIZE="$sanitize" -DCAIRN_BENCHMARKS="$benchmarks" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$config_flags" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$config_flags" >&2
fi
cmake --build "$build_dir" --parallel "$(nproc)" >&2
echo "$build_dir"
