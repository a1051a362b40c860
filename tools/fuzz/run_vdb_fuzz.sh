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
source tools/fuzz/libfuzzer_run.sh
run_fuzzer run_vdb_fuzz vdb_import_fuzzer "$out" "$seconds" 65536
