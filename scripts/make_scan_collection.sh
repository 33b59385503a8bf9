#!/usr/bin/env bash
# Scans every mesh below ROOT once by the single-view protocol (flowseg_sample --single-view-protocol:
# a 240 x 240-pixel, 50-degree range camera two bounding-box diagonals from the centre in a random
# direction, constant depth noise along each ray), so that a development collection is made the same
# way as the held-out ones.
#   bash scripts/make_scan_collection.sh ROOT OUT [--noise F] [--seed S] [--build DIR] [-- OPTIONS...]
# ROOT/<class>/<id>.off (.obj, .ply) becomes OUT/<class>/<id>.pcd, its PCD VIEWPOINT the sensor.
# --noise: depth noise, a share of the diagonal (default 0; 0.005 for the noisy scans). --seed: the
# base seed S (default 1). --build: the build folder holding apps/flowseg_sample (default: build in
# this checkout).
# OPTIONS go to every flowseg_sample run (e.g. --binary).
# The seed of a mesh is (S + C) mod 2^32, C the POSIX cksum CRC of its path relative to ROOT as
# bytes, without a newline (`printf %s airplane/71.off | cksum`): the same for a file wherever ROOT
# lies, and the same for two noise levels, whose scans then share their viewpoints and rays.
# Writes OUT/scans.tsv (path, seed, points, viewpoint) and prints the point counts' min, median and max.
set -euo pipefail

usage() { sed -n '2,15p' "$0" >&2; exit 2; }
[ $# -ge 2 ] || usage
root=${1%/}
out=${2%/}
shift 2
noise=0 seed=1 build=
while [ $# -gt 0 ]; do
  case $1 in
    --noise) [ $# -ge 2 ] || usage; noise=$2; shift 2 ;;
    --seed) [ $# -ge 2 ] || usage; seed=$2; shift 2 ;;
    --build) [ $# -ge 2 ] || usage; build=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "make_scan_collection.sh: unknown option '$1'" >&2; usage ;;
  esac
done
options=("$@")
[[ $seed =~ ^[0-9]+$ ]] && [ "$seed" -le 4294967295 ] || { echo "make_scan_collection.sh: --seed needs a whole number from 0 to 4294967295, got '$seed'" >&2; exit 2; }
[ -d "$root" ] || { echo "make_scan_collection.sh: $root: not a folder" >&2; exit 1; }
sample=${build:-$(cd "$(dirname "$0")/.." && pwd)/build}/apps/flowseg_sample
[ -x "$sample" ] || { echo "make_scan_collection.sh: $sample: not built (make build, or give --build DIR)" >&2; exit 1; }

mapfile -t meshes < <(cd "$root" && find . -type f \( -name '*.off' -o -name '*.obj' -o -name '*.ply' \) | sed 's|^\./||' | LC_ALL=C sort)
[ ${#meshes[@]} -gt 0 ] || { echo "make_scan_collection.sh: no mesh (.off, .obj, .ply) below $root" >&2; exit 1; }
mkdir -p "$out"
manifest="$out/scans.tsv"
printf 'path\tseed\tpoints\tviewpoint\n' > "$manifest"
counts=()
for rel in "${meshes[@]}"; do
  crc=$(printf '%s' "$rel" | cksum | cut -d' ' -f1)
  file_seed=$(( (seed + crc) % 4294967296 ))
  pcd="$out/${rel%.*}.pcd"
  mkdir -p "$(dirname "$pcd")"
  status=0
  log=$("$sample" "$root/$rel" -o "$pcd" --single-view-protocol --noise "$noise" --seed "$file_seed" "${options[@]}" 2>&1) || status=$?
  if [ $status -ne 0 ]; then
    echo "make_scan_collection.sh: $rel: $log" >&2
    exit $status
  fi
  n=$(grep -a -m1 '^POINTS' "$pcd" | awk '{print $2}')
  viewpoint=$(grep -a -m1 '^VIEWPOINT' "$pcd" | awk '{print $2","$3","$4}')
  printf '%s\t%s\t%s\t%s\n' "${rel%.*}.pcd" "$file_seed" "$n" "$viewpoint" >> "$manifest"
  counts+=("$n")
done
printf '%s\n' "${counts[@]}" | sort -n | awk -v out="$out" -v noise="$noise" -v seed="$seed" '
  { v[NR] = $1 }
  END {
    median = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    printf "wrote %d scans to %s (noise %s, base seed %s): points min %d, median %g, max %d\n", NR, out, noise, seed, v[1], median, v[NR]
  }'
