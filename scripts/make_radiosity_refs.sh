#!/usr/bin/env bash
# POV-Ray's renders of the radiosity probes (tests/radiosity/*.pov) at 80x60, one thread (its
# radiosity is deterministic only on one), every option explicit.
set -euo pipefail
cd "$(dirname "$0")/../tests/radiosity"
for f in *.pov; do
  povray -D -V +FN8 -A +W80 +H60 +WT1 +L. +L/usr/share/povray-3.7/include \
    +I"$f" +Oref/"${f%.pov}".png
done
