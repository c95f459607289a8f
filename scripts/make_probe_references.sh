#!/usr/bin/env bash
# Renders every shading probe in tests/probes/ (or tests/$1/, e.g. probes_approx) with Debian's povray into tests/probes/ref/.
# The probes are tiny scenes that each isolate one POV-Ray shading rule; tests/probes.rs
# compares lancer's renders with these pixel for pixel. A probe whose first line is
# `// options: ...` is rendered with those options too (quality levels, alpha).
set -euo pipefail
cd "$(dirname "$0")/../tests/${1:-probes}"
command -v povray >/dev/null || { echo "povray not found: apt-get install povray" >&2; exit 1; }
mkdir -p ref
for f in *.pov; do
  n=${f%.pov}
  opts=$(sed -n '1s|^// options: ||p' "$f")
  # shellcheck disable=SC2086
  povray -D -V +FN8 -A +W80 +H60 $opts +L. +L/usr/share/povray-3.7/include "+I$f" "+Oref/$n.png" 2>/dev/null
  echo "ref/$n.png"
done
