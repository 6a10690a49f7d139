#!/usr/bin/python3
"""Render a colored mesh (PLY written by reebkit) to a PNG, optionally with
polylines over it (an OBJ of `l` lines, e.g. a Reeb graph or its skeleton).

Needs only Debian's python3-numpy and python3-matplotlib; reads PLY (ascii or
binary, as written by `reeb features --ply` / `reeb graph --ply`) by itself.

    render_mesh.py MESH.ply OUT.png [--lines graph.obj] [--view ELEV AZIM] [--title T]
"""
import argparse
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

PLY_TYPES = {"char": "i1", "uchar": "u1", "short": "i2", "ushort": "u2", "int": "i4", "uint": "u4",
             "float": "f4", "double": "f8", "int8": "i1", "uint8": "u1", "int16": "i2", "uint16": "u2",
             "int32": "i4", "uint32": "u4", "float32": "f4", "float64": "f8"}


def read_ply(path):
    """Vertices (n,3), triangles (m,3) and vertex colors (n,3) in [0,1] or None."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    fmt, elements = None, []
    for line in header:
        words = line.split()
        if not words:
            continue
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append([words[1], int(words[2]), []])
        elif words[0] == "property":
            elements[-1][2].append(words[1:])
    body = data[end:]
    order = "<" if fmt == "binary_little_endian" else ">"
    out = {}
    if fmt == "ascii":
        tokens = body.split()
        pos = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for p in props:
                    if p[0] == "list":
                        k = int(tokens[pos]); pos += 1
                        row.append([float(t) for t in tokens[pos:pos + k]]); pos += k
                    else:
                        row.append(float(tokens[pos])); pos += 1
                rows.append(row)
            out[name] = (props, rows)
    else:
        offset = 0
        for name, count, props in elements:
            if all(p[0] != "list" for p in props):
                dtype = np.dtype([(p[1], order + PLY_TYPES[p[0]]) for p in props])
                arr = np.frombuffer(body, dtype=dtype, count=count, offset=offset)
                offset += dtype.itemsize * count
                out[name] = (props, arr)
            else:  # faces: assume "list <count type> <index type>" only, as reebkit writes
                ct, it = PLY_TYPES[props[0][1]], PLY_TYPES[props[0][2]]
                rows = []
                for _ in range(count):
                    k = int(np.frombuffer(body, order + ct, 1, offset)[0]); offset += np.dtype(ct).itemsize
                    rows.append(np.frombuffer(body, order + it, k, offset)); offset += np.dtype(it).itemsize * k
                out[name] = (props, rows)
    vprops, v = out["vertex"]
    names = [p[-1] for p in vprops]
    if fmt == "ascii":
        v = np.array(v, dtype=float)
        col = lambda n: v[:, names.index(n)]  # noqa: E731
    else:
        col = lambda n: np.asarray(v[n], dtype=float)  # noqa: E731
    verts = np.stack([col("x"), col("y"), col("z")], axis=1)
    colors = None
    if "red" in names:
        colors = np.stack([col("red"), col("green"), col("blue")], axis=1)
        if colors.max() > 1.0:
            colors = colors / 255.0
    faces = out.get("face", (None, []))[1]
    if fmt == "ascii":
        faces = [np.array(r[0], dtype=int) for r in faces]
    tris = np.array([[f[0], f[i], f[i + 1]] for f in faces for i in range(1, len(f) - 1)], dtype=int)
    return verts, tris, colors


def read_obj_lines(path):
    """Points and polylines (`v` and `l` records) of an OBJ file, the
    polylines grouped by the object (`o` record) they belong to."""
    points, groups, name = [], {}, ""
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "o":
                name = " ".join(w[1:])
            elif w[0] == "v":
                points.append([float(x) for x in w[1:4]])
            elif w[0] == "l":
                idx = [int(x.split("/")[0]) for x in w[1:]]
                groups.setdefault(name, []).append([i - 1 if i > 0 else len(points) + i for i in idx])
    return np.array(points), groups


def render(mesh_path, out_path, lines_path=None, view=(15, -60), title=None):
    verts, tris, colors = read_ply(mesh_path)
    if colors is None:
        colors = np.full((len(verts), 3), 0.7)
    fig = plt.figure(figsize=(6, 6), dpi=120)
    ax = fig.add_subplot(projection="3d")
    tri_pts = verts[tris]
    normals = np.cross(tri_pts[:, 1] - tri_pts[:, 0], tri_pts[:, 2] - tri_pts[:, 0])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-30)
    elev, azim = np.radians(view[0]), np.radians(view[1])
    eye = np.array([np.cos(elev) * np.cos(azim), np.cos(elev) * np.sin(azim), np.sin(elev)])
    shade = 0.45 + 0.55 * np.abs(normals @ eye)  # two-sided Lambert
    face_colors = np.clip(colors[tris].mean(axis=1) * shade[:, None], 0, 1)
    # A graph or skeleton runs inside the volume (barycenters of level lines):
    # then the surface is drawn translucent and the lines on top of it.
    alpha = 0.35 if lines_path else 1.0
    ax.computed_zorder = False
    ax.add_collection3d(Poly3DCollection(tri_pts, facecolors=face_colors, edgecolors="none", linewidths=0,
                                         alpha=alpha, zorder=1))
    if lines_path:
        # `reeb graph --obj` writes the graph (object reeb_graph: node
        # immersions and edges) and its skeleton; the graph is drawn in red.
        points, groups = read_obj_lines(lines_path)
        for name, lines in groups.items():
            graph = name == "reeb_graph"
            segments = [points[[a, b]] for line in lines for a, b in zip(line[:-1], line[1:])]
            ax.add_collection3d(Line3DCollection(segments, colors="crimson" if graph else "black",
                                                 linewidths=2.2 if graph else 0.9, zorder=3 if graph else 2))
            if graph:
                used = sorted({i for line in lines for i in line})
                ax.scatter(*points[used].T, color="crimson", s=14, depthshade=False, zorder=4)
    lo, hi = verts.min(axis=0), verts.max(axis=0)
    center, radius = (lo + hi) / 2, (hi - lo).max() / 2
    for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), center):
        setter(c - radius, c + radius)
    ax.set_box_aspect((1, 1, 1), zoom=1.5)
    ax.view_init(elev=view[0], azim=view[1])
    ax.set_axis_off()
    if title:
        ax.set_title(title)
    fig.tight_layout()
    fig.savefig(out_path)
    plt.close(fig)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mesh")
    p.add_argument("out")
    p.add_argument("--lines")
    p.add_argument("--view", nargs=2, type=float, default=(15, -60), metavar=("ELEV", "AZIM"))
    p.add_argument("--title")
    a = p.parse_args(argv)
    render(a.mesh, a.out, a.lines, tuple(a.view), a.title)


if __name__ == "__main__":
    main(sys.argv[1:])
