#!/usr/bin/env bash
# Regenerates the guide's pictures in docs/images/ by following each tutorial's commands
# (docs/guide/*.md). Needs a full build (`make demo` or `make test`: tide, tide-view for the
# install) and Debian's python3-matplotlib. Takes ~5 minutes on two idle cores.
#   docs/guide/scripts/make_pictures.sh [WORK_DIR]     (default: out/guide)
# IMAGES=DIR writes the pictures there instead of docs/images/: a check that every tutorial's
# commands still run, leaving the committed pictures alone.
set -euo pipefail
cd "$(dirname "$0")/../../.."
work=$(realpath -m "${1:-out/guide}")
python=/usr/bin/python3
tide=build/bin/tide
images=${IMAGES:-docs/images}
mkdir -p "$images"
scripts=docs/guide/scripts
mkdir -p "$work"

# A dam break in ParaView (dam-break-paraview.md): the frame at 0.5 s, from the side.
$tide run scenes/dam_break.json --out "$work/dam" --end-time 0.5 --format vtu,csv --force --quiet
$python $scripts/plot_frame.py "$work/dam/frame_00015.csv" $images/guide-dam-break-speed.png \
    --color speed --title "scenes/dam_break.json at t = 0.5 s, coloured by speed"

# A wave tank and its gauges (wave-tank.md).
$tide run scenes/wave_tank.json --out "$work/wave" --end-time 8 --force --quiet
$python $scripts/plot_gauges.py scenes/wave_tank.json "$work/wave/gauges.csv" \
    $images/guide-wave-gauges.png --from 4

# Several fluids (several-fluids.md).
$tide render scenes/many_materials.json --out "$work/layers" --width 480 --height 270 \
    --end-time 1.5 --mode particles --color-by material --force --quiet
cp "$work/layers/frame_00045.png" $images/guide-many-materials.png

# Rendering a video (render-video.md).
$tide render scenes/dam_break.json --out "$work/dam_render" --width 480 --height 270 \
    --end-time 0.5 --video "$work/dam_break.mp4" --force --quiet
cp "$work/dam_render/frame_00015.png" $images/guide-dam-break-render.png
$tide render scenes/dam_break.json --out "$work/dam_speed" --width 480 --height 270 \
    --end-time 0.3 --mode particles --color-by speed --force --quiet
cp "$work/dam_speed/frame_00009.png" $images/guide-dam-break-particles.png

# The C++ Fluid API (fluid-api.md): install, build the program outside the tree, run, plot.
cmake --install build --prefix "$work/tide-prefix" >/dev/null
cmake -S $scripts/fluid_api -B "$work/fluid_api" -DCMAKE_PREFIX_PATH="$work/tide-prefix" >/dev/null
cmake --build "$work/fluid_api" >/dev/null
"$work/fluid_api/oil_and_water" "$work/oil_and_water.csv" 2
$python $scripts/plot_frame.py "$work/oil_and_water.csv" $images/guide-fluid-api.png --color material \
    --slab -0.1 0.1 --title "oil_and_water after 2 s, a 0.2 m slice: water (0), light oil (1), heavy oil (2)"

echo "guide pictures written to $images/"
