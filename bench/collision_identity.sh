#!/usr/bin/env bash
# Whether two builds of the CLI detect the same collisions: `reconfig check --json` of every
# examples/*/scene.json (and any scene files given after OUTDIR), with 1 and 2 threads, plain,
# with a clearance and with every contact, must match byte for byte but for the "seconds" line
# (wall time). For changes that must not change any answer of the collision engine.
#
#   bench/collision_identity.sh OLD_RECONFIG NEW_RECONFIG OUTDIR [SCENE.json ...]
#
# Writes OUTDIR/{old,new}/<scene>-<threads>t-<mode>.json and prints one line per difference;
# exit 0 if none, 1 if any differ.
set -euo pipefail

if [[ $# -lt 3 ]]; then
  echo "usage: $0 OLD_RECONFIG NEW_RECONFIG OUTDIR [SCENE.json ...]" >&2
  exit 2
fi
old=$1 new=$2 out=$3
shift 3
root=$(cd "$(dirname "$0")/.." && pwd)
scenes=("$root"/examples/*/scene.json "$@")
# The clearance is in scene units: every example is about a metre (0.01: 1 cm).
modes=(plain "clearance:--clearance 0.01" "all:--all-contacts")
mkdir -p "$out/old" "$out/new"

runs=0 differ=0
for scene in "${scenes[@]}"; do
  name=$(basename "$(dirname "$scene")")
  for threads in 1 2; do
    for mode in "${modes[@]}"; do
      label=${mode%%:*}
      flags=()
      [[ $mode == *:* ]] && read -r -a flags <<<"${mode#*:}"
      file="$name-${threads}t-$label.json"
      for side in old new; do
        binary=$old
        [[ $side == new ]] && binary=$new
        # Exit 1 means collisions were found: only 2 (bad input) and worse are failures, and so
        # is no output (a crash may print nothing).
        status=0
        "$binary" check --json --threads "$threads" "${flags[@]}" "$scene" >"$out/$side/$file.raw" || status=$?
        if [[ $status -ge 2 || ! -s $out/$side/$file.raw ]]; then
          echo "FAILED ($side, exit $status): $file" >&2
          exit 2
        fi
        grep -v '"seconds":' "$out/$side/$file.raw" >"$out/$side/$file"
        rm "$out/$side/$file.raw"
      done
      runs=$((runs + 1))
      if ! cmp -s "$out/old/$file" "$out/new/$file"; then
        differ=$((differ + 1))
        echo "DIFFERS: $file"
      fi
    done
  done
done
echo "$runs runs, $differ differ"
[[ $differ -eq 0 ]]
