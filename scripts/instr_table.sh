#!/usr/bin/env bash
# Instructions executed by lancer and by POV-Ray on a few sample scenes, counted by callgrind.
# A benchmark, not a test. On a shared machine one scene's CPU time moves by up to +-40 % between
# runs; instruction counts do not move at all, so this table says which scenes are really above
# POV-Ray and by how much, where cpu_table.sh's rows can only be trusted in aggregate.
#
# What is counted on each side, so the ratio matches cpu_table.sh's:
# - lancer: the whole process (start-up, parse, build, render, writing a PPM).
# - POV-Ray: only the threads that run its Parse, Bounding, Photon, Radiosity and Trace tasks,
#   the phases whose CPU-seconds cpu_table.sh and speed_table.sh add up. callgrind numbers
#   threads in the order they start and gives a finished thread's number to the next one, and
#   POV-Ray 3.7 starts five threads of its own (main, front end, messaging) before the parser,
#   so threads 6 and up are its tasks. Checked with `perf record -e task-clock` per thread on
#   incdemo/debug and radiosity/rad_def_test_37: the parser's, radiosity's and the trace's
#   threads each took the CPU-seconds POV-Ray reports for that phase (docs/performance.md,
#   "Seventeenth pass: the lead").
# An instruction is not a fixed time: in the same sitting incdemo/debug ran 5.3 G instructions
# per CPU-second in POV-Ray's trace thread and 4.9 G in lancer, so read the ratio as a guide
# within ~10 %, measured without noise.
#
# usage: scripts/instr_table.sh [-n lancer] [-b other_lancer] [-W width] [-H height] scene...
#   scene: a path under the sample directory without .pov, e.g. objects/superel1
#   default 160x120 (callgrind runs 30-100x slower than the program).
set -uo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
cd "$(dirname "$0")/.."
new=$PWD/target/release/lancer
base=
w=160
h=120
while getopts "n:b:W:H:" opt; do
  case $opt in
    n) new=$OPTARG ;;
    b) base=$OPTARG ;;
    W) w=$OPTARG ;;
    H) h=$OPTARG ;;
    *) echo "usage: $0 [-n lancer] [-b other_lancer] [-W width] [-H height] scene..." >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
command -v valgrind >/dev/null || { echo "valgrind not found (apt-get install valgrind)" >&2; exit 2; }
command -v povray >/dev/null || { echo "povray not found" >&2; exit 2; }
samples=/usr/share/povray-3.7/scenes
inc=/usr/share/povray-3.7/include
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
opts=(-A "+W$w" "+H$h" +WT1 -D)
lancer_ir() { # binary scene-path: millions of instructions of the whole process
  local dir
  dir=$(dirname "$2")
  rm -f "$tmp"/l.cg*
  (cd "$tmp" && valgrind --tool=callgrind --callgrind-out-file="$tmp/l.cg" "$1" "${opts[@]}" +FP \
    "+L$dir" "+L$inc" "+I$2" "+O$tmp/l.ppm" -q >/dev/null 2>&1)
  grep -h '^summary:' "$tmp"/l.cg* | awk '{s += $2} END {printf "%.1f", s / 1e6}'
}
pov_ir() { # scene-path: millions of instructions in POV-Ray's task threads (6 and up)
  local dir
  dir=$(dirname "$1")
  rm -f "$tmp"/p.cg*
  (cd "$tmp" && valgrind --tool=callgrind --separate-threads=yes --callgrind-out-file="$tmp/p.cg" \
    povray "${opts[@]}" +FN8 -V "+L$dir" "+L$inc" "+I$1" "+O$tmp/p.png" >/dev/null 2>&1)
  for f in "$tmp"/p.cg-*; do
    n=${f##*-}
    [ "$((10#$n))" -ge 6 ] && grep -h '^summary:' "$f"
  done | awk '{s += $2} END {printf "%.1f", s / 1e6}'
}
if [ -n "$base" ]; then
  echo "| scene | povray M | $(basename "$base") M | $(basename "$new") M | before/povray | after/povray |"
  echo "|---|---:|---:|---:|---:|---:|"
else
  echo "| scene | povray M | lancer M | lancer/povray |"
  echo "|---|---:|---:|---:|"
fi
for s in "$@"; do
  path=$samples/$s.pov
  p=$(pov_ir "$path")
  n=$(lancer_ir "$new" "$path")
  if [ "$p" = 0.0 ] || [ "$n" = 0.0 ]; then
    echo "| $s | $p | $n | (a run under valgrind failed) |"
  elif [ -n "$base" ]; then
    b=$(lancer_ir "$base" "$path")
    awk -v s="$s" -v b="$b" -v n="$n" -v p="$p" \
      'BEGIN {printf "| %s | %.1f | %.1f | %.1f | %.2f | %.2f |\n", s, p, b, n, b / p, n / p}'
  else
    awk -v s="$s" -v n="$n" -v p="$p" 'BEGIN {printf "| %s | %.1f | %.1f | %.2f |\n", s, p, n, n / p}'
  fi
done
