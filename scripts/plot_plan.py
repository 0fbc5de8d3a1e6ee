#!/usr/bin/python3
"""Figures (PNG) of a `rodshape plan` output directory: the command-line face of
rodshape.plot.plan_directory_figures (python/rodshape/plot.py).

    scripts/plot_plan.py OUTDIR [--output-dir FIGDIR] [--urdf PATH]

Writes end_effector_path.png, joint_positions.png (with a robot) and reach.png (with a reach shell)
into FIGDIR (default OUTDIR). Needs matplotlib and numpy (the system Python: /usr/bin/python3); not
the compiled module.
"""
import argparse
import importlib.util
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

ROOT = Path(__file__).resolve().parent.parent
_spec = importlib.util.spec_from_file_location("rodshape_plot", ROOT / "python" / "rodshape" / "plot.py")
plot = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(plot)


def main():
    parser = argparse.ArgumentParser(description="PNG figures of a `rodshape plan` output directory.")
    parser.add_argument("outdir", type=Path, help="the directory `rodshape plan -o` wrote")
    parser.add_argument("--output-dir", type=Path, help="where to write the PNGs (default OUTDIR)")
    parser.add_argument("--urdf", type=Path, default=plot.DEFAULT_URDF,
                        help="the robot's URDF, for the joint limits (default %(default)s)")
    args = parser.parse_args()
    written = plot.plan_directory_figures(args.outdir, args.output_dir, args.urdf)
    print("wrote " + (" ".join(str(p) for p in written) if written else "nothing"))


if __name__ == "__main__":
    try:
        main()
    except plot.InputError as e:
        print(f"plot_plan.py: error: {e}", file=sys.stderr)
        sys.exit(2)
