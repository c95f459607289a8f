#!/usr/bin/env bash
# Benchmark (not a test): scale and memory, lancer and POV-Ray side by side in one run.
#
#   scripts/scale_bench.sh [--cases LIST] [--threads N|default] [--size WxH] [--keep DIR]
#
# Cases (comma-separated, default "spheres1m,spheres300k,mesh1m"):
#   spheres1m    1,000,000 spheres made by a #while loop, each with its own pigment
#   spheres300k  300,000 spheres likewise
#   mesh1m       a mesh2 of 1,002,528 triangles (a 708x708 height grid), written by this script
#   shared1m     1,000,000 spheres sharing one #declare'd texture
#   big20k       a small scene at 20000x20000 (PNG; the picture's memory, not the scene's)
#   huge100k     the same at 100000x100000: must stream or refuse cleanly, never abort
# The scenes are generated into a temporary directory (nothing large is committed).
#
# For each case and renderer: whole-process wall time and peak resident memory (maxrss from
# /usr/bin/time -v), and the phases each program reports (POV-Ray: Parse, Bounding, Trace;
# lancer: its statistics line). --threads 1 passes +WT1 to both (per-core numbers); the
# default uses every core on both sides. lancer is target/release/lancer (LANCER=... to
# override), POV-Ray is `povray` (POVRAY=...).
set -euo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CASES="spheres1m,spheres300k,mesh1m"
THREADS=default
SIZE=320x240
KEEP=""
POVRAY="${POVRAY:-povray}"
LANCER="${LANCER:-$ROOT/target/release/lancer}"
INC=/usr/share/povray-3.7/include

usage() { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; }
while [ "$#" -gt 0 ]; do
  case "$1" in
    --cases) CASES="$2"; shift 2 ;;
    --threads) THREADS="$2"; shift 2 ;;
    --size) SIZE="$2"; shift 2 ;;
    --keep) KEEP="$2"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "error: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
command -v "$POVRAY" >/dev/null || { echo "error: $POVRAY not found" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "error: /usr/bin/time not found (apt-get install time)" >&2; exit 1; }
[ -x "$LANCER" ] || (cd "$ROOT" && cargo build --release --quiet)

if [ -n "$KEEP" ]; then WORK="$KEEP"; mkdir -p "$WORK"; else
  WORK="$(mktemp -d)"; trap 'rm -rf "$WORK"' EXIT; fi

HEADER='#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <50, 60, -120> look_at <50, 50, 50> }
light_source { <-100, 300, -300> rgb 1 }
'

spheres() { # spheres <count> <shared: 0|1>
  {
    echo "$HEADER"
    echo '#declare T = texture { pigment { rgb <0.8, 0.6, 0.3> } finish { phong 0.5 } }'
    echo "#declare N = $1;"
    echo '#declare I = 0;'
    echo '#while (I < N)'
    if [ "$2" = 1 ]; then
      echo '  sphere { <mod(I, 100), mod(div(I, 100), 100), div(I, 10000)>, 0.4 texture { T } }'
    else
      echo '  sphere { <mod(I, 100), mod(div(I, 100), 100), div(I, 10000)>, 0.4'
      echo '    pigment { rgb <mod(I, 100) / 100, mod(div(I, 100), 100) / 100, 0.5> } }'
    fi
    echo '  #declare I = I + 1;'
    echo '#end'
  }
}

mesh() { # a (n+1)^2-vertex height grid of 2n^2 triangles
  echo "$HEADER"
  awk -v n=708 'BEGIN {
    print "mesh2 {"; printf "  vertex_vectors { %d", (n + 1) * (n + 1)
    for (j = 0; j <= n; j++) for (i = 0; i <= n; i++)
      printf ",\n<%.4f,%.4f,%.4f>", i * 100 / n, 5 * sin(i * 0.05) * cos(j * 0.07) + 40, j * 100 / n
    printf "\n  }\n  face_indices { %d", 2 * n * n
    for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
      a = j * (n + 1) + i; b = a + 1; c = a + n + 1; d = c + 1
      printf ",\n<%d,%d,%d>,<%d,%d,%d>", a, b, d, a, d, c
    }
    print "\n  }\n  pigment { rgb <0.7, 0.8, 0.9> }\n}"
  }'
}

small() {
  echo "$HEADER"
  echo 'sphere { <50, 50, 50>, 30 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }'
  echo 'plane { y, 0 pigment { checker rgb 1 rgb 0.2 scale 10 } }'
}

# run <name> <log> <cmd...>: prints "wall maxrss_MB exit"
run() {
  local log="$2"; shift 2
  local rc=0
  /usr/bin/time -v -o "$log.time" "$@" >"$log" 2>&1 || rc=$?
  local wall rss
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, p, ":"); s = 0;
    for (i = 1; i <= n; i++) s = s * 60 + p[i]; printf "%.2f", s }' "$log.time")
  rss=$(awk -F': ' '/Maximum resident/ { printf "%.0f", $2 / 1024 }' "$log.time")
  echo "$wall $rss $rc"
}

pov_phase() { # seconds of a POV-Ray phase from its statistics
  awk -v phase="$2" '$1 == phase && $2 == "Time:" {
    s = $0; sub(/.*\(/, "", s); sub(/ seconds.*/, "", s); print s; exit }' "$1"
}

TOPT=()
[ "$THREADS" = default ] || TOPT=(+WT"$THREADS")
W=${SIZE%x*}; H=${SIZE#*x}
echo "# scale_bench  $(date -u '+%F %T') UTC  cores $(nproc)  threads $THREADS  size ${W}x${H}"
echo "# lancer: $LANCER  povray: $("$POVRAY" --version 2>&1 | grep -m1 '^POV-Ray' || echo '?')"
echo "# (the machine's load average: $(cut -d' ' -f1-3 /proc/loadavg); compare the two programs of one run)"
printf '%-12s %-7s %8s %9s %5s  %s\n' case prog wall_s peak_MB exit phases

IFS=, read -r -a LIST <<<"$CASES"
for c in "${LIST[@]}"; do
  w=$W; h=$H; aa=(-A)
  case "$c" in
    spheres1m) spheres 1000000 0 >"$WORK/$c.pov" ;;
    spheres300k) spheres 300000 0 >"$WORK/$c.pov" ;;
    shared1m) spheres 1000000 1 >"$WORK/$c.pov" ;;
    mesh1m) mesh >"$WORK/$c.pov" ;;
    big20k) small >"$WORK/$c.pov"; w=20000; h=20000 ;;
    huge100k) small >"$WORK/$c.pov"; w=100000; h=100000 ;;
    *) echo "error: unknown case $c" >&2; exit 2 ;;
  esac
  opts=(+W"$w" +H"$h" "${aa[@]}" "${TOPT[@]}")
  if [ "$c" != huge100k ]; then # POV-Ray would take hours to trace 10^10 pixels
    read -r pw pr prc < <(run povray "$WORK/$c.povray.log" "$POVRAY" -D -V +FN8 "${opts[@]}" \
      +L"$WORK" +L"$INC" +I"$WORK/$c.pov" +O"$WORK/$c.povray.png")
    printf '%-12s %-7s %8s %9s %5s  parse %s bounding %s trace %s\n' "$c" povray "$pw" "$pr" "$prc" \
      "$(pov_phase "$WORK/$c.povray.log" Parse)" "$(pov_phase "$WORK/$c.povray.log" Bounding)" \
      "$(pov_phase "$WORK/$c.povray.log" Trace)"
  fi
  lim=()
  # 10^10 pixels would take hours: watch the first minute (memory must stay bounded; exit 124
  # is the timeout, 1 a clean refusal, 134 an abort).
  [ "$c" = huge100k ] && lim=(timeout 60)
  read -r lw lr lrc < <(run lancer "$WORK/$c.lancer.log" "${lim[@]}" "$LANCER" "$WORK/$c.pov" "${opts[@]}" \
    +O"$WORK/$c.lancer.png")
  printf '%-12s %-7s %8s %9s %5s  %s\n' "$c" lancer "$lw" "$lr" "$lrc" \
    "$(grep -E 'lancer:|error' "$WORK/$c.lancer.log" | tail -1 | sed 's/^lancer: //' | cut -c1-160)"
  rm -f "$WORK/$c.povray.png" "$WORK/$c.lancer.png"
done
