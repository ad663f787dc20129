#!/usr/bin/env bash
# Whether two builds of the CLI answer the same about collision energies, hints and automatic
# resolution on every example: `check --energy --json`, `resolve --hint` for a part of each
# colliding transition, and `resolve --auto` (its output and the design it writes) must match
# byte for byte but for wall times and the written file's own name. For changes to the resolve
# module's speed that must not change any answer.
#
#   bench/resolve_identity.sh OLD_RECONFIG NEW_RECONFIG OUTDIR
#
# Prints one line per difference; exit 0 if none, 1 if any differ, 2 if a run failed.
set -uo pipefail
if [[ $# -ne 3 ]]; then
  echo "usage: $0 OLD_RECONFIG NEW_RECONFIG OUTDIR" >&2
  exit 2
fi
old=$(realpath "$1") new=$(realpath "$2")
mkdir -p "$3"
out=$(realpath "$3")
cd "$(dirname "${BASH_SOURCE[0]}")/.."
differ=0 runs=0
# name, then the arguments after the binary; @OUT@ stands for a file each side writes. Exit 1
# (collisions remain) is an answer; 2 and worse, or no output, are failures.
compare() {
  local name=$1
  shift
  local side status
  for side in old new; do
    local binary=$old
    [[ $side == new ]] && binary=$new
    rm -f "$out/$name.$side" "$out/$name.$side.json"
    status=0
    "$binary" "${@//@OUT@/$out/$name.$side.json}" >"$out/$name.$side.raw" || status=$?
    if [[ $status -ge 2 || ! -s $out/$name.$side.raw ]]; then
      echo "FAILED ($side, exit $status): $name" >&2
      exit 2
    fi
    sed -e '/"seconds":/d' -e "s|$out/$name.$side.json|@OUT@|" "$out/$name.$side.raw" >"$out/$name.$side"
    rm "$out/$name.$side.raw"
    echo "$status" >>"$out/$name.$side"
  done
  runs=$((runs + 1))
  if ! cmp -s "$out/$name.old" "$out/$name.new" ||
    { [[ -e $out/$name.old.json || -e $out/$name.new.json ]] && ! cmp -s "$out/$name.old.json" "$out/$name.new.json"; }; then
    echo "DIFFERENT: $name (diff $out/$name.old $out/$name.new)"
    differ=$((differ + 1))
  fi
}
for scene in examples/*/scene.json; do
  example=$(basename "$(dirname "$scene")")
  compare "$example-energy" check "$scene" --energy --json
  # Each transition with a collision: a hint for the first part of its first interval, and --auto.
  # (Tab-separated: names may hold spaces.)
  python3 - "$out/$example-energy.new" <<'PY' >"$out/$example-pairs" || exit 2
import json, sys
text = open(sys.argv[1]).read()
report = json.loads(text[: text.rstrip().rfind("\n")])  # the last line is the exit status
for t in report["transitions"]:
    if t["intervals"]:
        print(t["name"], t["intervals"][0]["parts"][0], sep="\t")
PY
  while IFS=$'\t' read -r transition part; do
    compare "$example-$transition-hint" resolve "$scene" --transition "$transition" --hint "$part" --json
    compare "$example-$transition-auto" resolve "$scene" --transition "$transition" --auto -o @OUT@ --json
  done <"$out/$example-pairs"
done
echo "$runs runs, $differ different"
((differ == 0))
