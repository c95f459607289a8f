#!/usr/bin/env bash
# Issue 10's benchmark 5 and issue 13's benchmark item: POV-Ray's own benchmark scene
# (advanced/benchmark/benchmark.pov) rendered by povray and by lancer side by side in one run,
# at 512x512 with +A0.3, both with their default thread count (or THREADS=n for +WTn on both),
# and the whole run's wall time of each (povray's picture takes minutes). Prints the times,
# their ratio and the SSIM of lancer's picture against povray's.
# usage: scripts/benchmark_scene.sh [-n lancer] [-s WxH] [-k dir]   (-k keeps the pictures in dir)
set -euo pipefail
cd "$(dirname "$0")/.."
lancer=$PWD/target/release/lancer
size=512x512
keep=
while getopts "n:s:k:" opt; do
  case $opt in
    n) lancer=$OPTARG ;;
    s) size=$OPTARG ;;
    k) keep=$OPTARG ;;
    *) echo "usage: $0 [-n lancer] [-s WxH] [-k dir]" >&2; exit 2 ;;
  esac
done
[ -x "$lancer" ] || { echo "no lancer binary $lancer: cargo build --release" >&2; exit 2; }
command -v povray >/dev/null || { echo "povray not found" >&2; exit 2; }
w=${size%x*}; h=${size#*x}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -rL /usr/share/povray-3.7/scenes/advanced/benchmark/. "$tmp/"
chmod -R u+w "$tmp"
inc=/usr/share/povray-3.7/include
threads=()
[ -n "${THREADS:-}" ] && threads=("+WT$THREADS")
opts=(+A0.3 "+W$w" "+H$h" "+L$tmp" "+L$inc" "${threads[@]}")
secs() { date +%s.%N; }
cd "$tmp"
t0=$(secs)
povray -D -V +FN8 "${opts[@]}" +Ibenchmark.pov +Opov.png >pov.log 2>&1 || { echo "povray failed:"; tail pov.log; exit 1; }
t1=$(secs)
LANCER_NO_CONFIG=1 "$lancer" benchmark.pov "${opts[@]}" +FN8 +Olancer.png 2>lancer.log || { echo "lancer failed:"; tail lancer.log; exit 1; }
t2=$(secs)
pov=$(echo "$t1 - $t0" | bc -l); lan=$(echo "$t2 - $t1" | bc -l)
printf 'benchmark.pov %sx%s +A0.3 %s: povray %.1f s, lancer %.1f s, lancer/povray %.3f\n' \
  "$w" "$h" "${threads[*]:-default threads}" "$pov" "$lan" "$(echo "$lan / $pov" | bc -l)"
"$lancer" compare pov.png lancer.png | head -1
grep -E "(Parse|Photon|Trace) Time" pov.log | sed 's/^/  povray /' || true
grep -E "wrote" lancer.log | sed 's/^/  /' || true
if [ -n "$keep" ]; then mkdir -p "$keep"; cp pov.png lancer.png "$keep/"; fi
