#!/usr/bin/env bash
# docs/distributed.md's local recipe: the demo animation split into subsets of frames run as
# separate lancer processes by GNU parallel (four jobs), then checked byte for byte against
# one whole run. Needs GNU parallel (Debian package `parallel`).
#   scripts/flyby_parallel.sh [WORK_DIR] [JOBS]
set -euo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mkdir -p "${1:-/tmp/flyby_parallel}" && cd "${1:-/tmp/flyby_parallel}" && pwd)
jobs=${2:-4}
command -v parallel >/dev/null || { echo "flyby_parallel: install GNU parallel (apt-get install parallel)" >&2; exit 2; }
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
lancer="$root/target/release/lancer"
rm -rf "$work/split" "$work/whole"; mkdir -p "$work/split" "$work/whole"
# Eight subsets of six frames; each job is what one machine or one array task would run.
seq 1 6 48 | parallel -j "$jobs" --halt now,fail=1 \
  "cd '$work/split' && '$lancer' '$root/scenes/flyby.ini' +L'$root/scenes' +SF{} +EF\$(({} + 5)) +WT1 -q"
(cd "$work/whole" && "$lancer" "$root/scenes/flyby.ini" +L"$root/scenes" -q)
same=0
for f in "$work"/whole/flyby*.png; do
  cmp -s "$f" "$work/split/$(basename "$f")" && same=$((same + 1))
done
total=$(ls "$work"/whole/flyby*.png | wc -l)
echo "$same of $total frames byte-identical between the split and the whole run"
[ "$same" -eq "$total" ]
