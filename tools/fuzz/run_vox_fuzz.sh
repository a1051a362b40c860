#!/usr/bin/env bash
# Fuzzes the MagicaVoxel .vox path (parse, plan, import, export, import again) for a bounded time.
#   tools/fuzz/run_vox_fuzz.sh [SECONDS=600] [SEED_DIR=../shared/data/vox]
# Builds vox_import_fuzzer in the 'fuzz' preset (clang, libFuzzer, ASan; build/fuzz) and runs it
# on out/fuzz/vox/corpus seeded with the .vox files of SEED_DIR (not committed). Findings go to
# out/fuzz/vox/artifacts/, the log to out/fuzz/vox/fuzz.log. Exit status 0: no finding.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-600}"
seeds="${2:-../shared/data/vox}"
out=out/fuzz/vox
mkdir -p "$out/corpus" "$out/seeds" "$out/artifacts"

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target vox_import_fuzzer
cp "$seeds"/*.vox "$out/seeds/"
python3 tools/fuzz/vox_small_seeds.py "$out/seeds" "$seeds"/*.vox
echo "run_vox_fuzz: $(ls "$out/seeds" | wc -l) seed files, fuzzing for ${seconds}s"

export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
set +e
# Inputs up to 64 KiB: the small seeds whole, the real files' first 64 KiB (their headers and
# first models); larger inputs would run a few times a second under ASan.
build/fuzz/tools/fuzz/vox_import_fuzzer "$out/corpus" "$out/seeds" \
    -max_total_time="$seconds" -max_len=65536 -timeout=30 -rss_limit_mb=2048 \
    -artifact_prefix="$out/artifacts/" -print_final_stats=1 2>&1 | tee "$out/fuzz.log" | grep -E "^#[0-9]+.*(pulse|DONE)|ERROR|SUMMARY|stat::" | tail -n 40
status=${PIPESTATUS[0]}
set -e
execs=$(grep -E "stat::number_of_executed_units" "$out/fuzz.log" | awk '{print $2}' | tail -1)
findings=$(ls "$out/artifacts" | wc -l)
echo "run_vox_fuzz: exit ${status}, ${execs:-?} executions, ${findings} artifact(s) in $out/artifacts"
exit "$status"
