#!/usr/bin/env bash
# Installs the build into a temporary prefix and builds a consumer project against it, through
# the CMake package and through pkg-config. Usage: run_install_test.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
src=$2
work=$(mktemp -d /tmp/flowseg_install_XXXXXX)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/pcl_flowseg/segmentation/flow_segmentation.h"
test -f "$work/prefix/include/pcl_flowseg/evaluation/retrieval_scores.h"
test -f "$work/prefix/lib/cmake/pcl_flowseg/pcl_flowsegConfig.cmake" || test -f "$work"/prefix/lib/*/cmake/pcl_flowseg/pcl_flowsegConfig.cmake
if grep -rl "CGAL/" "$work/prefix/include/pcl_flowseg" >/dev/null; then
  echo "FAILED: a public header includes CGAL"; exit 1
fi
cmake -S "$src/test/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" -j 2 >/dev/null
LD_LIBRARY_PATH="$work/prefix/lib:$(dirname "$(find "$work/prefix" -name 'libpcl_flowseg.so' | head -1)")" "$work/consumer/consumer"
# The same consumer through pkg-config (the .pc files find their prefix from where they lie).
pc=$(find "$work/prefix" -name pcl_flowseg.pc | head -1)
flags=$(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --cflags --libs pcl_flowseg_eval pcl_flowseg)
echo "$flags" | grep -q -- "-lpcl_flowseg_eval"
echo "$flags" | grep -qE -- "-lpcl_flowseg( |$)"
# shellcheck disable=SC2086
g++ -std=c++17 "$src/test/consumer/main.cpp" -o "$work/consumer_pkgconfig" $flags
LD_LIBRARY_PATH="$work/prefix/lib:$(dirname "$(find "$work/prefix" -name 'libpcl_flowseg.so' | head -1)")" "$work/consumer_pkgconfig"
# The library users link for segmentation carries no evaluation code and no ESF dependency.
lib=$(find "$work/prefix" -name 'libpcl_flowseg.so' | head -1)
if nm -DC "$lib" | grep -qE ' T .*(scoreRetrieval|esfDescriptor|sampleShapes)'; then
  echo "FAILED: libpcl_flowseg.so exports evaluation code"; exit 1
fi
if ldd "$lib" | grep -q libpcl_features; then
  echo "FAILED: libpcl_flowseg.so links pcl_features"; exit 1
fi
if ldd "$lib" | grep -q libpcl_io; then
  echo "FAILED: libpcl_flowseg.so links pcl_io (it opens the plugin with PCL's I/O on first use)"; exit 1
fi
test -f "$(dirname "$lib")/libpcl_flowseg_pcl.so" || { echo "FAILED: the plugin libpcl_flowseg_pcl.so is not installed beside the library"; exit 1; }
# The Python package, when built: importable from its install directory with no library path
# (its RPATH finds libpcl_flowseg.so), segmenting a shipped sample.
package=$(find "$work/prefix" -path '*dist-packages/pcl_flowseg/__init__.py' | head -1)
if [ -f "$build/python/pcl_flowseg/__init__.py" ]; then
  [ -n "$package" ] || { echo "FAILED: the Python package was built but not installed"; exit 1; }
  python=$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt") # the interpreter it was built for
  PYTHONPATH=$(dirname "$(dirname "$package")") "${python:-/usr/bin/python3}" -c "
import sys, pcl_flowseg as fs
assert fs.__file__.startswith('$work/prefix'), fs.__file__
seg = fs.segment(fs.read_points(sys.argv[1])[0])
assert len(seg.features) > 0
" "$src/samples/animal3d.pcd"
fi
echo "install: 1 passed, 0 failed"
