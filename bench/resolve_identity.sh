#!/usr/bin/env bash
# Compares what two reconfig binaries answer about collision energies, hints and automatic
# resolution on every example: `check --energy --json`, `resolve --hint` for a part of each
# colliding transition, and `resolve --auto`. Use it to show that a change to the resolve
# module's speed left its answers bit for bit as they were.
#   bench/resolve_identity.sh OLD_RECONFIG NEW_RECONFIG OUT_DIR
set -uo pipefail
old=$1 new=$2 out=$3
mkdir -p "$out"
cd "$(dirname "${BASH_SOURCE[0]}")/.."
differ=0 runs=0
compare() {  # name, then the arguments after the binary; @OUT@ stands for a file each writes
  local name=$1
  shift
  local old_args=("${@//@OUT@/$out/$name.old.json}") new_args=("${@//@OUT@/$out/$name.new.json}")
  # Wall times and the output's own name are all that may differ.
  "$old" "${old_args[@]}" 2>&1 | sed -e '/"seconds":/d' -e "s|$out/$name.old.json|@OUT@|" >"$out/$name.old"
  local old_status=${PIPESTATUS[0]}
  "$new" "${new_args[@]}" 2>&1 | sed -e '/"seconds":/d' -e "s|$out/$name.new.json|@OUT@|" >"$out/$name.new"
  local new_status=${PIPESTATUS[0]}
  runs=$((runs + 1))
  if [[ $old_status != "$new_status" ]] || ! cmp -s "$out/$name.old" "$out/$name.new" ||
    { [[ -e $out/$name.old.json ]] && ! cmp -s "$out/$name.old.json" "$out/$name.new.json"; }; then
    echo "DIFFERENT: $name (exit $old_status vs $new_status; diff $out/$name.old $out/$name.new)"
    differ=$((differ + 1))
  fi
}
for scene in examples/*/scene.json; do
  example=$(basename "$(dirname "$scene")")
  compare "$example-energy" check "$scene" --energy --json
  # Each transition with a collision: a hint for the first part of its first interval, and --auto.
  python3 - "$out/$example-energy.new" <<'PY' >"$out/$example-pairs"
import json, sys
try:
    report = json.load(open(sys.argv[1]))
except ValueError:
    sys.exit(0)
for t in report.get("transitions", []):
    intervals = t.get("intervals", [])
    if intervals:
        print(t["name"], intervals[0]["parts"][0])
PY
  while read -r transition part; do
    compare "$example-$transition-hint" resolve "$scene" --transition "$transition" --hint "$part" --json
    compare "$example-$transition-auto" resolve "$scene" --transition "$transition" --auto -o @OUT@ --json
  done <"$out/$example-pairs"
done
echo "$runs runs, $differ different"
((differ == 0))
