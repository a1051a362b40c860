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
source tools/fuzz/libfuzzer_run.sh
run_fuzzer run_scene_fuzz scene_file_fuzzer "$out" "$seconds" 16384
