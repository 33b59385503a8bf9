#!/usr/bin/env bash
# Regenerates the documentation's pictures in docs/images from the shipped samples and ../shared/data.
# Needs a build (make build), xvfb-run (Debian package xvfb) for the 3D views, and rsvg-convert
# (librsvg2-bin) for the 2D SVG. Usage: bash scripts/make_pictures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
data=../shared/data
out=docs/images
mkdir -p "$out"
view() { xvfb-run -a -s "-screen 0 1280x1024x24" "$build/apps/flowseg_view" "$@" --size 420x420 2>&1 | grep -v -i vtk || true; }

# The generated animal: its eight parts.
view samples/animal3d.pcd --surface --screenshot "$out/animal3d.png"
# The paper's Figure 6: the cactus without merging and at rho 1.1, 1.8, 2.0 (the paper's rule).
for rho in 0.9 1.1 1.8 2.0; do
  view "$data/meshes/cactus.off" --mesh-points 20000 --rho "$rho" --paper-rule --point-size 2 --screenshot "$out/cactus_rho$rho.png"
done
# The paper's Figure 8: the hand at two densities.
for n in 2301 25626; do
  view "$data/meshes/hand.off" --mesh-points "$n" --point-size 2 --screenshot "$out/hand_$n.png"
done
# A 2D silhouette (Kimia-216), as the SVG flowseg_segment writes.
tmp=$(mktemp -d)
"$build/apps/flowseg_segment" samples/hand2d.pcd -o "$tmp/hand2d" -q
rsvg-convert -w 420 "$tmp/hand2d.svg" -o "$out/hand2d_svg.png"
# A silhouette image: its boundary sample, segmented (Kimia-216, a camel).
"$build/apps/flowseg_sample" "$data/2d/kimia216/camel/camel-1.bmp" -o "$tmp/camel.pcd"
"$build/apps/flowseg_segment" "$tmp/camel.pcd" -o "$tmp/camel" -q
rsvg-convert -w 420 "$tmp/camel.svg" -o "$out/kimia_camel_svg.png"
rm -rf "$tmp"
ls -la "$out"
