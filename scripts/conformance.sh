#!/usr/bin/env bash
# Regenerates docs/conformance.md and .tsv over POV-Ray 3.7's sample scenes, and the subset CI
# reruns (tests/conformance/subset.txt). Needs `povray` and `povray-examples`; POV-Ray's
# renders are cached (~/.cache/lancer/conformance), so only changed scenes cost a POV-Ray run.
# Extra arguments go to `lancer conformance` (e.g. --jobs 4, --scenes DIR).
set -euo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
cd "$(dirname "$0")/.."
cargo build --release --quiet
target/release/lancer conformance --report docs/conformance --known docs/known-differences.tsv \
  --write-subset tests/conformance/subset.txt "$@"
