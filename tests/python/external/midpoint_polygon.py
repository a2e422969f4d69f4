"""An external algorithm with vertices of its own: the polygon through the midpoints of the
points taken in order of angle around their centroid (right for a star-shaped curve only).

    python midpoint_polygon.py POINTS OUTPUT --format edges --vertices VERTICES
    python midpoint_polygon.py POINTS OUTPUT --format reconstruction-json

With the edges format the vertices go to a points file and the edges, `i j` between them, to
OUTPUT; with the JSON format both go to OUTPUT as a reconstruction's curve.
"""
import argparse
import json

import numpy as np

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("points")
parser.add_argument("output")
parser.add_argument("--format", choices=["edges", "reconstruction-json"], required=True)
parser.add_argument("--vertices", help="points file of the vertices (edges format)")
args = parser.parse_args()
points = np.loadtxt(args.points, ndmin=2)
offsets = points - points.mean(axis=0)
ordered = points[np.argsort(np.arctan2(offsets[:, 1], offsets[:, 0]))]
midpoints = (ordered + np.roll(ordered, -1, axis=0)) / 2
edges = [(i, (i + 1) % len(midpoints)) for i in range(len(midpoints))]
if args.format == "edges":
    np.savetxt(args.vertices, midpoints, fmt="%.17g")
    with open(args.output, "w") as out:
        out.write("".join(f"{i} {j}\n" for i, j in edges))
else:
    with open(args.output, "w") as out:
        json.dump({"curve": {"vertices": midpoints.tolist(), "edges": edges}}, out)
