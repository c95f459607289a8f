#!/usr/bin/env bash
# Where the speed table's time goes, as a geometric mean sees it: every scene of the speed table
# (sample scenes at SSIM >= 0.95 in docs/conformance.tsv, or the scenes given) is profiled on its
# own (`perf record`, 320x240, no AA, one thread, PPM), and each function's share of a scene is
# averaged over the scenes, each scene weighing the same. A function that is 20 % of one small
# scene counts as much as one that is 20 % of the largest: that is what lowers the geometric mean.
# A benchmark, not a test (a few minutes of CPU). Prints markdown: shares by category and the top
# functions; -o FILE also keeps the raw rows (scene, percent, function) for grep.
#
# usage: scripts/profile_table.sh [-n lancer] [-o rows.tsv] [-i rows.tsv] [-t top] [scene.pov ...]
#   -i: summarise rows kept by an earlier -o instead of profiling again
#   scene: a path under the sample directory, e.g. objects/superel1.pov
set -uo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
cd "$(dirname "$0")/.."
lancer=$PWD/target/release/lancer
rows_out=
rows_in=
top=60
while getopts "n:o:i:t:" opt; do
  case $opt in
    n) lancer=$OPTARG ;;
    o) rows_out=$OPTARG ;;
    i) rows_in=$OPTARG ;;
    t) top=$OPTARG ;;
    *) echo "usage: $0 [-n lancer] [-o rows.tsv] [-i rows.tsv] [-t top] [scene.pov ...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ -x "$lancer" ] || { echo "no lancer binary $lancer: cargo build --release" >&2; exit 2; }
command -v perf >/dev/null || { echo "perf not found" >&2; exit 2; }
inc=/usr/share/povray-3.7/include
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rows=$tmp/rows.tsv
: >"$rows"
if [ -n "$rows_in" ]; then
  cp "$rows_in" "$rows"
else
  # Some scenes write files that others read: work in a copy.
  cp -rL /usr/share/povray-3.7/scenes "$tmp/samples" 2>/dev/null
  chmod -R u+w "$tmp/samples"
  scenes=("$@")
  if [ ${#scenes[@]} -eq 0 ]; then
    mapfile -t scenes < <(awk -F'\t' '$2 == "ssim>=0.95" {print $1}' docs/conformance.tsv)
  fi
  for s in "${scenes[@]}"; do
    path=$tmp/samples/$s
    dir=$(dirname "$path")
    # A high sampling rate: the smallest scenes take 20 ms.
    (cd "$dir" && nice timeout 300 perf record -q -F 2999 -o "$tmp/perf.data" "$lancer" -D -V +FP -A +W320 +H240 +WT1 \
      "+L$dir" "+L$inc" "+I$path" "+O$tmp/l.ppm" >/dev/null 2>&1) || { echo "failed: $s" >&2; continue; }
    perf report -i "$tmp/perf.data" --no-children --sort sym --stdio -q 2>/dev/null |
      awk -v s="$s" '$1 ~ /%$/ {p = $1; sub(/%/, "", p); $1 = ""; $2 = ""; sub(/^ +/, ""); print s "\t" p "\t" $0}' >>"$rows"
  done
fi
[ -n "$rows_out" ] && cp "$rows" "$rows_out"
n=$(cut -f1 "$rows" | sort -u | wc -l)
echo "### Where the time goes: $n scenes profiled one by one, each function's mean share of a scene"
echo
echo "320x240 -A +WT1, $(basename "$lancer"); each scene weighs the same (as in the geometric mean)."
echo
echo "| category | mean % of a scene |"
echo "|---|---:|"
# Categories by symbol name; the order of the tests decides a name that fits several.
awk -F'\t' '{
  s = $3; c = "other"
  if (s ~ /noise|turb/) c = "noise"
  else if (s ~ /^lancer::render::(pattern|pigment|texture|normal|warp|crackle|fractal|irid)/) c = "patterns, pigments, normals"
  else if (s ~ /func::|vm::/) c = "user functions (VM)"
  else if (s ~ /radiosity/) c = "radiosity"
  else if (s ~ /media|fog|atmos/) c = "media and fog"
  else if (s ~ /shadow|light/) c = "lights and shadow rays"
  else if (s ~ /render::trace|render::shade|finish|Tracer/) c = "tracing and shading"
  else if (s ~ /^lancer::scene::(build::query|children)|bvh/) c = "acceleration walk (BVH, unions)"
  else if (s ~ /csg|^lancer::scene::object/) c = "object layer and CSG"
  else if (s ~ /poly|bernstein|sturm|quartic|algebraic|torus/) c = "polynomial solvers"
  else if (s ~ /^<lancer::geom::|^lancer::geom::/) c = "other shapes"
  else if (s ~ /^_*(ieee754_)?(pow|sin|cos|tan|atan|atan2|exp|log|fmod|cbrt|hypot)(_fma|f)?(@.*)?$/) c = "libm"
  else if (s ~ /malloc|free|memmove|memcpy|memset|realloc|_int_/) c = "allocation, memcpy"
  else if (s ~ /sdl::|parser|lexer|Parser|Lexer|nom::/) c = "parsing"
  else if (s ~ /^lancer::/) c = "lancer, other"
  else if (s ~ /^[a-z_0-9.]+$/) c = "kernel and libc (page faults, start-up)"
  cat[c] += $2
  if (!seen[$1]++) n++
} END { for (c in cat) printf "| %s | %.2f |\n", c, cat[c] / n }' "$rows" | sort -t'|' -k3 -rn
echo
echo "| function | mean % of a scene | scenes where it is >= 10 % |"
echo "|---|---:|---:|"
awk -F'\t' '{ p[$3] += $2; if ($2 >= 10) big[$3]++; if (!seen[$1]++) n++ }
  END { for (f in p) printf "| `%s` | %.2f | %d |\n", f, p[f] / n, big[f] }' "$rows" | sort -t'|' -k3 -rn | head -"$top"
