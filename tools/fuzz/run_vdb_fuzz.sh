#!/usr/bin/env bash
# Fuzzes the OpenVDB import path for a bounded time.
#   tools/fuzz/run_vdb_fuzz.sh [SECONDS=600]
# Builds the 'fuzz' preset (clang, libFuzzer, ASan; build/fuzz), writes the seed corpus of small
# valid files with make_vdb_samples (OpenVDB-written foreign files plus a voxengine world), then
# runs vdb_import_fuzzer on out/fuzz/vdb/corpus. Findings go to out/fuzz/vdb/artifacts/, the log to
# out/fuzz/vdb/fuzz.log. Exit status: 0 when the run ended without a finding.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-600}"
out=out/fuzz/vdb
mkdir -p "$out/corpus" "$out/seeds" "$out/artifacts"

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
build/fuzz/tools/vdb_samples/make_vdb_samples seeds "$out/seeds"
echo "run_vdb_fuzz: $(ls "$out/seeds" | wc -l) seed files, fuzzing for ${seconds}s"

# Leak checks stay on; returning null from an over-large malloc is never needed because the
# engine's allocation budget refuses such requests before they reach malloc.
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
set +e
build/fuzz/tools/fuzz/vdb_import_fuzzer "$out/corpus" "$out/seeds" \
    -max_total_time="$seconds" -max_len=65536 -timeout=30 -rss_limit_mb=2048 \
    -artifact_prefix="$out/artifacts/" -print_final_stats=1 2>&1 | tee "$out/fuzz.log" | grep -E "^#[0-9]+.*(pulse|DONE|NEW)|ERROR|SUMMARY|stat::" | grep -vE "NEW" | tail -n 40
status=${PIPESTATUS[0]}
set -e
execs=$(grep -E "stat::number_of_executed_units" "$out/fuzz.log" | awk '{print $2}' | tail -1)
findings=$(ls "$out/artifacts" | wc -l)
echo "run_vdb_fuzz: exit ${status}, ${execs:-?} executions, ${findings} artifact(s) in $out/artifacts"
exit "$status"
