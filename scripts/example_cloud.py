#!/usr/bin/env python3
"""Writes examples/clouds/estimate_band.ply: a synthetic depth-camera cloud of the rubber band of
examples/estimate_band.yaml, in the camera's frame (m). The band's equilibrium comes from
`rodshape equilibrium examples/rubber_band.yaml` (JSON on stdin): 500 points of its surface (the
tube of the section's circumscribed radius, 14.1 mm) that face the camera, the middle third of the
length hidden, Kinect v2 noise (axial 1.5 - 0.5 z + 0.3 z^2 mm along the ray, lateral 0.8 px),
then 10 % of the points replaced by outliers in the band's bounding box grown by 5 cm. Seeded.
  build/rodshape equilibrium examples/rubber_band.yaml | /usr/bin/python3 scripts/example_cloud.py
"""
import json
import math
import random
import sys

import numpy as np


def rotation(q):
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def main():
    nodes = json.load(sys.stdin)["nodes"]
    P, S = np.array(nodes["position"]), np.array(nodes["s"])
    Q = [rotation(q) for q in nodes["rotation"]]
    cam_p = np.array([0.0, -1.0, 0.15])
    q = np.array([0.7071068, -0.7071068, 0.0, 0.0])
    cam_R = rotation(q / np.linalg.norm(q))
    radius, length = 0.01 * math.sqrt(2.0), S[-1]
    focal = 0.5 * (256 / math.tan(math.radians(35.3)) + 212 / math.tan(math.radians(30.0)))
    rng = random.Random(22)
    points = []
    while len(points) < 500:
        s = rng.uniform(0.0, length)
        if length / 3 <= s < 2 * length / 3:
            continue  # hidden
        i = min(int(s / length * (len(S) - 1)), len(S) - 2)
        t = (s - S[i]) / (S[i + 1] - S[i])
        centre = (1 - t) * P[i] + t * P[i + 1]
        R = Q[i] if t < 0.5 else Q[i + 1]
        phi = rng.uniform(0.0, 2 * math.pi)
        normal = R @ np.array([math.cos(phi), math.sin(phi), 0.0])
        x = centre + radius * normal
        ray = (x - cam_p) / np.linalg.norm(x - cam_p)
        if normal @ ray >= 0:
            continue  # the far side
        z = (cam_R.T @ (x - cam_p))[2]
        axial, lateral = 1.5e-3 - 0.5e-3 * z + 0.3e-3 * z * z, 0.8 * z / focal
        a = np.cross(ray, [0.0, 0.0, 1.0])
        a /= np.linalg.norm(a)
        b = np.cross(ray, a)
        points.append(x + axial * rng.gauss(0, 1) * ray +
                      lateral * (rng.gauss(0, 1) * a + rng.gauss(0, 1) * b))
    lo, hi = P.min(0) - 0.05, P.max(0) + 0.05
    for k in range(50):
        points[k] = np.array([rng.uniform(lo[j], hi[j]) for j in range(3)])
    with open("examples/clouds/estimate_band.ply", "w") as out:
        out.write("ply\nformat ascii 1.0\n"
                  "comment the rubber band of examples/estimate_band.yaml in the camera frame, m\n"
                  "comment synthetic (scripts/example_cloud.py): Kinect v2 noise, the middle "
                  "third hidden, 10 percent outliers\n"
                  f"element vertex {len(points)}\nproperty float x\nproperty float y\n"
                  "property float z\nend_header\n")
        for p in points:
            c = cam_R.T @ (p - cam_p)
            out.write(f"{c[0]:.6f} {c[1]:.6f} {c[2]:.6f}\n")


if __name__ == "__main__":
    main()
