#!/usr/bin/env bash
# Parse phase side by side: lancer's "parse" seconds (its statistics line) and POV-Ray's
# "Parse Time" for sample scenes, each at 32x24 without AA on one thread (the render is
# negligible; only the parse phase is compared), best of $RUNS (default 3) for both.
# usage: scripts/parse_table.sh [-b lancer-binary] scene.pov ...   (paths relative to the sample
#        scenes directory, or absolute). Prints a markdown table.
set -uo pipefail
export LANCER_NO_CONFIG=1
bin=$(cd "$(dirname "$0")/.." && pwd)/target/release/lancer
while getopts "b:" opt; do
  case $opt in
    b) bin=$OPTARG ;;
    *) echo "usage: $0 [-b lancer-binary] scene.pov ..." >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
samples=/usr/share/povray-3.7/scenes
runs=${RUNS:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| scene | lancer parse s | POV-Ray parse s | ratio |"
echo "|---|---:|---:|---:|"
for s in "$@"; do
  case $s in /*) path=$s ;; *) path=$samples/$s ;; esac
  dir=$(dirname "$path")
  best_l=; best_p=
  for _ in $(seq "$runs"); do
    l=$(cd "$dir" && "$bin" -D -V +FN8 -A +W32 +H24 +WT1 +L"$dir" +L/usr/share/povray-3.7/include \
      +I"$path" +O"$tmp/l.ppm" 2>&1 | sed -n 's/.*parse \([0-9.]*\)s.*/\1/p' | tail -1)
    p=$(cd "$dir" && povray -D -V +FN8 -A +W32 +H24 +WT1 +L"$dir" +L/usr/share/povray-3.7/include \
      +I"$path" +O"$tmp/p.ppm" 2>&1 | sed -n 's/.*Parse Time: .*(\([0-9.]*\) seconds).*/\1/p' | head -1)
    [ -n "$l" ] && { [ -z "$best_l" ] || awk "BEGIN{exit !($l < $best_l)}"; } && best_l=$l
    [ -n "$p" ] && { [ -z "$best_p" ] || awk "BEGIN{exit !($p < $best_p)}"; } && best_p=$p
  done
  ratio=$(awk -v l="${best_l:-0}" -v p="${best_p:-0}" 'BEGIN{ if (p > 0) printf "%.2f", l / p; else print "-" }')
  echo "| ${s#"$samples"/} | ${best_l:--} | ${best_p:--} | $ratio |"
done
