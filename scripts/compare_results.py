#!/usr/bin/env python3
"""Compares two directories of rodshape results, number by number.

Usage:
  scripts/compare_results.py OLD NEW [--tolerance 1e-12]

OLD and NEW hold what `rodshape equilibrium` (*.json) and `rodshape plan` (one directory per task
with plan.json, trajectory.csv, joint_trajectory.*) wrote for the same task files, e.g.

  for t in examples/*.yaml; do n=$(basename "$t" .yaml)
    case $n in plan_* | validate_*) build/rodshape plan "$t" -o OUT/$n -q ;;
               estimate_*) ;;  # rodshape estimate: see docs/estimate.md
               *) build/rodshape equilibrium "$t" -o OUT/$n.json -q ;; esac; done

Numbers agree when |a - b| <= tolerance * max(1, |a|, |b|); strings, keys and list lengths must be
equal. SVG pictures are not compared (they round their coordinates). Prints every difference and
exits 1 when there is one. Standard library only.
"""
import argparse
import csv
import json
import math
import os
import sys


def close(a, b, tolerance):
    if isinstance(a, bool) or isinstance(b, bool):
        return a == b
    if math.isnan(a) and math.isnan(b):
        return True
    return abs(a - b) <= tolerance * max(1.0, abs(a), abs(b))


def compare_values(a, b, where, tolerance, out):
    number = (int, float)
    if isinstance(a, number) and isinstance(b, number) and not isinstance(a, bool):
        if not close(float(a), float(b), tolerance):
            out.append(f"{where}: {a!r} != {b!r}")
    elif isinstance(a, dict) and isinstance(b, dict):
        for key in sorted(set(a) | set(b)):
            if key not in a or key not in b:
                out.append(f"{where}.{key}: only in {'new' if key in b else 'old'}")
            else:
                compare_values(a[key], b[key], f"{where}.{key}", tolerance, out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{where}: {len(a)} items != {len(b)}")
        for i, (x, y) in enumerate(zip(a, b)):
            compare_values(x, y, f"{where}[{i}]", tolerance, out)
    elif a != b:
        out.append(f"{where}: {a!r} != {b!r}")


def cell(text):
    try:
        return float(text)
    except ValueError:
        return text


def read_csv(path):
    with open(path, newline="") as f:
        return [[cell(c) for c in row] for row in csv.reader(f)]


def compare_file(old, new, name, tolerance, out):
    if name.endswith(".json"):
        with open(old) as f, open(new) as g:
            compare_values(json.load(f), json.load(g), name, tolerance, out)
    elif name.endswith(".csv"):
        compare_values(read_csv(old), read_csv(new), name, tolerance, out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--tolerance", type=float, default=1e-12)
    args = parser.parse_args()
    differences, files = [], 0
    for root, _, names in os.walk(args.old):
        for name in sorted(names):
            if not name.endswith((".json", ".csv")):
                continue
            old = os.path.join(root, name)
            relative = os.path.relpath(old, args.old)
            new = os.path.join(args.new, relative)
            if not os.path.exists(new):
                differences.append(f"{relative}: missing in {args.new}")
                continue
            files += 1
            compare_file(old, new, relative, args.tolerance, differences)
    for line in differences[:200]:
        print(line)
    print(f"compared {files} files: {len(differences)} differences (tolerance {args.tolerance:g})")
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main())
