"""An external algorithm for curvebench, in Python: the nearest-neighbour chain.

    python nn_chain.py POINTS OUTPUT --neighbours K [--open]

Reads a points file (`x y` per line), starts at the first point and walks to the nearest
point not yet visited (scipy's k-d tree, asking for K neighbours at a time and more when
those are all visited), and writes the chain's edges as `i j` lines, closed back to the first
point unless --open. A reference method for tests and for the README, not a good one.
"""
import argparse

import numpy as np
from scipy.spatial import cKDTree


def nearest_neighbour_chain(points: np.ndarray, neighbours: int) -> list[tuple[int, int]]:
    tree = cKDTree(points)
    visited = np.zeros(len(points), dtype=bool)
    current = 0
    visited[current] = True
    edges = []
    for _ in range(len(points) - 1):
        k = min(neighbours + 1, len(points))
        while True:
            _, candidates = tree.query(points[current], k=k)
            unvisited = [c for c in np.atleast_1d(candidates) if not visited[c]]
            if unvisited or k == len(points):
                break
            k = min(2 * k, len(points))
        following = int(unvisited[0])
        edges.append((current, following))
        visited[following] = True
        current = following
    return edges


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("points")
    parser.add_argument("output")
    parser.add_argument("--neighbours", type=int, required=True)
    parser.add_argument("--open", action="store_true", help="do not close the chain")
    args = parser.parse_args()
    points = np.loadtxt(args.points, ndmin=2)
    edges = nearest_neighbour_chain(points, args.neighbours)
    if not args.open and len(points) > 2:
        edges.append((edges[-1][1], 0))
    with open(args.output, "w") as out:
        out.write("".join(f"{i} {j}\n" for i, j in edges))


if __name__ == "__main__":
    main()
