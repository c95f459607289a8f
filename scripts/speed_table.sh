#!/usr/bin/env bash
# The speed benchmarks of issue 10, side by side with povray in one run (a benchmark, not a test;
# it takes minutes of CPU, so it runs under `nice`). Prints markdown for docs/performance.md.
#
# 1. Every sample scene lancer renders at SSIM >= 0.95 (from $SPEED_TSV, else
#    docs/conformance.tsv), 320x240, no AA (-A), one thread each side (+WT1), best of
#    REPS: lancer's own phases (parse + build + render from its statistics line; not the
#    writing of the file) against POV-Ray's Parse + Bounding + Photon + Radiosity + Trace times from its
#    statistics (the photon and radiosity phases are the same work lancer does in its render).
#    Per-scene ratio lancer/povray and the geometric mean over scenes where POV-Ray works at
#    least 0.05 s. With -b, a second lancer binary (e.g. main before a change) gets a column.
# 2. 10,000 spheres in one union against the same spheres outside any union.
# 4. scenes/mirror_spheres.pov at 512x512, one thread: million rays per second, counting every
#    ray lancer traces (camera, reflected, refracted and shadow rays, its statistics line)
#    over its render phase.
#
# usage: scripts/speed_table.sh [-c] [-n lancer] [-b other_lancer] [-r reps] [-s only_scene ...]
#   -n: the lancer binary measured (default target/release/lancer)
#   -c: CPU seconds instead of wall-clock phases, for a shared machine: POV-Ray's
#       "CPU-seconds total" of Parse, Bounding, Photon, Radiosity and Trace against lancer's whole process
#       (task-clock from `perf stat`, or user + system from /usr/bin/time in 10 ms steps when
#       perf is missing) writing a PPM file (+FP), whose writing costs next to nothing (a PNG's
#       compression does: 10-20 ms at 320x240), so it is parse, build and render plus start-up
#       (subtracting the write phase's wall time does not work under load: waiting for a core
#       counts in it).
#       Benchmark 1 and 2 only use this.
set -uo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
cd "$(dirname "$0")/.."
lancer=$PWD/target/release/lancer
have_perf=0
perf stat -x, -e task-clock -o /dev/null true 2>/dev/null && have_perf=1
other=
reps=2
only=()
cpu=0
while getopts "cn:b:r:s:" opt; do
  case $opt in
    c) cpu=1 ;;
    n) lancer=$OPTARG ;;
    b) other=$OPTARG ;;
    r) reps=$OPTARG ;;
    s) only+=("$OPTARG") ;;
    *) echo "usage: $0 [-b other_lancer] [-r reps] [-s scene]..." >&2; exit 2 ;;
  esac
done
[ -x "$lancer" ] || { echo "no lancer binary $lancer: cargo build --release" >&2; exit 2; }
command -v povray >/dev/null || { echo "povray not found" >&2; exit 2; }
# The scene list: $SPEED_TSV, else the committed conformance report.
tsv=${SPEED_TSV:-docs/conformance.tsv}
inc=/usr/share/povray-3.7/include
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Some scenes write files that others read: work in a copy.
cp -rL /usr/share/povray-3.7/scenes "$tmp/samples" 2>/dev/null
chmod -R u+w "$tmp/samples"

# Seconds of work from a statistics text: POV-Ray's "... Time: ... (0.123 seconds)" lines for
# Parse, Bounding and Trace; lancer's "parse 0.1s, build 0.1s, render 0.2s" phases.
pov_work() {
  if [ "$cpu" = 1 ]; then
    # The "using 1 thread(s) with X CPU-seconds total" line after each phase's time.
    grep -A1 -E "^ *(Parse|Bounding|Photon|Radiosity|Trace) Time:" | grep -oE "with [0-9.]+ CPU-seconds" | awk '{s += $2} END {printf "%.3f", s}'
  else
    grep -E "^ *(Parse|Bounding|Photon|Radiosity|Trace) Time:" | grep -oE "\([0-9.]+ seconds\)" | tr -d '(' | awk '{s += $1} END {printf "%.3f", s}'
  fi
}
lancer_work() { grep -oE "(parse|build|render) [0-9.]+s" | awk '{s += $2} END {printf "%.3f", s}'; }
best() { sort -g | head -1; }

# run_pov SCENE_PATH W H -> work seconds (best of reps), or "fail"
run_pov() {
  local path=$1 w=$2 h=$3 dir i t
  dir=$(dirname "$path")
  for i in $(seq "$reps"); do
    (cd "$dir" && nice timeout 300 povray -D -V +FN8 -A "+W$w" "+H$h" +WT1 "+L$dir" "+L$inc" "+I$path" "+O$tmp/p.png" 2>&1) | pov_work
    echo
  done | grep . | best
}
run_lancer() {
  local bin=$1 path=$2 w=$3 h=$4 dir i
  dir=$(dirname "$path")
  for i in $(seq "$reps"); do
    if [ "$cpu" = 1 ]; then
      # PPM: writing it costs next to nothing, so the process's CPU is parse, build and render.
      if [ "$have_perf" = 1 ]; then
        # perf's task-clock counts in nanoseconds; /usr/bin/time's 10 ms steps were a fifth of
        # the smallest scenes' time.
        rm -f "$tmp/perf.txt"
        if (cd "$dir" && nice timeout 300 perf stat -x, -e task-clock -o "$tmp/perf.txt" "$bin" -D -V +FP -A "+W$w" "+H$h" +WT1 "+L$dir" "+L$inc" "+I$path" "+O$tmp/l.ppm" 2>&1 >/dev/null) | grep -qE "wrote"; then
          awk -F, '$3 ~ /^task-clock/ {printf "%.4f", $1 / 1000}' "$tmp/perf.txt"
        fi
      else
        (cd "$dir" && nice timeout 300 /usr/bin/time -f "cpu %U %S" "$bin" -D -V +FP -A "+W$w" "+H$h" +WT1 "+L$dir" "+L$inc" "+I$path" "+O$tmp/l.ppm" 2>&1 >/dev/null) |
          grep -B1 -E "^cpu " | paste -sd' ' | grep -E "wrote" | grep -oE "cpu [0-9.]+ [0-9.]+$" | awk '{printf "%.3f", $2 + $3}'
      fi
    else
      (cd "$dir" && nice timeout 300 "$bin" -D -V +FN8 -A "+W$w" "+H$h" +WT1 "+L$dir" "+L$inc" "+I$path" "+O$tmp/l.png" 2>&1) | grep -E "wrote" | lancer_work
    fi
    echo
  done | grep . | best
}

scenes=("${only[@]}")
if [ ${#scenes[@]} -eq 0 ]; then
  mapfile -t scenes < <(awk -F'\t' '$2 == "ssim>=0.95" {print $1}' "$tsv")
fi

what="wall-clock phases"
[ "$cpu" = 1 ] && what="CPU seconds (povray: its phases' CPU-seconds; lancer: its whole process, writing PPM)"
echo "### Benchmark 1: sample scenes at SSIM >= 0.95 ($(basename "$tsv")), 320x240 -A +WT1, best of $reps, $what"
echo
if [ -n "$other" ]; then
  echo "| scene | povray s | lancer s | lancer/povray | $(basename "$other") s | $(basename "$other")/povray |"
  echo "|---|---:|---:|---:|---:|---:|"
else
  echo "| scene | povray s | lancer s | lancer/povray |"
  echo "|---|---:|---:|---:|"
fi
rows=$tmp/rows
: >"$rows"
for s in "${scenes[@]}"; do
  path=$tmp/samples/$s
  p=$(run_pov "$path" 320 240)
  l=$(run_lancer "$lancer" "$path" 320 240)
  [ -n "$p" ] && [ -n "$l" ] || { echo "| $s | ${p:-fail} | ${l:-fail} | | |"; continue; }
  r=$(awk -v a="$l" -v b="$p" 'BEGIN {if (b > 0) printf "%.2f", a / b; else print "-"}')
  if [ -n "$other" ]; then
    o=$(run_lancer "$other" "$path" 320 240)
    ro=$(awk -v a="${o:-0}" -v b="$p" 'BEGIN {if (b > 0 && a > 0) printf "%.2f", a / b; else print "-"}')
    echo "| $s | $p | $l | $r | ${o:-fail} | $ro |"
    echo "$p $l ${o:-0}" >>"$rows"
  else
    echo "| $s | $p | $l | $r |"
    echo "$p $l 0" >>"$rows"
  fi
done
echo
awk -v other="$other" '
  $1 >= 0.05 && $2 > 0 { n++; g += log($2 / $1); sp += $1; sl += $2; if ($3 > 0) { no++; go += log($3 / $1); so += $3 } ; if ($2 / $1 > 1) slow++ }
  END {
    printf "Geometric mean lancer/povray over %d scenes where POV-Ray works >= 0.05 s: **%.3f** (sums: lancer %.1f s, povray %.1f s; %d scenes above 1.0)\n", n, exp(g / n), sl, sp, slow
    if (other != "" && no > 0) printf "\nSame for %s: %.3f over %d scenes (sum %.1f s)\n", other, exp(go / no), no, so
  }' "$rows"
echo

echo "### Benchmark 2: 10,000 spheres, 320x240 -A +WT1, best of $reps"
echo
gen() { # gen UNION(0/1)
  echo '#version 3.7; global_settings { assumed_gamma 1.0 }'
  echo 'camera { location <0, 0, -30> look_at <0, 0, 0> } light_source { <20, 30, -40> rgb 1 }'
  echo "#declare R = seed(1); #if ($1) union { #end"
  echo '#declare I = 0; #while (I < 10000)'
  echo '  sphere { <rand(R)*20-10, rand(R)*20-10, rand(R)*20-10>, 0.3 pigment { rgb <rand(R), rand(R), 1> } }'
  echo '  #declare I = I + 1; #end'
  echo "#if ($1) } #end"
}
gen 1 >"$tmp/union.pov"
gen 0 >"$tmp/loose.pov"
echo "| | povray s | lancer s |$([ -n "$other" ] && echo " $(basename "$other") s |")"
echo "|---|---:|---:|$([ -n "$other" ] && echo "---:|")"
for k in union loose; do
  p=$(run_pov "$tmp/$k.pov" 320 240)
  l=$(run_lancer "$lancer" "$tmp/$k.pov" 320 240)
  o=$([ -n "$other" ] && echo " $(run_lancer "$other" "$tmp/$k.pov" 320 240) |")
  echo "| $k | $p | $l |$o"
done
echo

echo "### Benchmark 4: scenes/mirror_spheres.pov 512x512 -A +WT1, best of $reps"
echo
echo "Rays: every ray lancer traces (camera, reflected, refracted, shadow), over its render phase."
echo
mirror() {
  local bin=$1 i
  for i in $(seq "$reps"); do
    (cd scenes && nice "$bin" -D -V +FN8 -A +W512 +H512 +WT1 +Imirror_spheres.pov "+O$tmp/m.png" 2>&1) |
      grep wrote | sed -E 's/.*render ([0-9.]+)s.* ([0-9]+) rays.*/\1 \2/'
  done | sort -g | head -1 | awk '{printf "render %.3f s, %d rays, %.2f M rays/s", $1, $2, $2 / $1 / 1e6}'
}
# The same rays over the whole process's CPU time (parse, render and PNG writing): on a loaded
# machine the render phase's wall clock includes time spent waiting for a core.
mirror_cpu() {
  local bin=$1 i t rays
  for i in $(seq "$reps"); do
    t=$(cd scenes && TIMEFORMAT='%U %S' && { time nice "$bin" -D -V +FN8 -A +W512 +H512 +WT1 +Imirror_spheres.pov "+O$tmp/m.png" 2>"$tmp/m.err" >/dev/null; } 2>&1)
    rays=$(grep -oE "[0-9]+ rays" "$tmp/m.err" | grep -oE "[0-9]+")
    echo "$t ${rays:-0}" | awk '{print $1 + $2, $3}'
  done | sort -g | head -1 | awk '{printf "%.3f s CPU, %.2f M rays/s per CPU second", $1, $2 / $1 / 1e6}'
}
echo "- lancer: $(mirror "$lancer"); $(mirror_cpu "$lancer")"
[ -n "$other" ] && echo "- $(basename "$other"): $(mirror "$other"); $(mirror_cpu "$other")"
p=$(run_pov "$PWD/scenes/mirror_spheres.pov" 512 512)
echo "- povray: $p s (parse + bounding + trace)"
