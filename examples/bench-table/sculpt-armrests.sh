#!/bin/sh
# The bench-table's solution (b): reshape the armrests until `unfold` stops colliding. The
# backrest, turning over, sweeps through the armrests' rear ends; one stroke of a box tool that
# holds the rear end pushes it 14 cm forward, the coating (8 cm) compressing the armrest ahead
# of it smoothly and without folding. Run from the repository root after building:
#   sh examples/bench-table/sculpt-armrests.sh
# It rewrites meshes/armrest-sculpted.obj (both armrests of scene-sculpted.json use it) from
# meshes/armrest.obj (generate_armrest.py) and checks the sculpted design: exit 0, collision-free.
set -e
cd "$(dirname "$0")/../.."
build/bin/reconfig sculpt examples/bench-table/meshes/armrest.obj \
  --tool box:0.2,0.2,0.2 --at 0,-0.25,0 --coating 0.08 --translate 0,0.14,0 \
  -o examples/bench-table/meshes/armrest-sculpted.obj
build/bin/reconfig check examples/bench-table/scene-sculpted.json
