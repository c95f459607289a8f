#!/usr/bin/env bash
# The demo animation (scenes/flyby.ini: 48 frames, 320x240, +A0.3 without jitter) rendered by
# povray and by lancer in one run: whole-run wall times as a ratio, and each frame's SSIM
# against POV-Ray's (lancer compare). Needs povray.
#   scripts/flyby_bench.sh [WORK_DIR]
set -euo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mkdir -p "${1:-/tmp/flyby_bench}" && cd "${1:-/tmp/flyby_bench}" && pwd)
command -v povray >/dev/null || { echo "flyby_bench: povray is not installed" >&2; exit 2; }
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
lancer="$root/target/release/lancer"
rm -rf "$work/pov" "$work/lancer"; mkdir -p "$work/pov" "$work/lancer"
t0=$(date +%s.%N)
(cd "$work/pov" && povray "$root/scenes/flyby.ini" +L"$root/scenes" -D -V -GA >/dev/null 2>&1)
t1=$(date +%s.%N)
(cd "$work/lancer" && "$lancer" "$root/scenes/flyby.ini" +L"$root/scenes" -q)
t2=$(date +%s.%N)
pov=$(echo "$t1 - $t0" | bc); lan=$(echo "$t2 - $t1" | bc)
echo "| frame | SSIM |"
echo "|---|---|"
min=1
for f in "$work"/pov/flyby*.png; do
  n=$(basename "$f" .png); n=${n#flyby}
  s=$("$lancer" compare "$work/lancer/flyby$n.png" "$f" | awk '/^ssim/ {print $2}')
  echo "| $n | $s |"
  min=$(echo "if ($s < $min) $s else $min" | bc -l)
done
echo
echo "frames: $(ls "$work"/pov/flyby*.png | wc -l) from povray, $(ls "$work"/lancer/flyby*.png | wc -l) from lancer; lowest SSIM $min"
printf "whole run: povray %.2f s, lancer %.2f s, lancer/povray %.2f\n" "$pov" "$lan" "$(echo "$lan / $pov" | bc -l)"
