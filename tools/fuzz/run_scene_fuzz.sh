#!/usr/bin/env bash
# Fuzzes the scene-file and path-file parsers for a bounded time.
#   tools/fuzz/run_scene_fuzz.sh [SECONDS=600]
# Builds scene_file_fuzzer in the 'fuzz' preset's folder (clang, libFuzzer, ASan; build/fuzz),
# seeds the corpus with worlds/*.toml and worlds/paths/*.toml, then runs it on
# out/fuzz/scene/corpus. Findings go to out/fuzz/scene/artifacts/, the log to
# out/fuzz/scene/fuzz.log. Exit status: 0 when the run ended without a finding.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-600}"
out=out/fuzz/scene
mkdir -p "$out/corpus" "$out/seeds" "$out/artifacts"

cmake --preset fuzz -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache >/dev/null
cmake --build build/fuzz --target scene_file_fuzzer
cp worlds/*.toml worlds/paths/*.toml "$out/seeds/"
echo "run_scene_fuzz: $(ls "$out/seeds" | wc -l) seed files, fuzzing for ${seconds}s"

export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
set +e
build/fuzz/tools/fuzz/scene_file_fuzzer "$out/corpus" "$out/seeds" \
    -max_total_time="$seconds" -max_len=16384 -timeout=30 -rss_limit_mb=2048 \
    -artifact_prefix="$out/artifacts/" -print_final_stats=1 2>&1 | tee "$out/fuzz.log" | grep -E "^#[0-9]+.*(pulse|DONE)|ERROR|SUMMARY|stat::" | tail -n 40
status=${PIPESTATUS[0]}
set -e
execs=$(grep -E "stat::number_of_executed_units" "$out/fuzz.log" | awk '{print $2}' | tail -1)
findings=$(ls "$out/artifacts" | wc -l)
echo "run_scene_fuzz: exit ${status}, ${execs:-?} executions, ${findings} artifact(s) in $out/artifacts"
exit "$status"
