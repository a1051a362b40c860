#!/usr/bin/env bash
# The world store's crash-safety acceptance: 200 SIGKILLs at seeded random moments during saves of
# an edited world (ctest runs 12). Each must leave a store that opens, passes PRAGMA
# integrity_check and holds one save's state in every region (docs/WORLD_STORE.md).
# Usage: bash tools/store_crash_test.sh [build dir] [runs]
set -euo pipefail
build="${1:-build/release}"
runs="${2:-200}"
VOX_STORE_CRASH_RUNS="$runs" nice -n 19 "$build/tests/store_tests" \
  --gtest_filter='BackgroundSaver.KilledDuringSavesLeavesPreviousOrNewState'
