#!/usr/bin/env bash
# Renders the README's pictures: lit scenes on Mesa | on libglfixed | their
# difference (black where identical), made by the reference harness itself.
# Run after building (cmake --build build).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
scenes=(light_lecture light_eight_lights)
"$build/reference/run_scenes.sh" --side-by-side "${scenes[@]}"
for s in "${scenes[@]}"; do
  cp "$build/reference/out/$s/side_by_side.png" "docs/${s}_mesa_glfixed_diff.png"
done
