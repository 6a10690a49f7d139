#!/usr/bin/env python3
"""reebkit from Python, as in a notebook: one mesh's f_q and Reeb graph
plotted with matplotlib, then a query against a classified collection and
the retrieval report of its all-pairs distances (docs/python.md).

    PYTHONPATH=build/python /usr/bin/python3 experiments/python_example.py \
        [--build build] [--mesh datasets/elk.off] [--collection C.h5] [-o results/local/python_example.png]

Without --collection, the collection of `bash tools/run demo` is made in
results/local/python_example/ by `reeb variants datasets/*.off` (each mesh and
5 variants, one class per mesh) and `reeb index --classes`.
"""
import argparse
import pathlib
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import reebkit  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]


def make_collection(build, folder):
    """datasets/*.off and their variants, indexed with their classes."""
    reeb = str(build / "tools" / "reeb")
    meshes = sorted(map(str, (ROOT / "datasets").glob("*.off")))
    subprocess.run([reeb, "variants", *meshes, "-o", folder / "meshes"], check=True, stdout=subprocess.DEVNULL)
    path = folder / "collection.h5"
    subprocess.run([reeb, "index", folder / "meshes", "-o", path, "--classes", folder / "meshes" / "variants.cla"],
                   check=True, stdout=subprocess.DEVNULL)
    return path


def plot(V, F, g, title, output):
    """f_q with the feature points (left), the segmentation with the graph and its skeleton (right)."""
    fig = plt.figure(figsize=(12, 6))
    left = fig.add_subplot(1, 2, 1, projection="3d")
    surface = left.plot_trisurf(*V.T, triangles=F, cmap="viridis", linewidth=0, antialiased=False)
    surface.set_array(g.fq[F].mean(axis=1))  # f_q per face: the mean of its corners
    left.scatter(*V[g.feature_points].T, color="red", s=40, depthshade=False)
    left.set_title(f"{title}: f_q and {len(g.feature_points)} feature points")
    fig.colorbar(surface, ax=left, shrink=0.6, label="f_q")

    right = fig.add_subplot(1, 2, 2, projection="3d")
    segments = right.plot_trisurf(*V.T, triangles=F, cmap="tab20", linewidth=0, antialiased=False, alpha=0.35)
    segments.set_array(g.vertex_node[F[:, 0]] % 20)
    barycenter = g.nodes["barycenter"]
    for a, b in g.edges:
        right.plot(*barycenter[[a, b]].T, color="red", linewidth=2)
    right.scatter(*barycenter.T, color="red", s=30, depthshade=False)
    for points in g.skeleton:
        right.plot(*points.T, color="black", linewidth=1)
    right.set_title(f"{g.num_nodes} nodes, {len(g.edges)} edges, {g.cycles} cycles")
    for axes in (left, right):
        axes.set_box_aspect(np.ptp(V, axis=0))
        axes.set_axis_off()
    output.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(output, dpi=100, bbox_inches="tight")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--mesh", type=pathlib.Path, default=ROOT / "datasets" / "elk.off")
    parser.add_argument("--collection", type=pathlib.Path)
    parser.add_argument("-o", "--output", type=pathlib.Path, default=ROOT / "results" / "local" / "python_example.png")
    args = parser.parse_args()

    # One mesh: arrays in, arrays out.
    V, F = reebkit.load_mesh(args.mesh)
    g = reebkit.reeb_graph(V, F)
    types = [reebkit.NODE_TYPES[t] for t in g.nodes["type"]]
    print(f"{args.mesh.name}: V {V.shape}, F {F.shape}; {g}")
    print(f"  node types: { {t: types.count(t) for t in reebkit.NODE_TYPES if t in types} }, leaves {g.leaves}")
    plot(V, F, g, args.mesh.stem, args.output)
    print(f"wrote {args.output}")

    # A collection: query by example, then all pairs and the PSB measures.
    path = args.collection or make_collection(args.build, ROOT / "results" / "local" / "python_example")
    collection = reebkit.Collection(path)
    print(f"\n{collection}, indexed with {collection.analysis_options}")
    print(f"query {args.mesh.name} (analysed with the collection's options):")
    for r in collection.query((V, F), k=6):
        print(f"  {r['rank']}  {r['distance']:.4f}  {r['class'] or '-':<10} {r['name']}")
    distances = collection.distances()
    report = reebkit.evaluate(distances, collection.classes)
    print(f"\nretrieval on {len(collection)} meshes ({report['queries']} queries):")
    print("            NN     FT     ST     E      DCG")
    for name, scores in (("micro", report), ("macro", report["macro"])):
        print(f"  {name:<8}" + "".join(f"{scores[m]:7.3f}" for m in ("NN", "FT", "ST", "E", "DCG")))
    for name, scores in report["classes"].items():
        print(f"  {name:<8}" + "".join(f"{scores[m]:7.3f}" for m in ("NN", "FT", "ST", "E", "DCG")))


if __name__ == "__main__":
    main()
