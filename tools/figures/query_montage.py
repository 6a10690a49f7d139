#!/usr/bin/python3
"""Pictures of retrieval queries: for the worst queries of a distance matrix
(the nearest neighbour in another class first, then the lowest first tier),
one row per query: the query mesh, then its top results, each titled with
its class and distance (results of the query's class framed in green, others
in red).

Needs only Debian's python3-numpy and python3-matplotlib; reads the PSB
binary .matrix (float32 N x N), the PSB .cla and OFF meshes named
<model>.off in MESH_DIR.

    query_montage.py DIST.matrix CLASSES.cla MESH_DIR OUT.png [--queries 4] [--results 4]
"""
import argparse
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read_cla(path):
    """Model names and class names in .cla order."""
    words = open(path).read().split()
    assert words[0] == "PSB", f"{path}: not a PSB .cla file"
    classes, pos, models, labels = int(words[2]), 4, [], []
    for _ in range(classes):
        name, count = words[pos], int(words[pos + 2])
        pos += 3
        models += words[pos:pos + count]
        labels += [name] * count
        pos += count
    return models, labels


def read_off(path):
    """Vertices and triangles of an OFF file (polygons fanned)."""
    tokens = [t for line in open(path) for t in line.split("#")[0].split()]
    pos = 1 if tokens[0].endswith("OFF") else 0
    nv, nf = int(tokens[pos]), int(tokens[pos + 1])
    pos += 3
    verts = np.array(tokens[pos:pos + 3 * nv], dtype=float).reshape(nv, 3)
    pos += 3 * nv
    tris = []
    for _ in range(nf):
        k = int(tokens[pos])
        face = [int(x) for x in tokens[pos + 1:pos + 1 + k]]
        tris += [[face[0], face[i], face[i + 1]] for i in range(1, k - 1)]
        pos += 1 + k
    return verts, np.array(tris)


def draw(ax, verts, tris, title, color):
    pts = verts[tris]
    normals = np.cross(pts[:, 1] - pts[:, 0], pts[:, 2] - pts[:, 0])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-30)
    shade = 0.35 + 0.65 * np.abs(normals @ np.array([0.4, -0.6, 0.7]) / np.linalg.norm([0.4, -0.6, 0.7]))
    ax.add_collection3d(Poly3DCollection(pts, facecolors=np.outer(shade, [0.75, 0.78, 0.85]), edgecolors="none"))
    lo, hi = verts.min(axis=0), verts.max(axis=0)
    c, r = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(c[0] - r, c[0] + r), ax.set_ylim(c[1] - r, c[1] + r), ax.set_zlim(c[2] - r, c[2] + r)
    ax.set_box_aspect((1, 1, 1), zoom=1.3)
    ax.set_axis_off()
    ax.set_title(title, fontsize=8, color=color)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("matrix"), p.add_argument("cla"), p.add_argument("mesh_dir"), p.add_argument("out")
    p.add_argument("--queries", type=int, default=4)
    p.add_argument("--results", type=int, default=4)
    a = p.parse_args(argv)
    models, labels = read_cla(a.cla)
    n = len(models)
    d = np.fromfile(a.matrix, dtype="<f4")
    assert d.size == n * n, f"{a.matrix}: {d.size} values for {n} models in {a.cla}"
    d = d.reshape(n, n)
    labels = np.array(labels)
    order, badness = [], []
    for q in range(n):
        ranking = [i for i in np.lexsort((np.arange(n), d[q])) if i != q]  # ties by index
        k = int((labels == labels[q]).sum()) - 1
        first_tier = float(np.mean(labels[ranking[:k]] == labels[q])) if k > 0 else 1.0
        order.append(ranking)
        badness.append((labels[ranking[0]] == labels[q], first_tier, q))
    worst = [q for _, _, q in sorted(badness)[: a.queries]]
    cols = a.results + 1
    fig = plt.figure(figsize=(2.2 * cols, 2.3 * len(worst)), dpi=100)
    for row, q in enumerate(worst):
        cells = [(q, f"query {models[q]}\n{labels[q]}", "black")]
        for i in order[q][: a.results]:
            good = labels[i] == labels[q]
            cells.append((i, f"{models[i]}: {labels[i]}\nd = {d[q, i]:.3f}", "green" if good else "red"))
        for col, (i, title, color) in enumerate(cells):
            ax = fig.add_subplot(len(worst), cols, row * cols + col + 1, projection="3d")
            verts, tris = read_off(os.path.join(a.mesh_dir, models[i] + ".off"))
            draw(ax, verts, tris, title, color)
    fig.tight_layout()
    fig.savefig(a.out)
    print(f"wrote {a.out}: queries " + ", ".join(f"{models[q]} ({labels[q]})" for q in worst))


if __name__ == "__main__":
    main(sys.argv[1:])
