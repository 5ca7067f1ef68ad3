#!/usr/bin/env python3
"""Lists the edges beyond the feature angle that a crease contrast drops.

    python3 benchmark/contrast_dropped_edges.py MESH.off [CONTRAST [FEATURE_ANGLE]]

For each edge of the OFF mesh whose face normals are more than FEATURE_ANGLE
(default 20) degrees apart, the crease contrast (user manual, "Crease
contrast"; default 5) compares that angle with the angle of the flatter of the
two other edges of each of its faces; this prints the edges it drops: their
vertices (0-based, in the file's order), the angle, the larger of the two
flatter angles, the length relative to the bounding-box diagonal and the
position of the first vertex. A diagnostic written from the manual's rule,
not the package's code: the package's count is the difference of the tool's
"sharp edges" with contrast 0 and with the contrast.
"""

import math
import sys


def read_off(path):
    words = []
    with open(path) as f:
        for line in f:
            words += line.split("#")[0].split()
    if words[0] == "OFF":
        words = words[1:]
    elif words[0].startswith("OFF"):
        words[0] = words[0][3:]
    nv, nf = int(words[0]), int(words[1])
    at = 3
    points = [tuple(float(w) for w in words[at + 3 * i:at + 3 * i + 3]) for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append(tuple(int(w) for w in words[at + 1:at + 1 + n]))
        at += 1 + n
    return points, faces


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def unit_normal(p, f):
    u, v = sub(p[f[1]], p[f[0]]), sub(p[f[2]], p[f[0]])
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = math.sqrt(sum(c * c for c in n))
    return tuple(c / length for c in n) if length > 0 else (0.0, 0.0, 0.0)


def main():
    path = sys.argv[1]
    contrast = float(sys.argv[2]) if len(sys.argv) > 2 else 5.0
    feature = float(sys.argv[3]) if len(sys.argv) > 3 else 20.0
    points, faces = read_off(path)
    normals = [unit_normal(points, f) for f in faces]
    edge_faces = {}
    for i, f in enumerate(faces):
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            edge_faces.setdefault((min(a, b), max(a, b)), []).append(i)
    angle = {}
    for e, fs in edge_faces.items():
        if len(fs) != 2:
            angle[e] = 0.0
            continue
        c = sum(x * y for x, y in zip(normals[fs[0]], normals[fs[1]]))
        angle[e] = math.acos(max(-1.0, min(1.0, c)))

    def flatter(i, e):
        f = faces[i]
        others = [(min(f[k], f[(k + 1) % 3]), max(f[k], f[(k + 1) % 3])) for k in range(3)]
        return min(angle[g] for g in others if g != e)

    lo = [min(p[i] for p in points) for i in range(3)]
    hi = [max(p[i] for p in points) for i in range(3)]
    diagonal = math.sqrt(sum((h - l) ** 2 for h, l in zip(hi, lo)))
    beyond = [e for e in edge_faces if len(edge_faces[e]) == 2 and angle[e] > math.radians(feature)]
    dropped = []
    for e in beyond:
        around = max(flatter(i, e) for i in edge_faces[e])
        if angle[e] < contrast * around:
            dropped.append((e, around))
    print(f"{path}: {len(beyond)} edges beyond {feature:g} degrees, {len(dropped)} dropped by a contrast of {contrast:g}")
    for e, around in dropped:
        length = math.sqrt(sum(c * c for c in sub(points[e[0]], points[e[1]]))) / diagonal
        position = " ".join(f"{c:.4f}" for c in points[e[0]])
        print(f"edge {e[0]} {e[1]}: angle {math.degrees(angle[e]):.1f}, flatter other edges {math.degrees(around):.1f}, "
              f"length {length:.4f}, at {position}")


if __name__ == "__main__":
    main()
