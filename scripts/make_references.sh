#!/usr/bin/env bash
# Regenerate the POV-Ray reference renders in reference/ from scenes/*.pov.
#
# For every scene S.pov it writes
#   reference/S.png     320x240, no anti-aliasing  (-A)
#   reference/S_aa.png  320x240, anti-aliasing     (+A0.3)
#   reference/S_aaj.png 320x240, anti-aliasing without jitter (+A0.3 -J)
#   reference/S_am2.png 320x240, anti-aliasing method 2 without jitter (+A0.3 +AM2 -J)
# and nothing else.  reference/manifest.tsv is maintained by hand; this
# script only checks that every scene has its rows there.
#
# POV-Ray warnings are collected and printed at the end.
#
# Usage: scripts/make_references.sh [scene.pov ...]   (default: all scenes)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SCENES="$ROOT/scenes"
REF="$ROOT/reference"
INC=/usr/share/povray-3.7/include
POVRAY="${POVRAY:-povray}"

if ! command -v "$POVRAY" >/dev/null 2>&1; then
  echo "error: '$POVRAY' not found. Install POV-Ray 3.7 (Debian: apt-get install povray)." >&2
  exit 1
fi
if [ ! -d "$INC" ]; then
  echo "error: $INC missing (Debian's povray-includes package)." >&2
  exit 1
fi
if [ ! -f "$SCENES/sky.png" ]; then
  echo "error: scenes/sky.png missing; run: python3 scripts/make_skybox.py" >&2
  exit 1
fi
mkdir -p "$REF"

if [ "$#" -gt 0 ]; then
  scenes=("$@")
else
  scenes=("$SCENES"/*.pov)
fi

LOG="$(mktemp -d)"
trap 'rm -rf "$LOG"' EXIT
warnings=0

render() {  # render <scene.pov> <aa-flags> <out.png>
  local pov="$1" aa="$2" out="$3" log
  log="$LOG/$(basename "$out").log"
  local t0 t1
  t0="$(date +%s.%N)"
  # Debian's povray reads /etc/povray/3.7/povray.ini first (800x600,
  # display on, ...): every setting that matters is passed explicitly.
  if ! "$POVRAY" -D -V +FN8 $aa +W320 +H240 \
        +L"$SCENES" +L"$INC" +I"$pov" +O"$out" >"$log" 2>&1; then
    echo "error: povray failed on $pov ($aa):" >&2
    grep -v '^\s*$' "$log" | tail -20 >&2
    exit 1
  fi
  t1="$(date +%s.%N)"
  local t
  t="$(sed -n 's/^ *Trace Time: .*(\([0-9.]*\) seconds).*/\1/p' "$log" | tail -1)"
  local p
  p="$(sed -n 's/^ *Parse Time: .*(\([0-9.]*\) seconds).*/\1/p' "$log" | tail -1)"
  printf '  %-24s wall %5.2fs  parse %6ss  trace %6ss\n' "$(basename "$out")" \
    "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" "${p:-?}" "${t:-?}"
  # Warnings look like "Parse Warning: ..." (possibly after "File '...' line n:").
  if grep -i 'warning:' "$log" >/dev/null; then
    warnings=$((warnings + 1))
    { echo "--- $(basename "$out")"
      # the warning line and its indented continuation lines
      awk 'tolower($0) ~ /warning:/ { on = 1; print; next }
           on && /^ / { print; next } { on = 0 }' "$log"; } >>"$LOG/warnings"
  fi
}

echo "POV-Ray: $("$POVRAY" --version 2>&1 | grep -m1 '^POV-Ray')"
for pov in "${scenes[@]}"; do
  pov="$(cd "$(dirname "$pov")" && pwd)/$(basename "$pov")"
  name="$(basename "$pov" .pov)"
  echo "$name.pov"
  render "$pov" -A     "$REF/$name.png"
  render "$pov" +A0.3  "$REF/${name}_aa.png"
  render "$pov" "+A0.3 -J" "$REF/${name}_aaj.png"
  render "$pov" "+A0.3 +AM2 -J" "$REF/${name}_am2.png"
done

if [ "$warnings" -gt 0 ]; then
  echo
  echo "POV-Ray printed warnings:"
  cat "$LOG/warnings"
else
  echo "no POV-Ray warnings"
fi

# The manifest is hand-maintained: only check that every scene has rows.
MANIFEST="$REF/manifest.tsv"
if [ ! -f "$MANIFEST" ]; then
  echo "warning: $MANIFEST missing (it is maintained by hand)" >&2
  exit 1
fi
missing=0
for pov in "$SCENES"/*.pov; do
  name="$(basename "$pov" .pov)"
  for ref in "$name.png" "${name}_aa.png" "${name}_aaj.png" "${name}_am2.png"; do
    if ! awk -F'\t' -v s="$name.pov" -v r="$ref" \
         'NR > 1 && $1 == s && $3 == r { found = 1 } END { exit !found }' "$MANIFEST"; then
      echo "warning: manifest.tsv has no row for $name.pov -> $ref" >&2
      missing=1
    fi
  done
done
exit "$missing"
