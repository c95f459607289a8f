#!/usr/bin/env bash
# The preview window's frame rate while the camera moves (issue 15's benchmark, not a test):
# scenes/mirror_spheres.pov at 512x512 on 2 threads, the camera orbiting steadily for SECONDS
# (default 10) in a real window on a virtual display. Prints two lines from `lancer preview
# --bench`: progressive (coarse levels while moving, the default) and full resolution only
# (every picture shown is the whole 512x512 frame). The batch render time of one frame at the
# same size and thread count is printed for comparison.
# Usage: scripts/preview_bench.sh [SECONDS] [lancer binary]
set -euo pipefail
cd "$(dirname "$0")/.."
secs=${1:-10}
bin=${2:-target/release/lancer}
scene=scenes/mirror_spheres.pov
opts=(+W512 +H512 -A +WT2)
run() { xvfb-run -a -s "-screen 0 1280x1024x24" "$bin" preview "$scene" "${opts[@]}" --bench "$secs" "$@" | grep 'bench:'; }
echo "progressive:      $(run)"
echo "full resolution:  $(run --full-resolution)"
"$bin" "$scene" "${opts[@]}" -F 2>&1 | sed 's/^/batch frame:      /'
uptime
