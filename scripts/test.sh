#!/usr/bin/env bash
# Builds Cairn and runs its whole test suite as users build it (build/); with --all, then again under
# AddressSanitizer and UndefinedBehaviorSanitizer (build-sanitize/), where the tests labelled sanitize_slow are left
# out (too slow under the sanitizers; they still run in the plain suite). Stops at the first failing suite; exits
# non-zero on any failure. The default is --all, what CI (.ci/run) runs: the sanitized build compiles at -O1 -g1
# (scripts/build.sh), which keeps both suites well within CI's time on 2 cores.
#   scripts/test.sh [--all | --plain | --sanitize]     --plain: the plain suite only; --sanitize: the sanitized one
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

suites=(plain sanitize)
for arg in "$@"; do
  case "$arg" in
    --plain) suites=(plain) ;;
    --sanitize) suites=(sanitize) ;;
    --all) suites=(plain sanitize) ;;
    *) echo "test.sh: unknown option '$arg' (known: --plain, --sanitize, --all)" >&2; exit 2 ;;
  esac
done

for suite in "${suites[@]}"; do
  start=$(date +%s)
  if [ "$suite" = plain ]; then
    build_dir="$("$root/scripts/build.sh" | tail -n 1)"
    exclude=()
  else
    build_dir="$("$root/scripts/build.sh" --sanitize | tail -n 1)"
    exclude=(--label-exclude sanitize_slow)
    # UBSan findings abort (-fno-sanitize-recover); print their stacks too.
    export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
  fi
  built=$(date +%s)
  echo "== $suite suite: built in $((built - start)) s" >&2
  (cd "$build_dir" && ctest --output-on-failure --parallel "$(nproc)" --timeout 900 ${exclude[@]+"${exclude[@]}"})
  echo "== $suite suite: build and tests took $(( $(date +%s) - start )) s" >&2
done
