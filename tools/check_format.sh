#!/usr/bin/env bash
# Fails, naming each file, when a C++ file of the project differs from what clang-format makes of
# it (.clang-format at the top). Fix with: tools/check_format.sh --fix
# shaders/ is not checked: clang-format has no GLSL mode, and the headers there are GLSL too.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check_format: clang-format is not installed (tools/setup.sh installs it)" >&2; exit 1; }
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.h' '*.hpp' ':!:shaders/**')
else
  mapfile -t files < <(find engine game tools tests -name '*.cpp' -o -name '*.h' -o -name '*.hpp')
fi
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  echo "check_format: formatted ${#files[@]} files"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  printf 'check_format: %s is not clang-formatted\n' "${bad[@]}" >&2
  echo "check_format: ${#bad[@]} of ${#files[@]} files differ; run tools/check_format.sh --fix" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files clang-formatted"
