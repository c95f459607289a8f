#!/usr/bin/env bash
# The radiosity benchmark of issue 12 (a benchmark, not a test: minutes of CPU, run under
# `nice`): the 12 sample scenes where radiosity is the only missing feature, 160x120 -A, one
# thread each side (+WT1). Per scene: lancer's SSIM against povray's render, povray's CPU
# seconds for Radiosity + Trace (its statistics' "CPU-seconds total" lines) against lancer's
# whole process (perf's task-clock, else user + system from /usr/bin/time; writing PPM: parse and build included, a
# few ms on these scenes), and their ratio. CPU seconds, not wall clock: the machine is
# shared and waiting for a core would count in wall time.
#
# usage: scripts/radiosity_table.sh [-n lancer] [-b other_lancer] [-W width -H height] [-s scene]...
set -uo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
cd "$(dirname "$0")/.."
lancer=$PWD/target/release/lancer
other=
w=160
h=120
only=()
while getopts "n:b:W:H:s:" opt; do
  case $opt in
    n) lancer=$OPTARG ;;
    b) other=$OPTARG ;;
    W) w=$OPTARG ;;
    H) h=$OPTARG ;;
    s) only+=("$OPTARG") ;;
    *) echo "usage: $0 [-n lancer] [-b other] [-W w -H h] [-s scene]..." >&2; exit 2 ;;
  esac
done
scenes=("${only[@]}")
if [ ${#scenes[@]} -eq 0 ]; then
  scenes=(advanced/blocks/stackerday.pov advanced/blocks/stackernight.pov
    animations/raddem/raddem.pov radiosity/cornell.pov radiosity/patio-radio_36.pov
    radiosity/patio-radio_37.pov radiosity/rad_def_test_36.pov radiosity/rad_def_test_37.pov
    radiosity/radiosity2.pov radiosity/radiosity3.pov radiosity/radiosity_36.pov
    radiosity/radiosity_37.pov)
fi
inc=/usr/share/povray-3.7/include
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -rL /usr/share/povray-3.7/scenes "$tmp/samples" 2>/dev/null
chmod -R u+w "$tmp/samples"

# lancer's CPU seconds (user + system) and its picture as PNG for the comparison.
run_lancer() {
  local bin=$1 path=$2 out=$3 dir
  dir=$(dirname "$path")
  if command -v perf >/dev/null; then
    # task-clock: the process's CPU time to the millisecond (/usr/bin/time's is 10 ms steps,
    # coarse for the small scenes).
    (cd "$dir" && nice perf stat -x, -e task-clock "$bin" -D -V +FP -A "+W$w" "+H$h" +WT1 "+L$dir" "+L$inc" "+I$path" "+O$out.ppm" 2>&1 >/dev/null) |
      awk -F, '/task-clock/ {printf "%.3f", $1 / 1000}'
  else
    (cd "$dir" && nice /usr/bin/time -f "cpu %U %S" "$bin" -D -V +FP -A "+W$w" "+H$h" +WT1 "+L$dir" "+L$inc" "+I$path" "+O$out.ppm" 2>&1 >/dev/null) |
      grep -oE "^cpu [0-9.]+ [0-9.]+" | awk '{printf "%.3f", $2 + $3}'
  fi
  "$bin" compare "$tmp/pov.png" "$out.ppm" 2>/dev/null | awk '/^ssim/ {printf " %.4f", $2}'
}

echo "### Radiosity scenes, ${w}x${h} -A +WT1, CPU seconds (povray: Radiosity + Trace; lancer: whole process)"
echo
if [ -n "$other" ]; then
  echo "| scene | SSIM | povray s | lancer s | lancer/povray | $(basename "$other") SSIM | $(basename "$other") s |"
  echo "|---|---:|---:|---:|---:|---:|---:|"
else
  echo "| scene | SSIM | povray s | lancer s | lancer/povray |"
  echo "|---|---:|---:|---:|---:|"
fi
for s in "${scenes[@]}"; do
  path=$tmp/samples/$s
  dir=$(dirname "$path")
  p=$( (cd "$dir" && nice povray -D -V +FN8 -A "+W$w" "+H$h" +WT1 "+L$dir" "+L$inc" "+I$path" "+O$tmp/pov.png" 2>&1) |
    grep -A1 -E "^ *(Radiosity|Trace) Time:" | grep -oE "with [0-9.]+ CPU-seconds" | awk '{s += $2} END {printf "%.3f", s}')
  read -r l q <<<"$(run_lancer "$lancer" "$path" "$tmp/l")"
  r=$(awk -v a="$l" -v b="$p" 'BEGIN {if (b > 0) printf "%.2f", a / b; else print "-"}')
  if [ -n "$other" ]; then
    read -r o oq <<<"$(run_lancer "$other" "$path" "$tmp/o")"
    echo "| $s | $q | $p | $l | $r | $oq | $o |"
  else
    echo "| $s | $q | $p | $l | $r |"
  fi
done
