#!/usr/bin/env bash
# Profile-guided (PGO) build of lancer: builds an instrumented binary, renders a training set of
# scenes with it at a small size, merges the counts with llvm-profdata and rebuilds with them.
# The optimised binary renders the same bytes as `cargo build --release` (PGO only moves code:
# inlining, block layout, branch weights; no floating-point change) and is faster; the numbers
# are in docs/performance.md, "Eleventh pass: profile-guided build (pgo11)".
#
# usage: scripts/build_pgo.sh        prints the path of the binary, target/pgo/lancer
#
# Needs: the Rust toolchain; llvm-profdata of the LLVM major version rustc was built with
# (`rustc -vV`, "LLVM version"): on Debian `apt-get install llvm-22` gives llvm-profdata-22 (set
# LLVM_PROFDATA to use another path); perf is not needed. The training set is this repository's
# scenes/ and POV-Ray's sample scenes (/usr/share/povray-3.7/scenes, Debian's povray package);
# without the samples it trains on scenes/ only and says so.
#
# Builds: the instrumented binary in target/pgo-instrumented (its own target dir), the optimised
# one with cargo's `pgo` profile (Cargo.toml) into target/pgo. target/release is not touched.
# Safe to run again: the raw profiles are made anew each time; cargo rebuilds what changed.
set -euo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf while training
cd "$(dirname "$0")/.."
root=$PWD

llvm_major=$(rustc -vV | sed -n 's/^LLVM version: \([0-9]*\).*/\1/p')
host=$(rustc -vV | sed -n 's/^host: //p')
profdata=
for c in "${LLVM_PROFDATA:-}" "llvm-profdata-$llvm_major" "/usr/lib/llvm-$llvm_major/bin/llvm-profdata" llvm-profdata; do
  [ -n "$c" ] && command -v "$c" >/dev/null 2>&1 || continue
  # The raw profile format changes between LLVM major versions: the tool must match rustc's.
  # (Old versions have no top-level --version and fail it: no version, not this one.)
  v=$({ "$c" --version 2>/dev/null || true; } | sed -n 's/.*LLVM version \([0-9]*\).*/\1/p' | head -1)
  if [ "$v" = "$llvm_major" ]; then
    profdata=$(command -v "$c")
    break
  fi
done
if [ -z "$profdata" ]; then
  echo "build_pgo.sh: needs llvm-profdata of LLVM $llvm_major (the LLVM of rustc, see rustc -vV)." >&2
  echo "  Debian/Ubuntu: apt-get install llvm-$llvm_major (gives llvm-profdata-$llvm_major)," >&2
  echo "  or set LLVM_PROFDATA=/path/to/llvm-profdata of that version." >&2
  exit 2
fi

work=$root/target/pgo-data
raw=$work/raw
merged=$work/lancer.profdata
rm -rf "$raw" "$merged"
mkdir -p "$raw"

# --config appends these flags to .cargo/config.toml's target rustflags (target-cpu), where
# RUSTFLAGS would replace them and so change the code the pictures come from.
flags() { # extra rustc flags as a TOML array
  echo "target.$host.rustflags=[$1]"
}

echo "== 1/4 instrumented build (target/pgo-instrumented)" >&2
cargo build --profile pgo --target-dir "$root/target/pgo-instrumented" \
  --config "$(flags "\"-Cprofile-generate=$raw\"")" >&2
instr=$root/target/pgo-instrumented/pgo/lancer

echo "== 2/4 training renders" >&2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
samples=/usr/share/povray-3.7/scenes
inc=/usr/share/povray-3.7/include
# scene (relative to the sample directory, or scenes/NAME for this repository's) and options.
# Spread over what lancer does: shapes (quartics, CSG, blobs, lathes, prisms, meshes, fractals,
# text, isosurfaces, height fields), patterns and noise, normals, finishes, media and fog,
# photons, radiosity, area lights, cameras, the parser (macros, loops), anti-aliasing on and
# off and two threads. Scenes not listed here are the held-out set of the measurements.
training=(
  "scenes/mirror_spheres.pov +A0.3"
  "scenes/glass.pov"
  "scenes/height_fields.pov"
  "scenes/icospheres.pov +A0.3"
  "scenes/isosurfaces.pov"
  "scenes/noise_patterns.pov"
  "scenes/phong.pov +WT2"
  "scenes/roughness.pov"
  "scenes/skybox.pov"
  "scenes/flyby.pov +A0.3"
  "advanced/chess2.pov"
  "advanced/woodbox.pov +A0.3"
  "advanced/mist.pov"
  "advanced/sunsethf.pov"
  "advanced/quilt1.pov"
  "advanced/crater/crater.pov"
  "advanced/teapot/teapot2.pov"
  "incdemo/woods/wood_3.pov"
  "incdemo/woods/wood_18.pov +A0.3"
  "incdemo/stones/rdgranit.pov"
  "incdemo/shapes.pov +WT2"
  "incdemo/metals/golds.pov"
  "objects/quartic/folium.pov"
  "objects/quartic/trough.pov"
  "objects/quartic/grafbic.pov +A0.3"
  "objects/superel2.pov"
  "objects/csg/cliptst2.pov"
  "objects/csg/granite.pov"
  "objects/blob.pov"
  "objects/lathe2.pov"
  "objects/prism3b.pov"
  "objects/sor1.pov"
  "objects/torus1.pov"
  "objects/bezier.pov"
  "objects/mesh2.pov"
  "objects/fractal3.pov"
  "objects/ttf1.pov"
  "portfolio/allpat1iso.pov"
  "interior/media/media2.pov"
  "interior/media/hollow3.pov"
  "interior/fog_ft.pov"
  "interior/foglayr.pov"
  "interior/crystal.pov +A0.3"
  "lights/arealit2.pov"
  "lights/phot_met_glass.pov"
  "lights/shadows.pov"
  "lights/spotlite.pov"
  "radiosity/rad_def_test_37.pov"
  "radiosity/radiosity2.pov"
  "textures/patterns/agate.pov"
  "textures/patterns/bozo.pov"
  "textures/patterns/crackle_form.pov"
  "textures/normals/normmap.pov"
  "textures/finishes/arches.pov"
  "camera/perspective.pov"
  "camera/focalblur.pov"
  "camera/fisheye.pov"
  "templates/Basic_Scenes/Sea_partly_cloudy_sky.pov"
  "language/macros/macro1.pov"
  "language/trace.pov"
)
if [ -d "$samples" ]; then
  # A scratch copy: some scenes write files that others read.
  cp -rL "$samples" "$tmp/samples" 2>/dev/null || true
  chmod -R u+w "$tmp/samples"
else
  echo "build_pgo.sh: no POV-Ray sample scenes at $samples: training on scenes/ only" >&2
fi
n=0
failed=0
start=$SECONDS
for entry in "${training[@]}"; do
  read -r scene opts <<<"$entry"
  case $scene in
    scenes/*) path=$root/$scene ;;
    *)
      [ -d "$tmp/samples" ] || continue
      path=$tmp/samples/$scene
      ;;
  esac
  dir=$(dirname "$path")
  n=$((n + 1))
  # shellcheck disable=SC2086 # opts are separate options
  if ! (cd "$dir" && LLVM_PROFILE_FILE="$raw/lancer-%p.profraw" timeout 300 "$instr" \
    +W240 +H180 -A +WT1 $opts "+L$dir" "+L$inc" "+I$path" "+O$tmp/out.png" -q >/dev/null 2>&1); then
    failed=$((failed + 1))
    echo "  (training render failed: $scene)" >&2
  fi
done
echo "   $n renders in $((SECONDS - start)) s, $failed failed" >&2
ls "$raw"/lancer-*.profraw >/dev/null 2>&1 || {
  echo "build_pgo.sh: the training wrote no profiles" >&2
  exit 1
}

echo "== 3/4 merge ($profdata)" >&2
# Only the renders: the build scripts and proc-macros of the instrumented build leave theirs too.
"$profdata" merge -o "$merged" "$raw"/lancer-*.profraw

echo "== 4/4 optimised build (target/pgo)" >&2
cargo build --profile pgo --config "$(flags "\"-Cprofile-use=$merged\"")" >&2
echo "$root/target/pgo/lancer"
