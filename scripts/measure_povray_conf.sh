#!/usr/bin/env bash
# Measures whether Debian's povray 3.7 enforces povray.conf's I/O restrictions on #fopen and
# #include (config.rs, tests/config_files.rs). A user povray.conf says `restricted` and permits
# only the current directory; the scene reads an include file and writes a file elsewhere.
# Run as root, and as nobody when root (measured 2026-11-23, povray 3.7.0.10: both write
# the file and read the include, that is, the restrictions are not enforced).
set -euo pipefail
d=$(mktemp -d /var/tmp/povconf.XXXXXX)
chmod 755 "$d"
mkdir -p "$d/home/.povray/3.7" "$d/run" "$d/elsewhere"
chmod 777 "$d/run" "$d/elsewhere"
printf '[File I/O Security]\nrestricted\n[Permitted Paths]\nread+write = .\n' \
  >"$d/home/.povray/3.7/povray.conf"
echo '#declare Q = 1;' >"$d/elsewhere/x.inc"
cat >"$d/run/s.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
#include "$d/elsewhere/x.inc"
#fopen F "$d/elsewhere/out.txt" write
#write (F, "x")
#fclose F
sphere { 0, 1 pigment { rgb 1 } }
POV
try() {
  rm -f "$d/elsewhere/out.txt"
  if "$@" >/dev/null 2>&1; then r=0; else r=$?; fi
  if [ -f "$d/elsewhere/out.txt" ]; then w="written"; else w="refused"; fi
  echo "exit $r, the file outside the permitted paths was $w"
}
cmd="cd $d/run && HOME=$d/home povray -D -V +W8 +H6 s.pov"
echo -n "as $(id -un): "; try sh -c "$cmd"
if [ "$(id -u)" = 0 ] && id nobody >/dev/null 2>&1; then
  echo -n "as nobody: "; try su nobody -s /bin/sh -c "$cmd"
fi
rm -rf "$d"
