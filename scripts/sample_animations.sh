#!/usr/bin/env bash
# POV-Ray's sample animations (the .ini files under the sample scenes that set Final_Frame)
# rendered by povray and by lancer from the same INI file at 160x120: do both write the same
# file names, and how close is each frame (lowest and mean SSIM)? Prints a Markdown table.
#   scripts/sample_animations.sh [SCENES_DIR]
set -uo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
root=$(cd "$(dirname "$0")/.." && pwd)
scenes=${1:-/usr/share/povray-3.7/scenes}
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
lancer="$root/target/release/lancer"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| INI file | frames (povray / lancer) | same names | lowest SSIM | mean SSIM | povray s | lancer s |"
echo "|---|---|---|---|---|---|---|"
find -L "$scenes" -name '*.ini' | sort | while read -r ini; do
  grep -qi '^ *final_frame' "$ini" || continue
  rel=${ini#"$scenes"/}
  src=$(dirname "$ini")
  rm -rf "$work"/*; mkdir -p "$work/src" "$work/pov" "$work/lan"
  cp -rL "$src"/. "$work/src/"
  name=$(basename "$ini")
  t0=$(date +%s.%N)
  (cd "$work/pov" && timeout 600 povray "$work/src/$name" +W160 +H120 -D -V -GA +L"$work/src" >/dev/null 2>&1)
  t1=$(date +%s.%N)
  (cd "$work/lan" && timeout 600 "$lancer" "$work/src/$name" +W160 +H120 -q +L"$work/src" >/dev/null 2>&1)
  t2=$(date +%s.%N)
  np=$(ls "$work/pov" | wc -l); nl=$(ls "$work/lan" | wc -l)
  same=$([ "$(ls "$work/pov")" = "$(ls "$work/lan")" ] && echo yes || echo no)
  stats=$(for f in "$work"/pov/*.png; do
      [ -f "$work/lan/$(basename "$f")" ] || continue
      "$lancer" compare "$work/lan/$(basename "$f")" "$f" 2>/dev/null | awk '/^ssim/ {print $2}'
    done | awk 'NR == 1 || $1 < m { m = $1 } { s += $1; n++ } END { if (n) printf "%.3f | %.3f", m, s / n; else printf "- | -" }')
  printf "| %s | %s / %s | %s | %s | %.1f | %.1f |\n" "$rel" "$np" "$nl" "$same" "$stats" \
    "$(echo "$t1 - $t0" | bc)" "$(echo "$t2 - $t1" | bc)"
done
