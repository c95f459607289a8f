#!/usr/bin/env bash
# Byte-identity check: renders scenes with a reference lancer binary (default
# /work/baseline/lancer-main) and with this tree's release build, and compares the PNG files
# with `cmp`, or where the bytes differ, by their chunks and decoded rows (scripts/png_same.py:
# the compressed data may differ, the samples may not). For changes that must not move a single
# pixel (speed work, refactoring).
#
# Scenes: every scenes/*.pov of this repository, then the POV-Ray sample scenes the CI ratchet
# lists (tests/conformance/subset.txt), or the scene paths given as arguments (relative to the
# sample directory, or absolute). Sample scenes run in a scratch copy of the sample directory,
# because some scenes write files that others read.
#
# usage: scripts/identical_check.sh [-b baseline] [-n new] [-s WxH] [scene ...]
#   -n: the binary under test (default target/release/lancer; a copy lets you keep building)
# env:   JOBS (parallel renders per side, default 1), LIMIT (seconds per render, default 120),
#        OPTS (options replacing the default "-A +FN8": "+A0.3 +FN8" checks the anti-aliased
#        path, "-A +FN8 +WT2" the threaded one, "-A +FP" the PPM writer)
# exit:  0 when every picture is byte-identical, 1 otherwise (the differing scenes are listed)
set -uo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
cd "$(dirname "$0")/.."
base=/work/baseline/lancer-main
new=$PWD/target/release/lancer
size=160x120
while getopts "b:n:s:" opt; do
  case $opt in
    b) base=$OPTARG ;;
    n) new=$OPTARG ;;
    s) size=$OPTARG ;;
    *) echo "usage: $0 [-b baseline] [-n new] [-s WxH] [scene ...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ -x "$base" ] || { echo "no baseline binary $base" >&2; exit 2; }
[ -x "$new" ] || { echo "no release build: cargo build --release" >&2; exit 2; }
w=${size%x*}
h=${size#*x}
limit=${LIMIT:-120}
samples=/usr/share/povray-3.7/scenes
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -rL "$samples" "$tmp/samples" 2>/dev/null
chmod -R u+w "$tmp/samples"

scenes=()
if [ $# -gt 0 ]; then
  scenes=("$@")
else
  for f in scenes/*.pov; do scenes+=("$PWD/$f"); done
  while read -r line; do
    case $line in "" | "#"* | min_good*) continue ;; esac
    scenes+=("$line")
  done <tests/conformance/subset.txt
fi

# render BINARY SCENE OUT: the canonical options, in the scene's directory.
render() {
  local bin=$1 scene=$2 out=$3 path dir
  case $scene in /*) path=$scene ;; *) path=$tmp/samples/$scene ;; esac
  dir=$(dirname "$path")
  (cd "$dir" && nice timeout "$limit" "$bin" -D -V $opts "+W$w" "+H$h" "+L$dir" \
    +L/usr/share/povray-3.7/include "+I$path" "+O$out" -q >/dev/null 2>&1)
}

check_one() {
  local scene=$1 key
  key=$(echo "$scene" | tr '/' '_')
  render "$base" "$scene" "$tmp/$key.base.png"
  local rb=$?
  render "$new" "$scene" "$tmp/$key.new.png"
  local rn=$?
  if [ $rb -ne 0 ] || [ $rn -ne 0 ]; then
    if [ $rb -ne $rn ]; then
      echo "DIFFER (exit $rb vs $rn) $scene"
    else
      echo "skip (both exit $rb) $scene"
    fi
  elif cmp -s "$tmp/$key.base.png" "$tmp/$key.new.png"; then
    echo "same $scene"
  elif "$same_png" "$tmp/$key.base.png" "$tmp/$key.new.png"; then
    # Another compression of the same samples and chunks (a change of the PNG writer's
    # deflate settings, or a baseline from before one).
    echo "same (pixels; compressed differently) $scene"
  else
    echo "DIFFER $scene"
  fi
  rm -f "$tmp/$key.base.png" "$tmp/$key.new.png"
}
export -f check_one render
same_png=$PWD/scripts/png_same.py
opts=${OPTS:--A +FN8}
export base new w h limit tmp same_png opts

printf '%s\n' "${scenes[@]}" | xargs -P "${JOBS:-1}" -I{} bash -c 'check_one "$1"' _ {} | tee "$tmp/log"
n=$(grep -c . "$tmp/log")
bad=$(grep -c '^DIFFER' "$tmp/log")
echo "$((n - bad)) of $n scenes pixel-identical (or failing alike), $bad differ ($size, $opts)"
[ "$bad" -eq 0 ]
