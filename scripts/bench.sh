#!/usr/bin/env bash
# Benchmark (not a test): render one scene with POV-Ray and with lancer,
# side by side, several times, and compare the best times.
#
#   scripts/bench.sh [--reps N] [--size N] [--scene FILE.pov] [--povray-only]
#
# Defaults: 3 repetitions, 512x512, scenes/mirror_spheres.pov, no anti-aliasing.
# For each renderer it reports the whole-process wall time and CPU time
# (user+sys, from /usr/bin/time), best of N.  For POV-Ray it also reports
# its own parse and trace times from its render statistics (printed on
# stderr even with -V).  POV-Ray's process has a fixed overhead of about
# 0.6 s of idle wall time (startup/shutdown of its front end) even for an
# empty scene, hence the second ratio against its trace phase alone.
#
# lancer is target/release/lancer, built with `cargo build --release` when
# missing (override with LANCER=/path/to/binary; POVRAY=... likewise).
# Both renderers get the same POV-Ray options verbatim; both use all cores.
set -euo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
REPS=3
SIZE=512
SCENE="$ROOT/scenes/mirror_spheres.pov"
POVRAY_ONLY=0
POVRAY="${POVRAY:-povray}"
LANCER="${LANCER:-$ROOT/target/release/lancer}"
INC=/usr/share/povray-3.7/include

usage() { sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; }

while [ "$#" -gt 0 ]; do
  case "$1" in
    --reps) REPS="$2"; shift 2 ;;
    --size) SIZE="$2"; shift 2 ;;
    --scene) SCENE="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2 ;;
    --povray-only) POVRAY_ONLY=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "error: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done

die() { echo "error: $*" >&2; exit 1; }

[ -f "$SCENE" ] || die "scene $SCENE not found"
case "$REPS" in ''|*[!0-9]*|0) die "--reps needs a positive integer" ;; esac
case "$SIZE" in ''|*[!0-9]*|0) die "--size needs a positive integer" ;; esac
command -v "$POVRAY" >/dev/null 2>&1 ||
  die "'$POVRAY' not found: install POV-Ray 3.7 (Debian: apt-get install povray povray-includes)"
[ -x /usr/bin/time ] ||
  die "/usr/bin/time not found: install it (Debian: apt-get install time)"

if [ "$POVRAY_ONLY" -eq 0 ] && [ ! -x "$LANCER" ]; then
  command -v cargo >/dev/null 2>&1 || die "cargo not found, cannot build lancer (or use --povray-only)"
  echo "building lancer (cargo build --release) ..."
  if ! (cd "$ROOT" && cargo build --release --quiet); then
    die "cargo build --release failed (use --povray-only to time POV-Ray alone)"
  fi
  [ -x "$LANCER" ] || die "build finished but $LANCER does not exist"
fi

WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
SCENE_DIR="$(dirname "$SCENE")"
OPTS=(+W"$SIZE" +H"$SIZE" -A)

# run_timed <log> <cmd...>: run the command with output to <log>, and append
# "wall cpu" (seconds; cpu = user + sys) to <log>.times
run_timed() {
  local log="$1"; shift
  if ! /usr/bin/time -f '%e %U %S' -o "$log.time" "$@" >"$log" 2>&1; then
    echo "error: command failed: $*" >&2
    tail -20 "$log" >&2
    exit 1
  fi
  awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' "$log.time" >>"$log.times"
}

# povray_stat <log> <Parse|Trace>: seconds and CPU-seconds of that phase
povray_stat() {
  awk -v phase="$2" '
    $1 == phase":" || ($1 == phase && $2 == "Time:") {
      s = $0; sub(/.*\(/, "", s); sub(/ seconds.*/, "", s); secs = s; want = 1; next }
    want && /CPU-seconds/ {
      c = $0; sub(/.* with /, "", c); sub(/ CPU-seconds.*/, "", c); cpu = c; want = 0 }
    END { printf "%s %s\n", (secs == "" ? "nan" : secs), (cpu == "" ? "nan" : cpu) }
  ' "$1"
}

echo "scene:   ${SCENE#$ROOT/}"
echo "options: ${OPTS[*]}   reps: $REPS   cores: $(nproc)"
echo "povray:  $("$POVRAY" --version 2>&1 | grep -m1 '^POV-Ray' || echo unknown)"
[ "$POVRAY_ONLY" -eq 1 ] || echo "lancer:  ${LANCER#$ROOT/}"
echo

for i in $(seq 1 "$REPS"); do
  plog="$WORK/povray.$i.log"
  # Debian's povray reads /etc/povray/3.7/povray.ini first: pass everything.
  run_timed "$plog" "$POVRAY" -D -V +FN8 "${OPTS[@]}" +L"$SCENE_DIR" +L"$INC" \
    +I"$SCENE" +O"$WORK/povray.png"
  tail -1 "$plog.times" >>"$WORK/povray.times"
  povray_stat "$plog" Parse >>"$WORK/povray.parse"
  povray_stat "$plog" Trace >>"$WORK/povray.trace"
  printf 'run %d  povray  wall %6.3fs  cpu %6.3fs  (trace %ss)\n' "$i" \
    $(tail -1 "$plog.times") "$(tail -1 "$WORK/povray.trace" | cut -d' ' -f1)"

  if [ "$POVRAY_ONLY" -eq 0 ]; then
    llog="$WORK/lancer.$i.log"
    run_timed "$llog" "$LANCER" "$SCENE" "${OPTS[@]}" +O"$WORK/lancer.png"
    tail -1 "$llog.times" >>"$WORK/lancer.times"
    printf 'run %d  lancer  wall %6.3fs  cpu %6.3fs\n' "$i" $(tail -1 "$llog.times")
  fi
done

# best (minimum) of each column
best() { awk -v c="$2" 'NR == 1 || $c < m { m = $c } END { printf "%.3f", m }' "$1"; }

pw=$(best "$WORK/povray.times" 1); pc=$(best "$WORK/povray.times" 2)
pp=$(best "$WORK/povray.parse" 1)
pt=$(best "$WORK/povray.trace" 1); ptc=$(best "$WORK/povray.trace" 2)

echo
echo "best of $REPS:"
printf '  povray  wall %6.3fs  cpu %6.3fs   parse %6.3fs   trace %6.3fs (trace cpu %6.3fs)\n' \
  "$pw" "$pc" "$pp" "$pt" "$ptc"
if [ "$POVRAY_ONLY" -eq 0 ]; then
  lw=$(best "$WORK/lancer.times" 1); lc=$(best "$WORK/lancer.times" 2)
  printf '  lancer  wall %6.3fs  cpu %6.3fs\n' "$lw" "$lc"
  echo
  awk -v lw="$lw" -v lc="$lc" -v pw="$pw" -v pc="$pc" -v pt="$pt" -v pp="$pp" '
    function ratio(a, b) { return (b > 0) ? sprintf("%.2f", a / b) : "n/a" }
    BEGIN {
      print "  lancer wall / povray wall:          " ratio(lw, pw)
      print "  lancer cpu  / povray cpu:           " ratio(lc, pc)
      print "  lancer wall / povray parse+trace:   " ratio(lw, pp + pt)
      print "  lancer wall / povray trace phase:   " ratio(lw, pt)
      print "  (below 1 means lancer is faster)"
    }'
fi
