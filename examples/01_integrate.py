"""01_integrate: the forward problem. The paper's rubber band, clamped at the origin along +z, is
integrated from a base wrench n(0), m(0). An end moment M about y bends an inextensible rod into an
arc of radius EI / M, so the tip can be checked against the circle. Same as 01_integrate.cpp."""
import sys

import numpy as np

import rodshape

rod = rodshape.rubber_band(rodshape.ConstitutiveModel.Kirchhoff, 100)
M = 0.05  # N·m about y
c = rodshape.integrate(rod, rodshape.BaseWrench(moment=[0.0, M, 0.0]))

L, EI = rod.properties.length, rod.properties.K_rot[1]
r = EI / M
arc_tip = np.array([r * (1 - np.cos(L / r)), 0.0, r * np.sin(L / r)])
tip = c.tip.position
print(f"nodes {c.nodes}, tip ({tip[0]:.6f}, {tip[1]:.6f}, {tip[2]:.6f}) m, "
      f"energy {c.energy:.6g} J")
print(f"distance to the arc's tip {np.linalg.norm(tip - arc_tip):.2e} m, "
      f"energy M²L/(2EI) = {M * M * L / (2 * EI):.6g} J")
print("positions", c.positions.shape, "rotations", c.rotations.shape)
sys.exit(0 if np.linalg.norm(tip - arc_tip) < 1e-9 else 1)
