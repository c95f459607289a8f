#!/usr/bin/env bash
# Fills fuzz/corpus/parse (gitignored) with seeds made from POV-Ray's sample scenes and
# include files, read at run time: those files are AGPL / CC-BY and must not enter git.
#
# The fuzz harness skips any input containing "include" (it would read files, see
# fuzz/src/lib.rs), so the #include lines are deleted from the copies; the rest of each file
# still seeds the fuzzer with real scene syntax. Files are named by content hash so re-running
# the script adds nothing twice.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out="$here/corpus/parse"
scenes=${POV_SCENES:-/usr/share/povray-3.7/scenes}
includes=${POV_INCLUDES:-/usr/share/povray-3.7/include}
mkdir -p "$out" "$here/corpus/lex"
n=0
while IFS= read -r -d '' f; do
    tmp=$(mktemp)
    # `#include`, `# include` and stray "include" words (comments) all go.
    grep -av 'include' "$f" >"$tmp" || true
    sum=$(sha1sum "$tmp" | cut -c1-40)
    mv "$tmp" "$out/$sum"
    n=$((n + 1))
done < <(find -L "$scenes" "$includes" \( -name '*.pov' -o -name '*.inc' \) -print0)
# The lexer target takes the same text; it needs no filtering but the copies do no harm.
cp -n "$out"/* "$here/corpus/lex/"
echo "seeded $n files into $out ($(ls "$out" | wc -l) distinct)"
