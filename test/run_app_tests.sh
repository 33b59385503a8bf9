#!/usr/bin/env bash
# Runs the command-line apps on shipped samples and on bad input; checks exit codes, messages
# and outputs. Usage: run_app_tests.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
src=$2
seg="$build/apps/flowseg_segment"
gen="$build/apps/flowseg_make_samples"
work=$(mktemp -d /tmp/flowseg_apps_XXXXXX)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

check() { # name, condition result (0 = ok)
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $1"; fi
}

# expect NAME EXIT_CODE MESSAGE_PATTERN -- command...
expect() {
  local name=$1 code=$2 pattern=$3
  shift 4
  "$@" >"$work/out.txt" 2>"$work/err.txt"
  local rc=$?
  if [ "$rc" -ne "$code" ]; then
    echo "FAILED: $name: exit $rc, expected $code"; sed 's/^/    /' "$work/err.txt" | head -5; failed=$((failed + 1)); return
  fi
  if [ -n "$pattern" ] && ! grep -qiE -e "$pattern" "$work/out.txt" "$work/err.txt"; then
    echo "FAILED: $name: output does not match '$pattern'"; sed 's/^/    /' "$work/err.txt" | head -5; failed=$((failed + 1)); return
  fi
  passed=$((passed + 1))
}

# --- good input: every shipped sample ------------------------------------------------------
for sample in "$src"/samples/*.pcd; do
  name=$(basename "$sample" .pcd)
  expect "segment $name" 0 "segments after merging" -- "$seg" "$sample" --output "$work/$name"
  n=$(grep -m1 '^POINTS' "$sample" | awk '{print $2}')
  m=$(grep -m1 '^POINTS' "$work/$name.labels.pcd" 2>/dev/null | awk '{print $2}')
  [ "$n" = "$m" ]; check "$name: label PCD has one point per input point ($n vs $m)" $?
  grep -q '^FIELDS x y z label' "$work/$name.labels.pcd"; check "$name: label PCD fields" $?
  head -1 "$work/$name.ply" | grep -q '^ply$'; check "$name: PLY header" $?
  grep -q '^element face [1-9]' "$work/$name.surface.ply"; check "$name: surface PLY has faces" $?
  if command -v python3 >/dev/null 2>&1; then
    python3 - "$work/$name.json" "$n" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["points"] == int(sys.argv[2]), "points"
assert d["segment_count"] == len(d["segments"]) > 0, "segments"
assert sum(s["point_count"] for s in d["segments"]) + d["unlabelled_points"] == d["points"], "point counts"
assert d["interior"]["computed"] and d["interior"]["closed"], "closed interior"
assert all(d["segments"][k]["interior"] for k in d["features"]["segments"]), "features are interior"
assert "interior" in d["timings_ms"], "interior timing"
assert any(s["significant"] for s in d["segments"]), "significant features marked"
assert all(k in d["timings_ms"] for k in ("delaunay", "flow", "merge", "total")), "timings"
PY
    check "$name: JSON well-formed and consistent" $?
  fi
  ls "$work" | grep -q '\.tmp\.'; [ $? -ne 0 ]; check "$name: no temporary files left" $?
done

# --- options ----------------------------------------------------------------------------
expect "help lists defaults" 0 "default" -- "$seg" --help
expect "2D forced on a 2D sample" 0 "2D:" -- "$seg" "$src/samples/hand2d.pcd" -d 2 --rho 0.5 --binary -o "$work/h"
expect "3D forced on a 2D sample" 1 "coplanar" -- "$seg" "$src/samples/hand2d.pcd" -d 3 -o "$work/h3"
[ ! -e "$work/h3.json" ] && [ ! -e "$work/h3.labels.pcd" ]; check "no output after a failure" $?
expect "rho negative" 2 "rho" -- "$seg" "$src/samples/hand2d.pcd" --rho -1
expect "rho not a number" 2 "rho" -- "$seg" "$src/samples/hand2d.pcd" --rho abc
expect "rho missing value" 2 "rho" -- "$seg" "$src/samples/hand2d.pcd" --rho
expect "dimension absurd" 2 "dimension" -- "$seg" "$src/samples/hand2d.pcd" --dimension 5
expect "unknown option" 2 "unknown option" -- "$seg" "$src/samples/hand2d.pcd" --frobnicate
expect "features absurd" 2 "features" -- "$seg" "$src/samples/hand2d.pcd" --features sideways
expect "significance absurd" 2 "significance" -- "$seg" "$src/samples/hand2d.pcd" --significance 1.5
expect "denoise absurd" 2 "denoise" -- "$seg" "$src/samples/hand2d.pcd" --denoise maybe
expect "viewpoint malformed" 2 "viewpoint" -- "$seg" "$src/samples/hand2d.pcd" --viewpoint 1,2
expect "viewpoint not finite" 2 "viewpoint" -- "$seg" "$src/samples/hand2d.pcd" --viewpoint 1,nan,3
expect "no-interior with features" 2 "excludes" -- "$seg" "$src/samples/hand2d.pcd" --no-interior --features both
expect "normals missing" 1 "no normals" -- "$seg" "$src/samples/hand2d.pcd" --use-normals -o "$work/nn"
expect "exterior features" 0 "features reported" -- "$seg" "$src/samples/star2d.pcd" --features exterior -o "$work/ext"
expect "raw segmentation" 0 "segments after merging" -- "$seg" "$src/samples/star2d.pcd" --no-interior -o "$work/raw"
[ ! -e "$work/raw.surface.ply" ]; check "raw segmentation writes no surface" $?
awk 'BEGIN{srand(1)} /^DATA/{d=1;next} d{n=sqrt($1*$1+$2*$2+$3*$3)+1e-12; print $1,$2,$3,$1,$2,$3}' "$src/samples/snowman3d.pcd" > "$work/normals.xyz"
expect "normals from a text file" 0 "interior:" -- "$seg" "$work/normals.xyz" --use-normals -o "$work/nrm"
expect "viewpoint" 0 "interior:" -- "$seg" "$src/samples/dumbbell3d.pcd" --viewpoint 0,8,0 -o "$work/vp"
expect "no input" 2 "no input" -- "$seg"

# --- bad input -----------------------------------------------------------------------------
expect "missing file" 1 "cannot open" -- "$seg" "$work/nope.pcd"
printf 'this is not a pcd file\n\001\002' > "$work/corrupt.pcd"
expect "corrupt PCD" 1 "not a PCD" -- "$seg" "$work/corrupt.pcd" -o "$work/c"
printf 'garbage' > "$work/corrupt.ply"
expect "corrupt PLY" 1 "PLY" -- "$seg" "$work/corrupt.ply" -o "$work/c"
printf '1 2 3\nx y z\n' > "$work/bad.xyz"
expect "bad XYZ line" 1 "bad.xyz:2" -- "$seg" "$work/bad.xyz" -o "$work/c"
printf '# empty\n' > "$work/empty.xyz"
expect "empty file" 1 "no points" -- "$seg" "$work/empty.xyz" -o "$work/c"
printf '0 0 0\n1 0 0\n' > "$work/two.xyz"
expect "fewer than d+1 points" 1 "at least 3" -- "$seg" "$work/two.xyz" -o "$work/c"
printf '0 0 0\n1 1 1\n2 2 2\n3 3 3\n' > "$work/line.xyz"
expect "collinear points" 1 "collinear" -- "$seg" "$work/line.xyz" -o "$work/c"
printf 'nan 0 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0.5\n0 0 0\n' > "$work/nan.xyz"
expect "NaN and duplicate are reported" 0 "1 non-finite, 1 duplicates" -- "$seg" "$work/nan.xyz" -o "$work/nan"
printf 'solid x\n' > "$work/mesh.stl"
expect "unknown extension" 1 "unknown file type" -- "$seg" "$work/mesh.stl"
[ ! -e "$work/c.json" ]; check "no output for any bad input" $?
expect "unwritable output" 1 "cannot write" -- "$seg" "$src/samples/star2d.pcd" -o "$work/no/such/dir/x"

# --- sample generator ----------------------------------------------------------------------
expect "generator" 0 "wrote" -- "$gen" --output "$work" --points2d 300 --points3d 400
[ "$(grep -m1 '^POINTS' "$work/animal3d.pcd" | awk '{print $2}')" = "400" ]; check "generator point count" $?
expect "generator bad option" 2 "points2d needs a whole number" -- "$gen" --points2d -5

# --- mesh sampler ----------------------------------------------------------------------------
smp="$build/apps/flowseg_sample"
printf 'OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > "$work/tet.off"
expect "sample a mesh" 0 "wrote" -- "$smp" "$work/tet.off" -n 500 --noise 0.001 -o "$work/tet.pcd"
[ "$(grep -m1 '^POINTS' "$work/tet.pcd" | awk '{print $2}')" = "500" ]; check "sampler point count" $?
expect "segment the sampled mesh" 0 "closed" -- "$seg" "$work/tet.pcd" -o "$work/tet"
expect "sampler missing mesh" 1 "cannot open" -- "$smp" "$work/none.off" -o "$work/x.pcd"
expect "sampler bad count" 2 "points" -- "$smp" "$work/tet.off" -n 0 -o "$work/x.pcd"
expect "sampler bad noise" 2 "noise" -- "$smp" "$work/tet.off" --noise -1 -o "$work/x.pcd"
expect "sampler no output" 2 "output" -- "$smp" "$work/tet.off"
expect "sampler output not PCD" 1 "written as PCD" -- "$smp" "$work/tet.off" -o "$work/tet.xyz"
[ ! -e "$work/tet.xyz" ]; check "no file under a non-PCD name" $?
printf 'P2\n5 5\n255\n255 255 255 255 255\n255 0 0 0 255\n255 0 0 0 255\n255 0 0 0 255\n255 255 255 255 255\n' > "$work/square.pgm"
expect "sample a silhouette image" 0 "silhouette boundary" -- "$smp" "$work/square.pgm" -o "$work/square.pcd"
[ "$(grep -m1 '^POINTS' "$work/square.pcd" | awk '{print $2}')" = "12" ]; check "a 3x3 square has 12 boundary edge midpoints" $?
printf 'P5\n5 5\n255\nxy' > "$work/short.pgm"
expect "sample a truncated image" 1 "truncated" -- "$smp" "$work/short.pgm" -o "$work/x.pcd"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n' > "$work/broken.off"
expect "sampler corrupt mesh" 1 "vertex" -- "$smp" "$work/broken.off" -o "$work/x.pcd"
expect "scan a mesh" 0 "a scan of" -- "$smp" "$work/tet.off" -n 300 --scan-from 5,5,5 --noise 0.001 -o "$work/scan.pcd"
[ "$(grep -m1 '^VIEWPOINT' "$work/scan.pcd")" = "VIEWPOINT 5 5 5 1 0 0 0" ]; check "the scan's viewpoint is the PCD VIEWPOINT" $?
[ "$(grep -m1 '^POINTS' "$work/scan.pcd" | awk '{print $2}')" = "300" ]; check "scan point count" $?
expect "segment a scan from its sensor origin" 0 "noise: estimated sigma" -- "$seg" "$work/scan.pcd" --use-sensor-origin -o "$work/scan"
expect "scan from inside the mesh" 1 "outside the mesh's bounding sphere" -- "$smp" "$work/tet.off" --scan-from 0.2,0.2,0.2 -o "$work/x.pcd"
expect "scan viewpoint malformed" 2 "scan-from" -- "$smp" "$work/tet.off" --scan-from 1,2 -o "$work/x.pcd"
expect "scan by the single-view protocol" 0 "a scan of .* 240 x 240 pixels, field of view 50 degrees, .* along each ray" -- "$smp" "$work/tet.off" --single-view-protocol --noise 0.005 --seed 3 -o "$work/proto.pcd"
awk '/^VIEWPOINT/ { d = sqrt (($2 - 0.5) ^ 2 + ($3 - 0.5) ^ 2 + ($4 - 0.5) ^ 2); ok = $5 == 1 && d > 3.4640 && d < 3.4642 } END { exit !ok }' "$work/proto.pcd"
check "the protocol's viewpoint, 2 diagonals from the box centre, is the PCD VIEWPOINT" $?
n=$(grep -m1 '^POINTS' "$work/proto.pcd" | awk '{print $2}')
[ "$n" -gt 100 ] && [ "$n" -le 57600 ]; check "a 240 x 240 scan has at most 57600 points ($n)" $?
expect "the protocol spelt out" 0 "a scan of" -- "$smp" "$work/tet.off" --scan-random --scan-distance 2 --scan-pixels 240 --scan-fov 50 --depth-noise-model constant --noise 0.005 --seed 3 -o "$work/proto2.pcd"
cmp -s "$work/proto.pcd" "$work/proto2.pcd"; check "--single-view-protocol is its options spelt out" $?
expect "the protocol without noise" 0 "a scan of" -- "$smp" "$work/tet.off" --single-view-protocol --seed 3 -o "$work/proto0.pcd"
[ "$(grep -m1 '^POINTS' "$work/proto0.pcd")" = "POINTS $n" ] && [ "$(grep -m1 '^VIEWPOINT' "$work/proto0.pcd")" = "$(grep -m1 '^VIEWPOINT' "$work/proto.pcd")" ]
check "the same seed without noise: the same viewpoint and rays" $?
expect "the protocol, another seed" 0 "a scan of" -- "$smp" "$work/tet.off" --single-view-protocol --seed 4 -o "$work/proto4.pcd"
[ "$(grep -m1 '^VIEWPOINT' "$work/proto4.pcd")" != "$(grep -m1 '^VIEWPOINT' "$work/proto.pcd")" ]; check "another seed, another direction" $?
expect "a camera scan from a given viewpoint" 0 "64 x 64 pixels, field of view 20 degrees" -- "$smp" "$work/tet.off" --scan-from 5,5,5 --scan-pixels 64 --scan-fov 20 -o "$work/cam.pcd"
[ "$(grep -m1 '^VIEWPOINT' "$work/cam.pcd")" = "VIEWPOINT 5 5 5 1 0 0 0" ]; check "the camera scan's viewpoint is the PCD VIEWPOINT" $?
[ "$(grep -m1 '^POINTS' "$work/cam.pcd" | awk '{print $2}')" -le 4096 ]; check "a 64 x 64 scan has at most 4096 points" $?
expect "scan field of view 180" 2 "scan-fov" -- "$smp" "$work/tet.off" --single-view-protocol --scan-fov 180 -o "$work/x.pcd"
expect "scan field of view negative" 2 "scan-fov" -- "$smp" "$work/tet.off" --single-view-protocol --scan-fov -5 -o "$work/x.pcd"
expect "scan pixels absurd" 2 "scan-pixels" -- "$smp" "$work/tet.off" --single-view-protocol --scan-pixels 100000 -o "$work/x.pcd"
expect "scan distance inside" 2 "scan-distance" -- "$smp" "$work/tet.off" --scan-random --scan-distance 0.4 -o "$work/x.pcd"
expect "depth noise model absurd" 2 "depth-noise-model" -- "$smp" "$work/tet.off" --scan-random --depth-noise-model square -o "$work/x.pcd"
expect "scan from a point and at random" 2 "exclude each other" -- "$smp" "$work/tet.off" --scan-from 5,5,5 --single-view-protocol -o "$work/x.pcd"
expect "scan options without a scan" 2 "need a scan" -- "$smp" "$work/tet.off" --scan-pixels 240 -o "$work/x.pcd"
mkdir -p "$work/meshes/a" "$work/meshes/b"
cp "$work/tet.off" "$work/meshes/a/1.off"
cp "$work/tet.off" "$work/meshes/b/2.off"
collect="$src/scripts/make_scan_collection.sh"
expect "scan collection" 0 "wrote 2 scans .*: points min [0-9]+, median [0-9.]+, max [0-9]+" -- bash "$collect" "$work/meshes" "$work/collection" --build "$build"
expect "scan collection with noise" 0 "wrote 2 scans" -- bash "$collect" "$work/meshes" "$work/collection_noisy" --noise 0.005 --build "$build"
[ -f "$work/collection/a/1.pcd" ] && [ -f "$work/collection/b/2.pcd" ] && [ "$(wc -l < "$work/collection/scans.tsv")" = 3 ]; check "one scan per mesh, in its class folder, and the list of scans" $?
one_seed=$(( (1 + $(printf '%s' a/1.off | cksum | cut -d' ' -f1)) % 4294967296 ))
"$smp" "$work/meshes/a/1.off" --single-view-protocol --seed "$one_seed" -o "$work/one.pcd" 2>/dev/null
cmp -s "$work/one.pcd" "$work/collection/a/1.pcd"; check "a collection scan's seed is the base seed plus the cksum of its relative path" $?
[ "$(grep -m1 '^VIEWPOINT' "$work/collection/a/1.pcd")" = "$(grep -m1 '^VIEWPOINT' "$work/collection_noisy/a/1.pcd")" ] &&
  [ "$(grep -m1 '^VIEWPOINT' "$work/collection/a/1.pcd")" != "$(grep -m1 '^VIEWPOINT' "$work/collection/b/2.pcd")" ]
check "the noisy collection shares the clean one's viewpoints; two files, two viewpoints" $?
expect "scan collection bad seed" 2 "seed" -- bash "$collect" "$work/meshes" "$work/x" --seed -1 --build "$build"
expect "scan collection bad noise" 2 "noise" -- bash "$collect" "$work/meshes" "$work/x" --noise 2 --build "$build"
expect "scan collection without meshes" 1 "no mesh" -- bash "$collect" "$work/collection" "$work/x" --build "$build"
expect "sample with outliers" 0 "replaced by outliers" -- "$smp" "$work/tet.off" -n 2000 --outliers 0.02 -o "$work/out.pcd"
expect "outliers found and left out" 0 "left out as outliers" -- "$seg" "$work/out.pcd" -o "$work/out"
grep -q '"outlier_points": [1-9]' "$work/out.json"; check "the JSON counts the outliers" $?
grep -q '"detached_share": 0\.0*[1-9]' "$work/out.json"; check "the JSON reports the detached share" $?
expect "outliers kept on request" 0 " 0 outliers)" -- "$seg" "$work/out.pcd" --outliers off -o "$work/out"
expect "smoothing forced" 0 ", 2 smoothing pass\(es\)" -- "$seg" "$work/out.pcd" --smooth on --smooth-passes 2 -o "$work/smooth"
grep -q '^  "smoothing_passes": 2,' "$work/smooth.json"; check "the JSON records the smoothing passes made" $?
grep -q '"smoothing": "on", "smoothing_passes": 2' "$work/smooth.json"; check "the JSON records the smoothing asked for" $?
expect "noisy sample" 0 "noise sigma" -- "$smp" "$work/tet.off" -n 3000 --noise 0.005 -o "$work/noisy.pcd"
expect "noisy sample smoothed automatically" 0 "roughness 0\.[1-9][0-9]*, .*, [1-6] smoothing pass\(es\)" -- "$seg" "$work/noisy.pcd" -o "$work/noisy"
expect "smoothing off" 0 ", 0 smoothing pass\(es\)" -- "$seg" "$work/noisy.pcd" --smooth off -o "$work/noisy"
expect "smoothing passes absurd" 2 "smooth-passes" -- "$seg" "$src/samples/hand2d.pcd" --smooth-passes 99
expect "smoothing passes zero" 2 "smooth-passes" -- "$seg" "$src/samples/hand2d.pcd" --smooth-passes 0
expect "smoothing mode absurd" 2 "smooth" -- "$seg" "$src/samples/hand2d.pcd" --smooth 2
expect "outlier mode absurd" 2 "outliers" -- "$seg" "$src/samples/hand2d.pcd" --outliers sometimes
expect "sampler bad outliers" 2 "outliers" -- "$smp" "$work/tet.off" --outliers 2 -o "$work/x.pcd"
expect "smallest part share absurd" 2 "min-part-share" -- "$seg" "$src/samples/hand2d.pcd" --min-part-share 1

# --- signature database and retrieval evaluation ----------------------------------------------
db="$build/apps/flowseg_db"
ev="$build/apps/flowseg_eval"
for seed in 1 2 3; do
  "$gen" --output "$work/gen$seed" --points3d 1500 --points2d 300 --seed $seed >/dev/null 2>&1
  for shape in snowman3d dumbbell3d animal3d; do
    mkdir -p "$work/tree/$shape"; cp "$work/gen$seed/$shape.pcd" "$work/tree/$shape/$shape-$seed.pcd"
  done
done
expect "segment with the paper's rule" 0 "segments after merging" -- "$seg" "$src/samples/star2d.pcd" -o "$work/paper" --paper-rule --rho 1.3
expect "segment with the paper's rule, spelt out" 0 "segments after merging" -- "$seg" "$src/samples/star2d.pcd" -o "$work/paper2" --tolerance 0 --stump-ratio 0 --compact-size 0 --rho 1.3
cmp -s "$work/paper.labels.pcd" "$work/paper2.labels.pcd"; check "--paper-rule is tolerance, stump ratio and compact size 0 (same labels)" $?
expect "segment bad compact size" 2 "compact-size" -- "$seg" "$src/samples/star2d.pcd" --compact-size -1
expect "segment bad compact rho" 2 "compact-rho" -- "$seg" "$src/samples/star2d.pcd" --compact-rho 0
expect "segment bad tolerance" 2 "tolerance" -- "$seg" "$src/samples/star2d.pcd" --tolerance -1
expect "segment bad stump ratio" 2 "stump-ratio" -- "$seg" "$src/samples/star2d.pcd" --stump-ratio 0.5
expect "segment threads" 0 "segments after merging" -- "$seg" "$src/samples/star2d.pcd" -o "$work/threads" -j 1
expect "segment threads attached" 0 "segments after merging" -- "$seg" "$src/samples/star2d.pcd" -o "$work/threads1" -j1
expect "segment threads with =" 0 "segments after merging" -- "$seg" "$src/samples/star2d.pcd" -o "$work/threads2" --threads=1
expect "segment all threads" 0 "segments after merging" -- "$seg" "$src/samples/star2d.pcd" -o "$work/threads0" --threads 0
for t in threads1 threads2 threads0; do
  cmp -s "$work/threads.labels.pcd" "$work/$t.labels.pcd"; check "labels do not depend on how threads are given ($t)" $?
done
expect "segment threads absurd" 2 "threads needs a whole number" -- "$seg" "$src/samples/star2d.pcd" -j -1
expect "segment option with a value it does not take" 2 "takes no value" -- "$seg" "$src/samples/star2d.pcd" --binary=yes
for app in flowseg_segment flowseg_db flowseg_eval flowseg_signature flowseg_match; do
  "$build/apps/$app" --help | grep -q -- "-j, --threads N        worker threads: 0 = all cores, 1 = sequential; the result is the same for"
  check "$app documents -j, --threads the same way" $?
done
expect "db build" 0 "9 shapes" -- "$db" build "$work/shapes.db" "$work/tree" -j 2
expect "db build, --jobs as before" 0 "9 shapes" -- "$db" build "$work/shapes2.db" "$work/tree" --jobs 2
cmp -s "$work/shapes.db" "$work/shapes2.db"; check "the same database whatever the thread option's name" $?
expect "db build sequential" 0 "9 shapes" -- "$db" build "$work/shapes3.db" "$work/tree" -j1
cmp -s "$work/shapes.db" "$work/shapes3.db"; check "the same database with -j1 (sequential) as with -j 2" $?
expect "db mesh points refused by the library's rule" 2 "mesh-points: .*4" -- "$db" build "$work/shapes4.db" "$work/tree" --mesh-points 2
expect "db list" 0 "snowman3d" -- "$db" list "$work/shapes.db"
expect "db query finds the class" 0 "^1.*snowman3d" -- "$db" query "$work/shapes.db" "$work/tree/snowman3d/snowman3d-1.pcd" -k 3
expect "db add" 0 "10 shapes" -- "$db" add "$work/shapes.db" "$src/samples/hand2d.pcd" --label hand
expect "db query with few candidates lists the rest unaligned" 0 "^3	-	-" -- "$db" query "$work/shapes.db" "$work/tree/snowman3d/snowman3d-1.pcd" -k 3 --candidates 2
expect "db bad candidates" 2 "candidates" -- "$db" query "$work/shapes.db" x.pcd --candidates -1
expect "db query reports its time" 0 "compared in full): " -- "$db" query "$work/shapes.db" "$work/tree/animal3d/animal3d-2.pcd"
printf 'not a database\n' > "$work/foreign.db"
expect "db foreign file" 1 "not a pcl_flowseg signature database" -- "$db" query "$work/foreign.db" "$work/tree/animal3d/animal3d-2.pcd"
expect "db missing file" 1 "cannot open" -- "$db" list "$work/none.db"
# shards of the collection, split in file order and merged in that order, give the same database
(cd "$work/tree" && "$db" add "$work/shard_a.db" animal3d/*.pcd dumbbell3d/*.pcd -q && "$db" add "$work/shard_b.db" snowman3d/*.pcd -q)
check "db add shards (names relative to the tree, as build makes them)" $?
expect "db merge shards" 0 "9 shapes" -- "$db" merge "$work/merged.db" "$work/shard_a.db" "$work/shard_b.db"
cmp -s "$work/merged.db" "$work/shapes3.db"; check "merged shards hold the same database as db build" $?
expect "db merge again replaces, adds nothing" 0 "9 shapes" -- "$db" merge "$work/merged.db" "$work/shard_b.db"
expect "db merge needs a shard" 2 "merge needs DB and at least one SHARD" -- "$db" merge "$work/merged.db"
expect "db merge a missing shard" 1 "cannot open" -- "$db" merge "$work/merged.db" "$work/none.db"
cmp -s "$work/merged.db" "$work/shapes3.db"; check "a failed merge leaves the database as it was" $?
expect "db bad command" 2 "unknown command" -- "$db" frobnicate "$work/shapes.db"
expect "db bad k" 2 "-k" -- "$db" query "$work/shapes.db" x.pcd -k -3

# --- concurrent writers: every added shape is there afterwards ----------------------------------
"$db" build "$work/conc.db" "$work/tree/snowman3d" -q
adders=0
for f in "$work"/tree/*/*.pcd "$src"/samples/*.pcd; do
  "$db" add "$work/conc.db" "$f" -j 1 -q 2>>"$work/conc.err" &
  adders=$((adders + 1))
done
wait
present=$("$db" list "$work/conc.db" | wc -l)
[ "$present" -eq $((3 + adders)) ]; check "$adders concurrent adds to one database: $((3 + adders)) shapes expected, $present present" $?
[ ! -s "$work/conc.err" ]; check "concurrent adds report no error" $?

# --- damaged databases: every verb refuses them with the line, none changes them ----------------
printf 'pcl_flowseg signature database 7\nshapes 2\nshape a 3 1 1 0.02 1 0 0 0 one\np 0 0 0 1\n' > "$work/truncated.db"
printf 'pcl_flowseg signature database 7\nshapes 1\nshape a 3 1 1 0.02 1 0 0 0 one\np 0 0 1 8888888888888888888888888888888888880.6\n' > "$work/absurd.db"
printf 'pcl_flowseg signature database 7\nshapes 1\nshape a 3 1 1 0.02 3 0 0 0 one\np 0 0 0 1\nshape b 3 1 1 0.02 1 0 0 0 two\n' > "$work/counts.db"
printf 'pcl_flowseg signature database 7\n\x00\x01\xff\xfe garbage \x80\n' > "$work/garbage.db"
for bad in truncated absurd counts garbage; do
  cp "$work/$bad.db" "$work/$bad.before"
  expect "db list $bad database" 1 "$bad.db" -- "$db" list "$work/$bad.db"
  expect "db query $bad database" 1 "$bad.db" -- "$db" query "$work/$bad.db" "$src/samples/snowman3d.pcd"
  expect "db add to $bad database" 1 "$bad.db" -- "$db" add "$work/$bad.db" "$src/samples/snowman3d.pcd"
  expect "db merge into $bad database" 1 "$bad.db" -- "$db" merge "$work/$bad.db" "$work/shard_b.db"
  expect "db merge $bad database as a shard" 1 "$bad.db" -- "$db" merge "$work/merged.db" "$work/$bad.db"
  cmp -s "$work/$bad.db" "$work/$bad.before"; check "db add leaves the $bad database as it was" $?
  expect "match against $bad database as a shape" 1 "$bad.db" -- "$build/apps/flowseg_match" "$src/samples/snowman3d.pcd" "$work/$bad.db"
done
expect "db absurd number refused at its line" 1 "absurd.db:4: the weight" -- "$db" query "$work/absurd.db" "$src/samples/snowman3d.pcd"
expect "db build replaces a damaged database" 0 "3 shapes" -- "$db" build "$work/garbage.db" "$work/tree/animal3d"
expect "db the rebuilt database reads" 0 "animal3d" -- "$db" list "$work/garbage.db"
expect "eval" 0 "flowseg.*NN" -- "$ev" "$work/tree" -o "$work/eval" -j 2
if command -v python3 >/dev/null 2>&1; then
  python3 - "$work/eval" <<'PY'
import csv, json, sys
d = json.load(open(sys.argv[1] + "/scores.json"))
for m in ("flowseg", "paper", "parts", "thickness", "inner", "solid", "inner-profile", "thickness-profile", "d2", "esf"):
    s = d["methods"][m]
    assert 0 <= s["first_tier"] <= 1 and s["queries"] == 9, m
    rows = list(csv.reader(open(sys.argv[1] + "/similarity_%s.csv" % m)))
    assert len(rows) == 10 and rows[0][1:] == [r[0] for r in rows[1:]], m
    assert open(sys.argv[1] + "/similarity_%s.png" % m, "rb").read(8) == b"\x89PNG\r\n\x1a\n", m
assert d["methods"]["flowseg"]["nearest_neighbour"] == 1.0, d["methods"]["flowseg"]
PY
  check "eval outputs well-formed; flowseg finds every nearest neighbour" $?
fi
expect "eval missing root" 1 "cannot open" -- "$ev" "$work/none" -o "$work/eval2"
expect "eval no output" 2 "output" -- "$ev" "$work/tree"
expect "eval absurd option" 2 "rho" -- "$ev" "$work/tree" -o "$work/eval3" --rho -2
mkdir -p "$work/badtree/x"; cp "$work/corrupt.pcd" "$work/badtree/x/"
expect "eval corrupt file" 1 "not a PCD" -- "$ev" "$work/badtree" -o "$work/eval4"

# --- signature, match, 2D SVG, viewer -----------------------------------------------------------
sig="$build/apps/flowseg_signature"
mat="$build/apps/flowseg_match"
expect "signature" 0 "significant features" -- "$sig" "$src/samples/snowman3d.pcd"
expect "signature json" 0 '"points": \[' -- "$sig" "$src/samples/animal3d.pcd" --json
expect "signature lists the described parts" 0 "3 described parts" -- "$sig" "$src/samples/snowman3d.pcd"
if command -v python3 >/dev/null 2>&1; then
  "$sig" "$src/samples/animal3d.pcd" --json | python3 -c '
import json, sys
d = json.load(sys.stdin)
assert len(d["parts"]) >= 6 and abs(sum(p["weight"] for p in d["parts"]) - 1) < 1e-9, d["parts"]
assert sorted(d["distributions"]) == ["inner_distance", "solid_distance", "thickness"]
assert all(len(v) == 32 and abs(sum(v) - 1) < 1e-9 for v in d["distributions"].values())
assert len(d["inner_profiles"]) == 16 and all(abs(sum(r) - 1) < 1e-9 for r in d["inner_profiles"])
assert len(d["thickness_profile"]) == 16 and d["thickness_profile"][0] > d["thickness_profile"][-1]'
  check "signature json holds the description" $?
fi
expect "signature bad option" 2 "unknown option" -- "$sig" "$src/samples/animal3d.pcd" --frob
expect "match alignment points refused by the library's rule" 2 "alignment-points: " -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --alignment-points 0
expect "signature missing file" 1 "cannot open" -- "$sig" "$work/none.pcd"
expect "signature corrupt file" 1 "not a PCD" -- "$sig" "$work/corrupt.pcd"
expect "match itself" 0 "similarity 1.0000" -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/animal3d.pcd"
expect "match two" 0 "similarity" -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --no-mirror
expect "match reports every component" 0 "components parts .* thickness .* inner .* solid " -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd"
expect "match paper method aligns" 0 "mirrored" -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --method paper
expect "match unknown method" 2 "method" -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --method d2
expect "match 2D against 3D refused" 1 "2D with a 3D" -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/star2d.pcd"
expect "db query by one component" 0 "method inner" -- "$db" query "$work/shapes.db" "$work/tree/animal3d/animal3d-2.pcd" --method inner
expect "match one input" 2 "two inputs" -- "$mat" "$src/samples/animal3d.pcd"
expect "match corrupt file" 1 "not a PCD" -- "$mat" "$src/samples/animal3d.pcd" "$work/corrupt.pcd"
expect "match missing file" 1 "cannot open" -- "$mat" "$work/none.pcd" "$src/samples/animal3d.pcd"
expect "match bad threshold" 2 "threshold" -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --threshold -1
expect "match old spelling warns" 0 "--no-mirror is deprecated: use --no-allow-mirror" -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --method paper --no-mirror
expect "match weights by name" 0 "similarity" -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --weights-3d parts=1,thickness=0
expect "match bad weight" 2 "weights-3d" -- "$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --weights-3d girth=1
"$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --weights-3d parts=1,thickness=0,thickness_profile=0,inner_context=0 >"$work/w1.txt" 2>&1
"$mat" "$src/samples/animal3d.pcd" "$src/samples/snowman3d.pcd" --method parts >"$work/w2.txt" 2>&1
[ "$(grep -o 'distance [0-9.]*' "$work/w1.txt" | head -1)" = "$(grep -o 'distance [0-9.]*' "$work/w2.txt" | head -1)" ]
check "match: only the parts weighted is the parts method" $?
expect "segment old option spelling warns" 0 "--tolerance is deprecated: use --sampling-tolerance" -- "$seg" "$src/samples/star2d.pcd" -o "$work/old" --tolerance 0.5
expect "2D writes SVG" 0 "svg" -- "$seg" "$src/samples/star2d.pcd" -o "$work/star"
head -c 4 "$work/star.svg" | grep -q '<svg'; check "SVG starts with <svg" $?
grep -q '</svg>' "$work/star.svg"; check "SVG is complete" $?
if [ -x "$build/apps/flowseg_view" ]; then
  view="$build/apps/flowseg_view"
  expect "view help" 0 "screenshot" -- "$view" --help
  expect "view missing file" 1 "cannot open" -- "$view" "$work/none.pcd" --screenshot "$work/x.png"
  expect "view bad screenshot name" 2 "png" -- "$view" "$src/samples/animal3d.pcd" --screenshot "$work/x.jpg"
  expect "view corrupt file" 1 "not a PCD" -- "$view" "$work/corrupt.pcd" --screenshot "$work/x.png"
  expect "view absurd size" 2 "size" -- "$view" "$src/samples/animal3d.pcd" --size 5x5 --screenshot "$work/x.png"
  if command -v xvfb-run >/dev/null 2>&1; then
    expect "view screenshot" 0 "wrote" -- xvfb-run -a -s "-screen 0 1024x768x24" "$view" "$src/samples/animal3d.pcd" --surface --size 300x300 --screenshot "$work/animal.png"
    [ "$(head -c 8 "$work/animal.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; check "screenshot is a PNG" $?
  else
    echo "SKIPPED: view screenshot (xvfb-run is not installed)"
  fi
fi

# --- single-view scans: every app that segments takes the viewpoint --------------------------
# Two balls side by side (radii 1 and 0.6, 32 x 16 quads each), scanned by flowseg_sample: from
# the viewpoint the balls are two parts, the hidden side guessed; without it one closed shell.
awk 'BEGIN {
  A = 32; D = 16; pi = atan2(0, -1); nv = (D + 1) * A; nf = D * A * 2;
  print "OFF"; print 2 * nv, 2 * nf, 0;
  for (b = 0; b < 2; b++) {
    r = b ? 0.6 : 1; cx = b ? 1.5 : 0;
    for (i = 0; i <= D; i++) for (j = 0; j < A; j++) {
      t = pi * i / D; f = 2 * pi * j / A;
      printf "%.6f %.6f %.6f\n", cx + r * sin(t) * cos(f), r * sin(t) * sin(f), r * cos(t);
    }
  }
  for (b = 0; b < 2; b++) for (i = 0; i < D; i++) for (j = 0; j < A; j++) {
    o = b * nv; a = o + i * A + j; c = o + (i + 1) * A + j; d = o + (i + 1) * A + (j + 1) % A; e = o + i * A + (j + 1) % A;
    print 3, a, c, d; print 3, a, d, e;
  }
}' > "$work/balls.off"
vp=0.5,0,12
expect "scan a mesh" 0 "a scan of 2048 faces" -- "$smp" "$work/balls.off" --scan-from $vp -n 3000 -o "$work/scan.pcd"
grep -q '^VIEWPOINT 0.5 0 12 1 0 0 0$' "$work/scan.pcd"; check "the scan's PCD carries the viewpoint" $?
mkdir -p "$work/scans/front" "$work/scans/above"
for from in 0.5,0,12 -0.5,1,12; do "$smp" "$work/balls.off" --scan-from $from -n 3000 -o "$work/scans/front/$from.pcd" -q; done
for from in 0,12,1 1,12,0; do "$smp" "$work/balls.off" --scan-from $from -n 3000 -o "$work/scans/above/$from.pcd" -q; done
awk '/^DATA/ { d = 1; next } d' "$work/scan.pcd" > "$work/scan.xyz"
mkdir -p "$work/xyz_scans/front" && cp "$work/scan.xyz" "$work/xyz_scans/front/"
sig_plain=$("$sig" "$work/scan.pcd" --json)
for how in "--use-sensor-origin" "--viewpoint $vp"; do
  # shellcheck disable=SC2086 # $how is two words for --viewpoint
  expect "segment a scan ($how)" 0 "[1-9][0-9]* vertices guessed on the hidden side" -- "$seg" "$work/scan.pcd" $how -o "$work/scan_seg"
  grep -q '"viewpoint": \[0.5, 0, 12\]' "$work/scan_seg.json" && grep -q '"hidden_side_vertices": [1-9]' "$work/scan_seg.json"
  check "segment a scan ($how): the JSON has the viewpoint and the hidden side" $?
  expect "signature of a scan ($how)" 0 "2 significant features" -- "$sig" "$work/scan.pcd" $how
  [ "$("$sig" "$work/scan.pcd" --json $how)" != "$sig_plain" ]; check "signature of a scan ($how) differs from the one without viewpoint" $?
  expect "match a scan ($how)" 0 "A: 2 parts, B: 2" -- "$mat" "$work/scan.pcd" "$work/scans/front/0.5,0,12.pcd" $how
  expect "db build from scans ($how)" 0 "4 shapes" -- "$db" build "$work/scans.db" "$work/scans" $how
  expect "db query a scan ($how)" 0 "^1	(1.0000|0.99[0-9]*)	0.00[0-9]*	front	front/0.5,0,12.pcd" -- "$db" query "$work/scans.db" "$work/scan.pcd" $how
  expect "db add a scan ($how)" 0 "5 shapes" -- "$db" add "$work/scans.db" "$work/scan.pcd" --label scan $how
  expect "eval scans ($how)" 0 "flowseg.*NN" -- "$ev" "$work/scans" -o "$work/scans_eval" --methods flowseg,parts $how
done
"$db" build "$work/scans_plain.db" "$work/scans" -q
"$db" build "$work/scans_own.db" "$work/scans" -q --use-sensor-origin
[ "$("$db" list "$work/scans_own.db" | grep -c '	2 features	2 parts')" -eq 4 ]; check "db: each scan from its own viewpoint has two parts" $?
! cmp -s "$work/scans_plain.db" "$work/scans_own.db"; check "db: scans segmented from their own viewpoints give other signatures" $?
"$ev" "$work/scans" -o "$work/scans_eval_plain" --methods parts -q >/dev/null
"$ev" "$work/scans" -o "$work/scans_eval_own" --methods parts -q --use-sensor-origin >/dev/null
! cmp -s "$work/scans_eval_plain/similarity_parts.csv" "$work/scans_eval_own/similarity_parts.csv"
check "eval: scans segmented from their own viewpoints compare otherwise" $?
if [ -x "$build/apps/flowseg_view" ] && command -v xvfb-run >/dev/null 2>&1; then
  for how in "--use-sensor-origin" "--viewpoint $vp"; do
    expect "view a scan ($how)" 0 "3000 points, 2 features" -- xvfb-run -a -s "-screen 0 1024x768x24" "$build/apps/flowseg_view" "$work/scan.pcd" $how --size 200x200 --screenshot "$work/scan.png"
  done
else
  echo "SKIPPED: view a scan (flowseg_view or xvfb-run is missing)"
fi
scan_apps=(flowseg_segment flowseg_signature flowseg_match flowseg_db flowseg_eval)
[ -x "$build/apps/flowseg_view" ] && scan_apps+=(flowseg_view)
for app in "${scan_apps[@]}"; do
  case $app in
    flowseg_match) args=("$work/scan.pcd" "$work/scan.pcd") no_origin=("$work/scan.pcd" "$work/scan.xyz") ;;
    flowseg_db) args=(query "$work/scans_own.db" "$work/scan.pcd") no_origin=(query "$work/scans_own.db" "$work/scan.xyz") ;;
    flowseg_eval) args=("$work/scans" -o "$work/scans_eval2") no_origin=("$work/xyz_scans" -o "$work/scans_eval3" --methods parts) ;;
    flowseg_view) args=("$work/scan.pcd" --screenshot "$work/x.png") no_origin=("$work/balls.off" --screenshot "$work/x.png") ;;
    flowseg_segment) args=("$work/scan.pcd" -o "$work/x") no_origin=("$work/scan.xyz" -o "$work/x") ;;
    *) args=("$work/scan.pcd") no_origin=("$work/scan.xyz") ;;
  esac
  expect "$app: --viewpoint with --use-sensor-origin refused" 2 "--viewpoint and --use-sensor-origin exclude each other" -- "$build/apps/$app" "${args[@]}" --viewpoint $vp --use-sensor-origin
  expect "$app: --no-interior with --use-sensor-origin refused" 2 "--no-separate-interior excludes" -- "$build/apps/$app" "${args[@]}" --no-interior --use-sensor-origin
  expect "$app: --use-sensor-origin on a file without one" 1 "carries no sensor origin" -- "$build/apps/$app" "${no_origin[@]}" --use-sensor-origin
  "$build/apps/$app" --help | grep -q -- "--viewpoint X,Y,Z  sensor position of a single-view scan"; check "$app documents --viewpoint" $?
done

# --- single-view recognition: scans of a tiny collection against its meshes -----------------------
box_off() { # a box of sides X Y Z
  printf 'OFF\n8 12 0\n'
  for k in 0 1 2 3 4 5 6 7; do
    echo "$(( k & 1 )) $(( (k >> 1) & 1 )) $(( (k >> 2) & 1 ))"
  done | awk -v x="$1" -v y="$2" -v z="$3" '{ print $1 * x, $2 * y, $3 * z }'
  printf '3 0 2 1\n3 1 2 3\n3 4 5 6\n3 5 7 6\n3 0 1 4\n3 1 5 4\n3 2 6 3\n3 3 6 7\n3 0 4 2\n3 2 4 6\n3 1 3 5\n3 3 7 5\n'
}
ellipsoid_off() { # semi-axes A B C: 12 rings of 24 vertices
  awk -v a="$1" -v b="$2" -v c="$3" 'BEGIN {
    R = 12; S = 24; pi = atan2(0, -1); last = 1 + (R - 1) * S
    printf "OFF\n%d %d 0\n0 0 %g\n", last + 1, 2 * S * (R - 1), c
    for (i = 1; i < R; i++) for (j = 0; j < S; j++)
      printf "%.6f %.6f %.6f\n", a * sin(pi * i / R) * cos(2 * pi * j / S), b * sin(pi * i / R) * sin(2 * pi * j / S), c * cos(pi * i / R)
    printf "0 0 %g\n", -c
    for (j = 0; j < S; j++) printf "3 0 %d %d\n", 1 + j, 1 + (j + 1) % S
    for (i = 0; i < R - 2; i++) for (j = 0; j < S; j++) {
      u = 1 + i * S + j; v = 1 + i * S + (j + 1) % S
      printf "3 %d %d %d\n3 %d %d %d\n", u, u + S, v, v, u + S, v + S
    }
    for (j = 0; j < S; j++) printf "3 %d %d %d\n", last, 1 + (R - 2) * S + (j + 1) % S, 1 + (R - 2) * S + j
  }'
}
sv="$work/single_view"
mkdir -p "$sv/models/box" "$sv/models/ellipsoid"
box_off 1 1 1 > "$sv/models/box/cube.off"
box_off 4 1 0.5 > "$sv/models/box/bar.off"
ellipsoid_off 1 1 1 > "$sv/models/ellipsoid/round.off"
ellipsoid_off 3 1 0.6 > "$sv/models/ellipsoid/long.off"
for m in box/cube box/bar ellipsoid/round ellipsoid/long; do
  mkdir -p "$sv/scans/$(dirname $m)"
  "$smp" "$sv/models/$m.off" --single-view-protocol --seed 3 -o "$sv/scans/$m.pcd" -q
done
expect "single-view recognition" 0 "single-view recognition: 4 queries .* 4 models" -- "$ev" "$sv/models" --queries "$sv/scans" -o "$sv/out" --use-sensor-origin --mesh-points 3000 -j 2
grep -qE "^esf-views +[0-9.]+ +[0-9.]+ +1\.000 " "$work/out.txt"
check "single-view recognition: each scan's nearest rendered view (esf-views) is of its own mesh" $?
python3 - "$sv/out/single_view.tsv" <<'PY'
import sys
rows = [line.rstrip("\n").split("\t") for line in open(sys.argv[1])]
assert rows[0] == ["method", "class", "queries", "category_nn", "first_tier", "instance_top1", "ms_per_query", "ms_per_model"], rows[0]
body = rows[1:]
assert sorted({r[0] for r in body}) == ["esf", "esf-views", "flowseg"], body
for r in body:
    assert r[1] in ("box", "ellipsoid", "all"), r
    assert int(r[2]) == (4 if r[1] == "all" else 2), r
    assert all(0.0 <= float(v) <= 1.0 for v in r[3:6]), r
    assert float(r[6]) > 0 and float(r[7]) > 0, r
assert [r[5] for r in body if r[0] == "esf-views" and r[1] == "all"] == ["1.0000"], body
PY
check "single-view recognition: single_view.tsv has its columns, a row per method and class, scores in [0, 1]" $?
mkdir -p "$sv/point_models/box"
cp "$sv/scans/box/cube.pcd" "$sv/scans/box/bar.pcd" "$sv/point_models/box/"
expect "single-view recognition: esf-views skipped on point samples" 0 "esf-views +skipped: .*point sample" -- "$ev" "$sv/point_models" --queries "$sv/point_models" -o "$sv/out2" --methods esf,esf-views -q
mkdir -p "$sv/scans/box2" && cp "$sv/scans/box/cube.pcd" "$sv/scans/box2/"
expect "single-view recognition: a scan without a model" 1 "box2/cube.pcd has no model" -- "$ev" "$sv/models" --queries "$sv/scans" -o "$sv/out3" --methods esf
expect "single-view recognition: --views of no view sphere" 2 "--views: .*12, 42" -- "$ev" "$sv/models" --queries "$sv/scans" -o "$sv/out3" --views 40
expect "--views without --queries" 2 "--views is for single-view recognition" -- "$ev" "$sv/models" -o "$sv/out3" --views 12
expect "single-view recognition: d2 is no method of it" 2 "--methods: 'd2' is none of" -- "$ev" "$sv/models" --queries "$sv/scans" -o "$sv/out3" --methods d2

# --- every app takes -h and -q; every app that segments takes -j ----------------------------------
all_apps=(flowseg_segment flowseg_sample flowseg_make_samples flowseg_signature flowseg_match flowseg_db flowseg_eval)
[ -x "$build/apps/flowseg_view" ] && all_apps+=(flowseg_view)
for app in "${all_apps[@]}"; do
  expect "$app -h" 0 "^Usage: $app" -- "$build/apps/$app" -h
  "$build/apps/$app" --help | grep -qE '^  -q, --quiet '; check "$app takes -q" $?
  "$build/apps/$app" --help | grep -qE '^  -j, --threads N '; check "$app takes -j" $?
done
for app in "${scan_apps[@]}"; do
  "$build/apps/$app" --help | grep -q -- "-j, --threads N        worker threads: 0 = all cores, 1 = sequential; the result is the same for"
  check "$app takes -j, --threads" $?
done
quiet_run() { # name, command...: exit 0 and nothing on stderr
  local name=$1
  shift
  "$@" >/dev/null 2>"$work/quiet.err"
  [ $? -eq 0 ] && [ ! -s "$work/quiet.err" ]; check "$name -q: exit 0, nothing on stderr" $?
}
quiet_run flowseg_segment "$seg" "$work/scan.pcd" -o "$work/q" -q
quiet_run flowseg_signature "$sig" "$work/scan.pcd" -q
quiet_run flowseg_match "$mat" "$work/scan.pcd" "$work/scan.pcd" -q
quiet_run flowseg_db "$db" query "$work/scans_own.db" "$work/scan.pcd" --use-sensor-origin -q
"$db" build "$work/no_views.db" "$work/scans" -q --use-sensor-origin --no-views
[ "$(wc -c < "$work/no_views.db")" -lt "$(wc -c < "$work/scans_own.db")" ] && ! grep -q '^v ' "$work/no_views.db"
check "db build --no-views stores no views, and a smaller file" $?
expect "db query against a database without views warns" 0 "none of the 4 stored shapes has views" -- "$db" query "$work/no_views.db" "$work/scan.pcd" --use-sensor-origin
expect "db query of a scan without its viewpoint warns" 0 "scan.pcd looks like a single view seen from its sensor origin \(0.5, 0, 12\): single-view matching needs that viewpoint" -- "$db" query "$work/scans_own.db" "$work/scan.pcd" -q
expect "db query of a complete shape gives no single-view warning" 0 "" -- "$db" query "$work/scans_own.db" "$src/samples/snowman3d.pcd" -q
! grep -q "single view" "$work/err.txt"; check "db query of a complete shape: no single-view warning" $?
expect "db query from a viewpoint inside the object" 1 "the viewpoint lies inside the scanned points' bounding box" -- "$db" query "$work/scans_own.db" "$work/scan.pcd" --viewpoint 1,0.2,0.1
expect "db query from a viewpoint that is not a number" 2 "viewpoint needs X,Y,Z \(three finite numbers\)" -- "$db" query "$work/scans_own.db" "$work/scan.pcd" --viewpoint nan,0,0
quiet_run flowseg_eval "$ev" "$work/scans" -o "$work/scans_eval4" --methods parts -q
quiet_run flowseg_sample "$smp" "$work/balls.off" -n 100 -o "$work/q.pcd" -q
quiet_run flowseg_make_samples "$gen" -o "$work/q_samples" --points2d 100 --points3d 100 -q
if [ -x "$build/apps/flowseg_view" ] && command -v xvfb-run >/dev/null 2>&1; then
  quiet_run flowseg_view xvfb-run -a -s "-screen 0 1024x768x24" "$build/apps/flowseg_view" "$work/scan.pcd" --size 200x200 --screenshot "$work/q.png" -q
fi

# --- the documentation holds every app's own --help -------------------------------------------
if [ -x "$build/apps/flowseg_view" ]; then
  bash "$src/scripts/update_app_docs.sh" "$build" "$work/apps.md"
  cmp -s "$work/apps.md" "$src/docs/apps.md"
  check "docs/apps.md holds every app's --help (run: bash scripts/update_app_docs.sh)" $?
else
  echo "SKIPPED: docs/apps.md check (flowseg_view is not built)"
fi

echo "apps: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
