#!/usr/bin/env bash
# Runs every bundled example as CI's step 3 does (each examples/*.yaml through the command its name
# asks for, and the seeded validations) with the tool of a build, writing their result files into
# one folder; or compares two such folders byte for byte (a refactoring that must not change
# behaviour: every plan.json, validation.json and equilibrium/estimate JSON the same).
# Usage: bash scripts/example_outputs.sh run OUT [BUILD]       (BUILD: default build/)
#        bash scripts/example_outputs.sh compare BEFORE AFTER  (exit 1 on any difference)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

run() {
  local out="$1" tool="${2:-build}/rodshape"
  mkdir -p "$out"
  for task in examples/*.yaml; do
    local name
    name=$(basename "$task" .yaml)
    case "$name" in
      estimate_*) "$tool" estimate "$task" --cloud "examples/clouds/$name.ply" -o "$out/$name.json" > /dev/null ;;
      plan_* | validate_*) "$tool" plan -q "$task" -o "$out/$name" ;;
      *) "$tool" equilibrium -q "$task" -o "$out/$name.json" ;;
    esac
  done
  "$tool" validate -q examples/plan_c_arc.yaml -o "$out/validate_c_arc" --runs 2
  "$tool" validate -q examples/plan_c_arc.yaml -o "$out/validate_c_arc_closed" --runs 2 --closed-loop
  "$tool" validate -q examples/plan_panda_closed_loop.yaml -o "$out/validate_panda_closed" --runs 2 \
    --closed-loop
  "$tool" validate -q examples/validate_depth_camera.yaml -o "$out/validate_depth_camera" --runs 1 \
    --closed-loop
  "$tool" validate -q examples/plan_two_pandas.yaml -o "$out/validate_two_pandas" --runs 1 --closed-loop
  "$tool" validate -q examples/plan_around_post.yaml -o "$out/validate_post_closed" --runs 1 --closed-loop
  echo "example_outputs: $(find "$out" -name '*.json' | wc -l) JSON files in $out"
}

compare() {
  local before="$1" after="$2" differ=0 files=0
  while IFS= read -r file; do
    files=$((files + 1))
    if [ ! -f "$after/$file" ]; then
      echo "missing in $after: $file"
      differ=$((differ + 1))
    elif ! cmp -s "$before/$file" "$after/$file"; then
      echo "differs: $file"
      differ=$((differ + 1))
    fi
  done < <(cd "$before" && find . -name '*.json' | sort)
  echo "example_outputs: $files JSON files compared, $differ differ"
  [ "$differ" -eq 0 ]
}

case "${1:-}" in
  run) run "${2:?OUT}" "${3:-build}" ;;
  compare) compare "${2:?BEFORE}" "${3:?AFTER}" ;;
  *)
    echo "usage: $0 run OUT [BUILD] | compare BEFORE AFTER" >&2
    exit 2
    ;;
esac
