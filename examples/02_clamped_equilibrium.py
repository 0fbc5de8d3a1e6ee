"""02_clamped_equilibrium: the boundary-value problem. The gripper holds the band's tip 0.12 m
aside, 0.22 m up, turned 90° about y; shooting finds the base wrench whose integration ends there,
and the conjugate-point test says whether that equilibrium is stable. Same as
02_clamped_equilibrium.cpp."""
import sys

import numpy as np

import rodshape

rod = rodshape.rubber_band()
quarter_turn_about_y = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])
tip = rodshape.ClampedTip(rodshape.Pose([0.12, 0.0, 0.22], quarter_turn_about_y))

# Solve, check the held pose's validity and the stability (a stable one sought if unstable).
analysis = rodshape.analyse_equilibrium(rod, tip)
print(analysis.brief())
if not analysis.converged():
    sys.exit(1)
w = analysis.solution.base_wrench
print("n(0) = ({:.5f}, {:.5f}, {:.5f}) N, m(0) = ({:.5f}, {:.5f}, {:.5f}) N·m, energy {:.6g} J"
      .format(*w.force, *w.moment, analysis.configuration.energy))
