#!/usr/bin/env bash
# Builds Cairn and runs its whole test suite; exits non-zero on any failure.
#   scripts/test.sh [--sanitize]      --sanitize: run the suite under ASan + UBSan (build-sanitize/)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="$("$root/scripts/build.sh" "$@" | tail -n 1)"
cd "$build_dir"
ctest --output-on-failure --parallel "$(nproc)" --timeout 900
