#!/usr/bin/env bash
# Makes docs/images/viewer.png, the README's picture of `hooke view`: lloyd-tet springs on cylinder_hole at
# nu = 0.45 dragged by 3 mm at the top, coloured by their distance to the linear FEM under the same probe, the FEM
# ghost as a wireframe. Needs a Release build with the viewer and xvfb-run (scripts/setup.sh).
# Usage: scripts/make_viewer_screenshot.sh [HOOKE=build/release/apps/hooke/hooke]
set -euo pipefail
cd "$(dirname "$0")/.."
hooke=${1:-build/release/apps/hooke/hooke}
script=$(mktemp)
trap 'rm -f "$script"' EXIT
cat > "$script" <<'SCRIPT'
0     grab-nearest 0.0 -0.01 0.02
0.01  drag 0.003 -0.001 0 over 0.4
3.0   ghost linear
3.0   colormap error
3.0   screenshot docs/images/viewer.png
3.0   quit
SCRIPT
xvfb-run -a -s "-screen 0 1024x768x24" "$hooke" view data/meshes/cylinder_hole.msh --young 14630 --poisson 0.45 \
  --method lloyd-tet --integrator local-global --damping-mass 40 --script "$script" --window-size 1024,640
echo "wrote docs/images/viewer.png"
