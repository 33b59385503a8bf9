#!/usr/bin/env bash
# Segments each input with two builds of flowseg_segment and compares their label files byte for
# byte: the check that a change kept the behaviour (same labels for the same input and parameters).
#   bash scripts/compare_labels.sh OLD_FLOWSEG_SEGMENT NEW_FLOWSEG_SEGMENT INPUT... [-- OPTIONS...]
# OPTIONS go to both runs. Prints one line per input and a summary; exits 1 when any differ.
set -euo pipefail

if [ $# -lt 3 ]; then
  sed -n '2,5p' "$0" >&2
  exit 2
fi
old=$1 new=$2
shift 2
inputs=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do inputs+=("$1"); shift; done
[ $# -gt 0 ] && shift
options=("$@")

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
same=0 differ=0
for input in "${inputs[@]}"; do
  name=$(basename "$input")
  "$old" "$input" -o "$work/old" "${options[@]}" > "$work/old.log" 2>&1 || { echo "old build failed on $input" >&2; cat "$work/old.log" >&2; exit 1; }
  "$new" "$input" -o "$work/new" "${options[@]}" > "$work/new.log" 2>&1 || { echo "new build failed on $input" >&2; cat "$work/new.log" >&2; exit 1; }
  if cmp -s "$work/old.labels.pcd" "$work/new.labels.pcd"; then
    same=$((same + 1))
    echo "same    $name ($(head -1 "$work/new.log" | sed 's/.*maxima, //'))"
  else
    differ=$((differ + 1))
    echo "DIFFER  $name"
  fi
done
echo "compare_labels: $same same, $differ differ"
[ "$differ" -eq 0 ]
