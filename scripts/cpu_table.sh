#!/usr/bin/env bash
# CPU seconds of a few sample scenes: two lancer binaries (whole process, `perf stat -e
# task-clock`, best of REPS, writing PPM so PNG compression is not counted) beside POV-Ray (the
# CPU-seconds its Parse, Bounding, Photon, Radiosity and Trace phases report, best of REPS). 320x240, no AA, one
# thread each. For a shared machine, where wall time says more about the load than about either
# renderer. A benchmark, not a test. Prints a markdown table.
#
# usage: scripts/cpu_table.sh [-b baseline] [-n new] [-r reps] scene...
#   scene: a path under the sample directory without .pov, e.g. objects/superel1
set -uo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
cd "$(dirname "$0")/.."
base=/work/baseline/lancer-main
new=$PWD/target/release/lancer
reps=3
while getopts "b:n:r:" opt; do
  case $opt in
    b) base=$OPTARG ;;
    n) new=$OPTARG ;;
    r) reps=$OPTARG ;;
    *) echo "usage: $0 [-b baseline] [-n new] [-r reps] scene..." >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
command -v perf >/dev/null || { echo "perf not found" >&2; exit 2; }
samples=/usr/share/povray-3.7/scenes
inc=/usr/share/povray-3.7/include
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
lancer_ms() { # binary scene-path
  local dir best=""
  dir=$(dirname "$2")
  for _ in $(seq "$reps"); do
    # In the scratch directory: scenes that write files (#fopen) write them there.
    (cd "$tmp" && perf stat -x, -e task-clock -o "$tmp/stat" "$1" -A +W320 +H240 +WT1 +FP "+L$dir" "+L$inc" \
      "+I$2" "+O$tmp/l.ppm" -q >/dev/null 2>&1)
    grep task-clock "$tmp/stat" | cut -d, -f1
  done | sort -g | head -1 | awk '{printf "%.0f", $1}'
}
pov_ms() { # scene-path: POV-Ray's Parse + Bounding + Photon + Radiosity + Trace CPU-seconds, in ms
  local dir
  dir=$(dirname "$1")
  for _ in $(seq "$reps"); do
    (cd "$dir" && povray -D -V +FN8 -A +W320 +H240 +WT1 "+L$dir" "+L$inc" "+I$1" "+O$tmp/p.png" 2>&1) |
      grep -A1 -E "^ *(Parse|Bounding|Photon|Radiosity|Trace) Time:" | grep -oE "with [0-9.]+ CPU-seconds" |
      awk '{s += $2} END {printf "%.0f\n", s * 1000}'
  done | sort -g | head -1
}
echo "| scene | $(basename "$base") ms | $(basename "$new") ms | povray ms | before/povray | after/povray |"
echo "|---|---:|---:|---:|---:|---:|"
for s in "$@"; do
  path=$samples/$s.pov
  b=$(lancer_ms "$base" "$path")
  n=$(lancer_ms "$new" "$path")
  p=$(pov_ms "$path")
  awk -v s="$s" -v b="$b" -v n="$n" -v p="$p" \
    'BEGIN {printf "| %s | %d | %d | %d | %.2f | %.2f |\n", s, b, n, p, b / p, n / p}'
done
