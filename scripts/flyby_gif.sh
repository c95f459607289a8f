#!/usr/bin/env bash
# Renders the demo animation (scenes/flyby.ini, 48 frames) and joins the frames into an
# animated GIF, with whichever tool is here: ffmpeg, ImageMagick's convert, or Python's Pillow.
#   scripts/flyby_gif.sh [OUT_DIR]      (default: flyby/ under the current directory)
set -euo pipefail
export LANCER_NO_CONFIG=1 # lancer reads no povray.ini/povray.conf: results do not depend on the machine
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mkdir -p "${1:-flyby}" && cd "${1:-flyby}" && pwd)
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
(cd "$out" && "$root/target/release/lancer" "$root/scenes/flyby.ini" +L"$root/scenes" +C -q)
gif="$out/flyby.gif"
if command -v ffmpeg >/dev/null; then
  ffmpeg -loglevel error -y -framerate 24 -i "$out/flyby%02d.png" \
    -vf "split[a][b];[a]palettegen[p];[b][p]paletteuse" -loop 0 "$gif"
elif convert -version 2>/dev/null | grep -q ImageMagick; then
  convert -delay 4 -loop 0 "$out"/flyby[0-9][0-9].png "$gif"
elif python3 -c "import PIL" 2>/dev/null; then
  python3 - "$out" "$gif" <<'PY'
import glob, sys
from PIL import Image
frames = [Image.open(p).convert("RGB") for p in sorted(glob.glob(sys.argv[1] + "/flyby[0-9][0-9].png"))]
frames[0].save(sys.argv[2], save_all=True, append_images=frames[1:], duration=42, loop=0)
PY
else
  echo "flyby_gif: the frames are in $out; install ffmpeg, ImageMagick or Pillow to join them" >&2
  exit 1
fi
echo "wrote $gif"
