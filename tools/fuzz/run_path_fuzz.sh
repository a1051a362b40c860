#!/usr/bin/env bash
# Fuzzes path files as a capture plays them (read, write back, check every frame, apply the
# timeline to a small world) for a bounded time.
#   tools/fuzz/run_path_fuzz.sh [SECONDS=600]
# Builds path_file_fuzzer in the 'fuzz' preset's folder (clang, libFuzzer, ASan; build/fuzz),
# seeds the corpus with worlds/paths/*.toml, the sandbox's [path] and path_seed_events.toml, then
# runs it on out/fuzz/path/corpus. Findings go to out/fuzz/path/artifacts/, the log to
# out/fuzz/path/fuzz.log. Exit status: 0 when the run ended without a finding.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-600}"
out=out/fuzz/path
mkdir -p "$out/corpus" "$out/seeds" "$out/artifacts"

cmake --preset fuzz -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache >/dev/null
cmake --build build/fuzz --target path_file_fuzzer
cp worlds/paths/*.toml tools/fuzz/path_seed_events.toml "$out/seeds/"
cp worlds/sandbox.toml "$out/seeds/sandbox_path.toml"  # a scene file: its [path] table
source tools/fuzz/libfuzzer_run.sh
run_fuzzer run_path_fuzz path_file_fuzzer "$out" "$seconds" 16384
