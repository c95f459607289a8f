#!/usr/bin/env bash
# Per-scene timing, lancer vs POV-Ray, for every row of reference/manifest.tsv: whole-process
# wall time of each (best of N) and POV-Ray's own trace time. A benchmark, not a test.
# usage: scripts/scene_times.sh [reps]
set -euo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
cd "$(dirname "$0")/.."
reps=${1:-3}
command -v povray >/dev/null || { echo "povray not found: apt-get install povray povray-includes" >&2; exit 1; }
[ -x target/release/lancer ] || cargo build --release -q
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
best() { sort -n | head -1; }
wall() { local s e; s=$(date +%s.%N); "$@" >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; return 1; }; e=$(date +%s.%N); echo "$e - $s" | bc; }
printf "%-20s %-20s %10s %10s %10s %8s\n" scene options lancer_s povray_s pov_trace lan/pov
tail -n +2 reference/manifest.tsv | while IFS=$'\t' read -r scene opts _ _ _; do
  [ -n "$scene" ] || continue
  l=$(for _ in $(seq "$reps"); do wall target/release/lancer "scenes/$scene" $opts "+O$tmp/l.png" -q; done | best)
  p=$(for _ in $(seq "$reps"); do wall povray -D -V +FN8 $opts +Lscenes +L/usr/share/povray-3.7/include "+Iscenes/$scene" "+O$tmp/p.png"; done | best)
  povray -D +V +FN8 $opts +Lscenes +L/usr/share/povray-3.7/include "+Iscenes/$scene" "+O$tmp/p.png" >/dev/null 2>"$tmp/stats" || true
  t=$(grep -E "^Render Time:|Trace Time:" "$tmp/stats" | grep -oE "[0-9]+\.[0-9]+ seconds" | head -1 | grep -oE "[0-9.]+" || echo "?")
  printf "%-20s %-20s %10.3f %10.3f %10s %8.2f\n" "$scene" "$opts" "$l" "$p" "$t" "$(echo "$l / $p" | bc -l)"
done
