#!/usr/bin/env bash
# Renders every sensation of every example file to out/examples/FILE/NAME.{csv,png} and its
# x-y view NAME.xy.png, with a firm hand sweeping a slow circle so that conditions have
# something to push against.
# Usage: scripts/render-examples.sh [FEEL_BINARY]
set -euo pipefail
cd "$(dirname "$0")/.."
feel=${1:-build/apps/feel/feel}
motion=${MOTION:-circle:6000:0.5}

for file in examples/*.feel.json; do
  base=$(basename "$file" .feel.json)
  mkdir -p "out/examples/$base"
  # Example files are in canonical form (a test checks it), so every sensation name sits
  # at four spaces of indent.
  names=$(grep -oE '^    "[A-Za-z0-9_.-]+": \{' "$file" | sed -E 's/^    "([^"]+)".*/\1/')
  for name in $names; do
    out="out/examples/$base/$name"
    if "$feel" render "$file" --sensation "$name" --hand firm --motion "$motion" \
         --duration 4 -o "$out.csv" --plot "$out.png" --plot-xy "$out.xy.png" > /dev/null 2> "$out.err"; then
      rm -f "$out.err"
      echo "rendered $out.png"
    else
      echo "skipped  $base/$name: $(tail -n 1 "$out.err")"
    fi
  done
done
