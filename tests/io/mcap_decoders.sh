#!/usr/bin/env bash
# mcap_decoders.sh: ctest io.mcap_decoders (issue 49, item 2). Writes plan.mcap and
# validation.mcap from bundled examples (a plan without an arm, zstd; the Panda's S-curve with its
# joint trajectory, uncompressed; two Pandas; a validation with markers; one with a depth camera)
# and reads every message back with npm's decoders (tests/io/mcap_decoders.mjs).
# Usage: mcap_decoders.sh RODSHAPE_CLI SOURCE_DIR BUILD_DIR
# The decoders are looked for in $RODSHAPE_MCAP_DECODERS, else BUILD_DIR/mcap-decoders (an npm
# prefix: its node_modules). Without node or without them the test is skipped (exit 77), saying
# how to install them; it never downloads anything itself.
set -euo pipefail
cli="$1"
source_dir="$2"
build_dir="$3"
prefix="${RODSHAPE_MCAP_DECODERS:-$build_dir/mcap-decoders}"
packages=(@mcap/core @foxglove/rosmsg @foxglove/rosmsg2-serialization fzstd)

if ! command -v node > /dev/null 2>&1; then
  echo "SKIP: node is not installed (Debian: apt-get install nodejs npm); the MCAP files are not decoded"
  exit 77
fi
for package in "${packages[@]}"; do
  if [ ! -f "$prefix/node_modules/$package/package.json" ]; then
    echo "SKIP: npm package $package is not in $prefix/node_modules; install the decoders with:"
    echo "  npm install --prefix $prefix ${packages[*]}"
    echo "(or set RODSHAPE_MCAP_DECODERS to an npm prefix that has them)"
    exit 77
  fi
done

out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
examples="$source_dir/examples"
"$cli" plan "$examples/plan_c_arc.yaml" -o "$out/plan_c_arc" -q --no-html --mcap
"$cli" plan "$examples/plan_panda_s_curve.yaml" -o "$out/plan_panda_s_curve" -q --no-html --mcap \
  --mcap-compression none
"$cli" plan "$examples/plan_two_pandas.yaml" -o "$out/plan_two_pandas" -q --no-html --mcap
"$cli" validate "$examples/plan_c_arc.yaml" -o "$out/validate_c_arc" -q --no-html --runs 1 --mcap
"$cli" validate "$examples/validate_depth_camera.yaml" -o "$out/validate_depth_camera" -q --no-html \
  --runs 1 --mcap --mcap-compression none
node "$source_dir/tests/io/mcap_decoders.mjs" --modules "$prefix" "$out"/*
