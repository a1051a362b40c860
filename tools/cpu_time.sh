#!/usr/bin/env bash
# CPU milliseconds per frame of `vox render`, for comparing builds on a CPU Vulkan device
# (lavapipe), where GPU timestamps are wall time and swing with the machine's load but the CPU
# time of the process (lavapipe's threads do the GPU work) does not. Renders 10 and 40 frames
# three times each and prints (median CPU time of 40 frames - median of 10) / 30: start-up and
# warm-up cancel out. Divide by the cores lavapipe uses for a wall-time estimate on an idle machine.
#
#   tools/cpu_time.sh build/release/tools/vox/vox sandbox --size 320x180 --indirect cache
set -euo pipefail
if [[ $# -lt 2 ]]; then
    echo "usage: $0 VOX WORLD [vox render options...]" >&2
    exit 2
fi
[[ -x /usr/bin/time ]] || { echo "$0: needs /usr/bin/time (apt install time)" >&2; exit 1; }
vox=$1
shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for frames in 10 40; do
    for run in 1 2 3; do
        /usr/bin/time -f "$frames %U %S" -o "$out/time" "$vox" render "$@" --frames "$frames" -o "$out/image.png" > /dev/null
        cat "$out/time"
    done
done | awk '
    { t = $2 + $3; if ($1 == 10) a[++na] = t; else b[++nb] = t }
    function median(x, n,   i, j, v) {  # n == 3
        for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (x[j] < x[i]) { v = x[i]; x[i] = x[j]; x[j] = v }
        return x[2]
    }
    END { m10 = median(a, na); m40 = median(b, nb); printf "cpu ms/frame %.1f  (10 frames %.2f s, 40 frames %.2f s)\n", (m40 - m10) / 30 * 1000, m10, m40 }'
