#!/usr/bin/env bash
# Parse-speed benchmark, lancer against POV-Ray's parse phase (see scripts/parse_bench.py for
# the scenes and how each side is timed). Builds lancer in release mode first.
#   scripts/parse_bench.sh [--runs N] [--keep DIR]
set -euo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
root=$(cd "$(dirname "$0")/.." && pwd)
command -v povray >/dev/null || { echo "parse_bench: povray is not installed (apt-get install povray povray-includes)" >&2; exit 2; }
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
exec python3 "$root/scripts/parse_bench.py" "$root/target/release/lancer" "$@"
