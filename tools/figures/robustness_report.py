#!/usr/bin/env python3
"""The report of the robustness suite (experiments/robustness.sh): reads the
CSV tables that build/experiments/robustness wrote into WORK and writes
REPORT/report.md with its PNG plots. Each section states the claim of Tierny
et al. 2006, the measured number and whether it holds.

usage: robustness_report.py WORK REPORT
       robustness_report.py --compare WORK...

--compare prints, as one Markdown table, the figures issue 22 aims at for
each WORK folder that holds sections 2 and 3 (experiments/robustness.sh's,
experiments/robustness_probe.sh's, named with the options of the probe):
fast marching, the default method; then each folder against the first,
variant by variant, with bootstrap intervals of the differences.
"""
import csv
import platform
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

METHODS = ["dijkstra", "fmm"]

# Earlier defaults that robustness.sh measures again beside today's (the
# folder under the work directory, the two columns' names, what changed, why,
# and how the pose section names the earlier analysis).
EARLIER_DEFAULTS = [
    ("layout15", "no bound (layout 15)", "4 passes (today)",
     "the diameter search held to four full passes for its ends, f1 and f2 together (`--max-search-passes 4`, "
     "layout 16), against no bound (layouts 11-15: up to 9 passes on SHREC07, 4.165 on average)",
     "The bound makes the time of the search that of four passes on every mesh; which of several nearly tied "
     "pairs of ends a round or symmetric shape keeps moves with the sweeps either way, and the variant-by-variant "
     "differences below are within what another draw of the meshes could give (docs/results.md, \"A budget of "
     "search passes\")",
     "layout 15's diameter search (no bound on its passes)"),
    ("layout14", "midpoint (layout 14)", "tips (today)",
     "the feature points other than the diameter ends at the centre of the tips around their pair "
     "(`--feature-site tips`, layout 15), against halfway between the pair's two extrema (`--feature-site "
     "midpoint`, layouts 10-14)",
     "On a limb that ends in nearly tied tips (fingers, toes) the extremum, and the midpoint with it, moves to "
     "whichever tip a sampling or a pose makes the farthest; the centre of the tips does not",
     "layout 14's feature points (halfway between their two extrema)"),
    ("layout10", "from vertex 0 (layout 10)", "from the centroid (today)",
     "the diameter search started at the vertex farthest from the area centroid (`--diameter-start "
     "centroid`, layout 11), against the search from vertex 0 (`--diameter-start vertex`, layout 10), both "
     "under today's other defaults",
     "Vertex 0 lies wherever a file puts it, and the search from it ends on one or another of the nearly tied "
     "pairs of a symmetric shape; the vertex farthest from the centroid is the same point of the surface "
     "however it is numbered",
     "layout 10's diameter search (from vertex 0)"),
]

# Paper section 5.1: seconds on a 3 GHz Pentium 4 for 2k, 10k, 40k and 100k faces.
PAPER_SECONDS = {2000: 0.23, 10000: 2.0, 40000: 17.0, 100000: 86.0}


def read(path, delimiter=","):
    with open(path, newline="") as f:
        return list(csv.DictReader(f, delimiter=delimiter))


def pct(x):
    return f"{100.0 * x:.1f} %"


def holds(ok):
    return "**holds**" if ok else "**does not hold**"


def mean(values):
    values = list(values)
    return float(np.mean(values)) if values else float("nan")


def rigid_section(work, out):
    rows = read(work / "rigid.csv")
    n = len(rows)
    features = sum(int(r["same_features"]) for r in rows)
    graph = sum(int(r["same_graph"]) for r in rows)
    attributes = [float(r["max_attribute_difference"]) for r in rows if int(r["same_attribute_shape"])]
    within = sum(1 for a in attributes if a <= 1e-6)
    meshes = len({r["mesh"] for r in rows})
    failing = sorted({r["mesh"] for r in rows if not (int(r["same_features"]) and int(r["same_graph"]))})
    ok = features == n and graph == n and within == n
    out.append("## 1. Rigid transformations and scale\n")
    out.append("*Claim* (sections 4.1.1 and 5.3, \"affine invariance\"): geodesic distances normalized by the "
               "diameter make the feature points and the Reeb graph invariant to rotation, translation and uniform "
               "scaling (and reebkit's attributes, docs/method.md).\n")
    out.append(f"*Measured*: {meshes} SHREC07 meshes, {n // max(meshes, 1)} random similarities each (uniform "
               "rotation, scale 2^u, translation u x diagonal, u uniform in [-1, 1]; `random_similarity`), "
               "default options (fast marching): identical feature points (the same vertices; their selection order may differ where two "
               "candidates tie) "
               f"{features}/{n} ({pct(features / n)}), identical graph (edges and vertex labels) {graph}/{n}, every "
               f"attribute within 1e-6 {within}/{n} (largest difference {max(attributes, default=0):.2g}). "
               f"Aim 100 %: {holds(ok)}.\n")
    if failing:
        out.append(f"Meshes where a similarity changed the features or the graph ({len(failing)}): "
                   + ", ".join(failing[:20]) + (" ..." if len(failing) > 20 else "") +
                   ". Rounding flips a tie (two vertices at equal distance) in the diameter search or the "
                   "extrema.\n")


def sampling_rows(work, failed=False):
    """The rows of every sampling table; failed=True: only the variants that could not be analysed."""
    rows = []
    for path in sorted(work.glob("sampling_*.csv")):
        group = path.stem[len("sampling_"):]
        for r in read(path):
            if (int(r["rank"]) < 0) != failed:
                continue
            r["group"] = group
            rows.append(r)
    return rows


def three_or_more(rows):
    """The rows whose original has three or more feature points."""
    return [r for r in rows if int(r["features"]) > 2]


def two_points(rows):
    """The rows whose original has two feature points (the diameter ends alone)."""
    return [r for r in rows if int(r["features"]) <= 2]


def by_variant(rows):
    """The rows grouped by (perturbation, strength, geodesic method)."""
    groups = defaultdict(list)
    for r in rows:
        groups[(r["kind"], float(r["strength"]), r["method"])].append(r)
    return groups


def summarize(rows):
    n = len(rows)
    return {
        "n": n,
        "forward": mean(float(r["forward"]) for r in rows),
        "backward": mean(float(r["backward"]) for r in rows),
        "forward90": mean(float(r["forward"]) >= 0.9 for r in rows),
        "nodes": mean(r["nodes"] == r["variant_nodes"] for r in rows),
        "leaves": mean(r["leaves"] == r["variant_leaves"] for r in rows),
        "cycles": mean(r["cycles"] == r["variant_cycles"] for r in rows),
        "distance": mean(float(r["distance"]) for r in rows),
        "rank1": mean(int(r["rank"]) == 1 for r in rows),
    }


def sampling_section(work, report, out):
    rows = [r for r in sampling_rows(work) if r["kind"] != "pose"]
    groups = sorted({r["group"] for r in rows})
    out.append("## 2. Mesh sampling\n")
    out.append("*Claim* (section 4.1.2, figure 5, and section 5.3, figure 11): the feature points and the graph are "
               "robust to variations in mesh sampling.\n")
    out.append("Variants per mesh: decimation to 75/50/25 % of the vertices (quadric edge collapse, "
               "`decimate_mesh`), remeshing at 0.5x/1x/2x the vertex count (`remesh`: a new triangulation sharing "
               "no vertex), one midpoint subdivision (`subdivide_mesh`), Gaussian noise along the normals with "
               "sigma 0.1/0.25/0.5/1 % of the bounding box diagonal (`add_normal_noise`); every variant with its "
               "vertices numbered anew (a random permutation, as another file of the surface would number them; "
               "before 2026-11-28 the variants kept the original's numbering, which flattered a search that "
               "starts at vertex 0). Groups: "
               + ", ".join(f"{g} ({len({r['mesh'] for r in rows if r['group'] == g})} meshes)" for g in groups) +
               ". *Repeatability*: share of the original's feature points with a variant point within 0.05 x the "
               "diameter after mapping the variant's points to the original (forward), and the reverse "
               "(backward), fast-marching distances on the original. *Rank*: of the original when the variant "
               "queries the group's originals by graph matching (1 = found first).\n")
    failed = sampling_rows(work, failed=True)
    if failed:
        names = sorted({f"{r['mesh']} ({r['kind']} {float(r['strength']):g})" for r in failed})
        out.append(f"{len(names)} variants could not be analysed and are left out of the tables: " + ", ".join(names)
                   + " (the decimated mesh fell apart at a thin part; the analysis needs one connected piece).\n")
    out.append("| perturbation | strength | geodesic | variants | forward | backward | forward >= 90 % | same nodes "
               "| same leaves | same cycles | mean distance | rank 1 |")
    out.append("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    table = by_variant(rows)
    order = ["decimate", "remesh", "subdivide", "noise"]
    for key in sorted(table, key=lambda k: (order.index(k[0]), k[1], METHODS.index(k[2]))):
        s = summarize(table[key])
        out.append(f"| {key[0]} | {key[1]:g} | {key[2]} | {s['n']} | {pct(s['forward'])} | {pct(s['backward'])} | "
                   f"{pct(s['forward90'])} | {pct(s['nodes'])} | {pct(s['leaves'])} | {pct(s['cycles'])} | "
                   f"{s['distance']:.3f} | {pct(s['rank1'])} |")
    out.append("")
    out.append("Per group (all perturbations but the pose, both methods):\n")
    out.append("| group | geodesic | variants | forward | backward | same nodes | rank 1 |")
    out.append("|---|---|---:|---:|---:|---:|---:|")
    for g in groups:
        for m in METHODS:
            s = summarize([r for r in rows if r["group"] == g and r["method"] == m])
            out.append(f"| {g} | {m} | {s['n']} | {pct(s['forward'])} | {pct(s['backward'])} | {pct(s['nodes'])} | "
                       f"{pct(s['rank1'])} |")
    out.append("")

    fig, axes = plt.subplots(1, 4, figsize=(13, 3.2), sharey=True)
    for ax, kind in zip(axes, order):
        for m, style, color in zip(METHODS, ["o-", "s--"], ["C0", "C2"]):
            strengths = sorted({k[1] for k in table if k[0] == kind and k[2] == m})
            ax.plot(strengths, [summarize(table[(kind, x, m)])["forward"] for x in strengths], style, color=color,
                    label=f"{m} forward")
            ax.plot(strengths, [summarize(table[(kind, x, m)])["backward"] for x in strengths], style, color=color,
                    alpha=0.35, label=f"{m} backward")
        ax.set_title(kind)
        ax.set_xlabel({"decimate": "vertices kept", "remesh": "vertex count factor", "subdivide": "rounds",
                       "noise": "sigma / diagonal"}[kind])
        ax.axhline(0.9, color="grey", lw=0.5)
        ax.set_ylim(0, 1.02)
    axes[0].set_ylabel("feature-point repeatability")
    axes[-1].legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(report / "sampling_repeatability.png", dpi=80)
    plt.close(fig)
    out.append("![repeatability against the strength of each perturbation](sampling_repeatability.png)\n")

    def aim(kind, strength, method):
        return summarize(table[(kind, strength, method)])
    lines = []
    for m in METHODS:
        d, r1 = aim("decimate", 0.5, m), aim("remesh", 1.0, m)
        remeshed = summarize([r for k, v in table.items() if k[0] == "remesh" and k[2] == m for r in v])
        d3 = summarize(three_or_more(table[("decimate", 0.5, m)]))["forward"]
        r3 = summarize(three_or_more(table[("remesh", 1.0, m)]))["forward"]
        lines.append(f"- {m}: repeatability at 50 % decimation {pct(d['forward'])} (aim >= 90 %: "
                     f"{holds(d['forward'] >= 0.9)}), at 1x remeshing {pct(r1['forward'])} "
                     f"({holds(r1['forward'] >= 0.9)}); on the meshes with three or more feature points "
                     f"{pct(d3)} / {pct(r3)} (aim >= 97 %: {holds(min(d3, r3) >= 0.97)}); node count unchanged on "
                     f"{pct(remeshed['nodes'])} of the remeshed variants (aim >= 80 %: "
                     f"{holds(remeshed['nodes'] >= 0.8)}).")
    out.append("*Aims*:\n\n" + "\n".join(lines) + "\n")

    out.append("*Why, from the data*: the variants below 90 % split by the original's number of feature points. With "
               "two, the feature points are the diameter ends only (eqs. 2-4): on a shape without protrusions (SHREC07 "
               "busts, bearings, mechanical parts, round CGAL parts) many pairs of vertices are nearly as far apart, "
               "and a new sampling moves the ends anywhere along that ridge. With three or more, a missing or extra "
               "extremum (persistence near the threshold, two extrema near epsilon) changes the count, and the node "
               "count with it (one leaf per feature point reached by its own level line).\n")
    out.append("| perturbation | geodesic | originals | variants | forward | same feature count | same nodes | "
               "rank 1 |")
    out.append("|---|---|---|---:|---:|---:|---:|---:|")
    ceilings = []  # the all-variant repeatability were every variant of three or more points perfect
    for kind, strength in [("decimate", 0.5), ("remesh", 1.0)]:
        for m in METHODS:
            rs = table[(kind, strength, m)]
            two = two_points(rs)
            for name, part in [("2 points", two), ("3 or more", three_or_more(rs))]:
                s = summarize(part)
                same = mean(r["features"] == r["variant_features"] for r in part)
                out.append(f"| {kind} {strength:g} | {m} | {name} | {s['n']} | {pct(s['forward'])} | {pct(same)} | "
                           f"{pct(s['nodes'])} | {pct(s['rank1'])} |")
            best = (sum(float(r["forward"]) for r in two) + len(rs) - len(two)) / len(rs)
            ceilings.append(f"{kind} {strength:g}, {m}: {len(two)} of {len(rs)} variants, at most {pct(best)}")
    out.append("")
    out.append("*The ceiling the two-point shapes set*: the variants of originals with two feature points, and the "
               "repeatability over all variants if every variant with three or more were perfect and these stayed "
               "as measured: " + "; ".join(ceilings) + ".\n")
    out.append("*What is recoverable on shapes with two feature points*: their feature "
               "count is kept (the two diameter ends), and so, mostly, is their graph (same nodes above): the "
               "structure of a shape without protrusions is recovered. What is not is where its two points lie: "
               "along a ridge of nearly equally distant pairs the ends move with the sampling (forward above), the "
               "level lines of f_q move with them, and so do the attributes of the regions: the rank of the "
               "original when the variant queries its group (rank 1 above) is where these shapes lose, not the "
               "graph. No selection rule can pin a diameter end that the surface itself does not single out; the "
               "retrieval of these shapes rests on the whole-surface terms of the matching (g_s, g_g: "
               "docs/method.md), which do not depend on the ends.\n")
    for folder, old_name, new_name, what, why, _ in EARLIER_DEFAULTS:
        earlier = [r for r in sampling_rows(work / folder) if r["kind"] != "pose"]
        if not earlier:
            continue
        out.append(f"*Old and new*: {what}; both with fast marching on the same variants, each numbered anew. "
                   f"{why}.\n")
        out.append(f"| perturbation | originals | {old_name}: forward | same nodes | {new_name}: forward | same nodes |")
        out.append("|---|---|---:|---:|---:|---:|")
        old = by_variant(earlier)
        for kind, strength in [("decimate", 0.5), ("remesh", 1.0)]:
            for name, pick in [("all", lambda rs: rs), ("3 or more", three_or_more)]:
                a, b = summarize(pick(old[(kind, strength, "fmm")])), summarize(pick(table[(kind, strength, "fmm")]))
                out.append(f"| {kind} {strength:g} | {name} | {pct(a['forward'])} | {pct(a['nodes'])} | "
                           f"{pct(b['forward'])} | {pct(b['nodes'])} |")
        a = summarize([r for r in earlier if r["method"] == "fmm"])
        b = summarize([r for r in rows if r["method"] == "fmm"])
        out.append(f"| every perturbation | all | {pct(a['forward'])} | {pct(a['nodes'])} | {pct(b['forward'])} | "
                   f"{pct(b['nodes'])} |")
        cells = paired_cells(work / folder, work, np.random.default_rng(0))
        out.append("\nToday against the old, variant by variant, in points (variants gaining / losing; 95 % bootstrap "
                   "interval over the variants; repeatability unless said): " +
                   "; ".join(f"{name} {cell}" for (name, *_), cell in zip(PAIRED_FIGURES, cells)) + ".")
        out.append("")


def mode_share(rows, method):
    """Share of the TOSCA poses (the first of each class included) whose node
    count is the most common one of their class: a measure that does not
    depend on which pose comes first."""
    kept = total = 0
    for c in sorted({r["class"] for r in rows}):
        rs = [r for r in rows if r["class"] == c and r["method"] == method]
        if not rs:
            continue
        counts = [rs[0]["reference_nodes"]] + [r["nodes"] for r in rs]
        common = max(sorted(set(counts)), key=counts.count)
        kept += counts.count(common)
        total += len(counts)
    return kept / total if total else float("nan")


def pose_section(work, report, out):
    rows = read(work / "tosca_poses.csv")
    pairs = read(work / "tosca_pairs.csv")
    out.append("## 3. Pose\n")
    out.append("*Claim* (section 4.1.1 and section 5.3, figures 9(c), 9(d)): geodesic distances make the feature "
               "points and the graph robust to model pose.\n")
    out.append("TOSCA (54 meshes, 5 classes): each pose against the first pose of its class (same triangulation, "
               "vertex i corresponds; each pose analysed with its vertices numbered anew, its points mapped back), "
               "repeatability as in section 2 on the first pose.\n")
    out.append("| class | geodesic | poses | forward | backward | same nodes | same leaves | distance within | "
               "distance across |")
    out.append("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    classes = sorted({r["class"] for r in rows})
    for c in classes:
        for m in METHODS:
            rs = [r for r in rows if r["class"] == c and r["method"] == m]
            within = [float(p["distance"]) for p in pairs if p["method"] == m and p["class_a"] == c == p["class_b"]]
            across = [float(p["distance"]) for p in pairs if p["method"] == m and (p["class_a"] == c) != (p["class_b"] == c)]
            out.append(f"| {c} | {m} | {len(rs) + 1} | {pct(mean(float(r['forward']) for r in rs))} | "
                       f"{pct(mean(float(r['backward']) for r in rs))} | "
                       f"{pct(mean(r['nodes'] == r['reference_nodes'] for r in rs))} | "
                       f"{pct(mean(r['leaves'] == r['reference_leaves'] for r in rs))} | {mean(within):.3f} | "
                       f"{mean(across):.3f} |")
    out.append("")
    lines = []
    earlier = [(f" with {pose}", work / folder / "tosca_poses.csv") for folder, *_, pose in EARLIER_DEFAULTS]
    # Layout 8 is measured under pose alone.
    earlier.append((" with layout 8's feature points (epsilon 0.05, persistence 0.01, on the extrema)",
                    work / "layout8" / "tosca_poses.csv"))
    for name, table in [("", rows)] + [(n, read(p)) for n, p in earlier if p.exists()]:
        for m in METHODS:
            rs = [r for r in table if r["method"] == m]
            f = mean(float(r["forward"]) for r in rs)
            lines.append(f"- {m}{name}: repeatability between TOSCA poses {pct(f)} (aim >= 90 %: {holds(f >= 0.9)}); "
                         f"node count unchanged on {pct(mean(r['nodes'] == r['reference_nodes'] for r in rs))} of "
                         f"the poses against the first pose, on {pct(mode_share(table, m))} against the count most "
                         "common in the class (every pose counted, the first too).")
    shrec_pose = [r for r in sampling_rows(work) if r["kind"] == "pose"]
    if shrec_pose:
        out.append("`--pose` variants (two leaf components turned by 20-35 degrees, `random_pose`, seeds 1 and 2; "
                   "numbered anew like the other variants):\n")
        out.append("| group | geodesic | variants | forward | backward | same nodes | mean distance | rank 1 |")
        out.append("|---|---|---:|---:|---:|---:|---:|---:|")
        for g in sorted({r["group"] for r in shrec_pose}):
            for m in METHODS:
                s = summarize([r for r in shrec_pose if r["group"] == g and r["method"] == m])
                out.append(f"| {g} | {m} | {s['n']} | {pct(s['forward'])} | {pct(s['backward'])} | {pct(s['nodes'])} | "
                           f"{s['distance']:.3f} | {pct(s['rank1'])} |")
        out.append("")
    out.append("*Aims*:\n\n" + "\n".join(lines) + "\n")

    fig, ax = plt.subplots(figsize=(6, 3))
    data, labels = [], []
    for m in METHODS:
        data.append([float(p["distance"]) for p in pairs if p["method"] == m and p["class_a"] == p["class_b"]])
        data.append([float(p["distance"]) for p in pairs if p["method"] == m and p["class_a"] != p["class_b"]])
        labels += [f"{m}\nwithin", f"{m}\nacross"]
    ax.boxplot(data, labels=labels)
    ax.set_ylabel("graph distance")
    ax.set_title("TOSCA: graph distance between poses")
    fig.tight_layout()
    fig.savefig(report / "tosca_distances.png", dpi=80)
    plt.close(fig)
    out.append("![TOSCA graph distances within and across classes](tosca_distances.png)\n")


def class_of(mesh):
    return mesh.split("/")[0]


def classes_section(work, report, out):
    meshes = read(work / "shrec_meshes.csv")
    pairs = read(work / "shrec_pairs.csv")
    labels = [class_of(r["mesh"]) for r in meshes]
    classes = sorted(set(labels), key=labels.index)
    within, across = [], []
    for p in pairs:
        (within if labels[int(p["a"])] == labels[int(p["b"])] else across).append(float(p["distance"]))
    out.append("## 4. Stability within a class\n")
    out.append("*Claim* (section 5.3, \"stability of the high level description\", figure 9): the graphs of models "
               "of one class are quite similar.\n")
    w, a = np.median(within), np.median(across)
    share = mean(x < a for x in within)
    out.append(f"*Measured* on all {len(meshes)} SHREC07 meshes (default options: fast marching): median graph distance "
               f"within a class {w:.3f}, across classes {a:.3f}; {pct(share)} of the within-class pairs are nearer "
               f"than the median across-class pair: {holds(w < a)} (as an ordering; retrieval figures in "
               "results/shrec07/report.md).\n")
    out.append("| class | meshes | nodes (min / median / max) | leaves (median) | feature points, fmm (default) / Dijkstra "
               "(median) | median distance within |")
    out.append("|---|---:|---|---:|---|---:|")
    for c in classes:
        rs = [r for r in meshes if class_of(r["mesh"]) == c]
        idx = {i for i, lab in enumerate(labels) if lab == c}
        cw = [float(p["distance"]) for p in pairs if int(p["a"]) in idx and int(p["b"]) in idx]
        nodes = [int(r["nodes"]) for r in rs]
        out.append(f"| {c} | {len(rs)} | {min(nodes)} / {int(np.median(nodes))} / {max(nodes)} | "
                   f"{int(np.median([int(r['leaves']) for r in rs]))} | "
                   f"{np.median([int(r['features']) for r in rs]):g} / {np.median([int(r['features_dijkstra']) for r in rs]):g} | "
                   f"{np.median(cw):.3f} |")
    out.append("")
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 3.4), gridspec_kw={"width_ratios": [4, 1]})
    ax1.boxplot([[int(r["nodes"]) for r in meshes if class_of(r["mesh"]) == c] for c in classes], labels=classes)
    ax1.set_ylabel("Reeb graph nodes")
    ax1.tick_params(axis="x", rotation=60, labelsize=7)
    ax2.boxplot([within, across], labels=["within", "across"])
    ax2.set_ylabel("graph distance")
    fig.tight_layout()
    fig.savefig(report / "shrec07_classes.png", dpi=80)
    plt.close(fig)
    out.append("![SHREC07: node counts per class; graph distances within and across classes](shrec07_classes.png)\n")


def handpicked_section(work, out):
    meshes = read(work / "shrec_meshes.csv")
    out.append("## 5. Feature points against the hand-picked points of SHREC07\n")
    out.append("*Claim* (section 4.1.2, figure 5): the feature points lie at the extremities of the prominent "
               "components. SHREC07's `features/*.vts` hold hand-picked points (extremities, and others). "
               "Precision: share of our feature points (default options: fast marching) with a hand-picked point within r "
               "x the diameter (fast-marching distance); recall: the reverse.\n")
    out.append("| class | meshes with points | precision 0.05 | recall 0.05 | precision 0.10 | recall 0.10 |")
    out.append("|---|---:|---:|---:|---:|---:|")
    labels = [class_of(r["mesh"]) for r in meshes]
    for c in sorted(set(labels), key=labels.index) + ["all"]:
        rs = [r for r in meshes if (c == "all" or class_of(r["mesh"]) == c) and int(r["handpicked"]) > 0]
        cells = [pct(mean(float(r[k]) for r in rs)) if rs else "-" for k in
                 ("precision05", "recall05", "precision10", "recall10")]
        out.append(f"| {c} | {len(rs)} | " + " | ".join(cells) + " |")
    out.append("")


def timing_section(work, out):
    rows = read(work / "timing.csv")
    out.append("## 6. Timing\n")
    out.append("*Paper* (section 5.1): 0.23, 2, 17 and 86 s for 2k, 10k, 40k and 100k faces on a 3 GHz Pentium 4 "
               "(the Reeb graph rebuilt per step). Here: TOSCA michael0 decimated to each size (quadric edge "
               "collapse), the whole analysis (mesh graph, feature points, f_q, Reeb graph), median of 3 runs, one "
               f"thread, {platform.processor() or platform.machine()}, {cpu_name()}, shared with other builds.\n")
    out.append("| faces | vertices | paper | Dijkstra | fast marching |")
    out.append("|---:|---:|---:|---:|---:|")
    by = defaultdict(dict)
    for r in rows:
        by[int(r["target_faces"])][r["method"]] = r
    for target in sorted(by):
        d, f = by[target]["dijkstra"], by[target]["fmm"]
        out.append(f"| {d['faces']} | {d['vertices']} | {PAPER_SECONDS.get(target, float('nan')):g} s | "
                   f"{float(d['total_ms']):.1f} ms | {float(f['total_ms']):.1f} ms |")
    out.append("")


def cpu_name():
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def compare(folders):
    """The Markdown table of robustness_report.py --compare."""
    out = ["| folder | 50 % decimation: all / 3+ points / 2 points / same nodes | 1x remeshing: the same | "
           "noise 0.25 %: all / same nodes | TOSCA poses: forward / same nodes as the first / as the class's "
           "most common |",
           "|---|---|---|---|---|"]
    for work in folders:
        groups = by_variant(sampling_rows(work))
        options = work / "options"  # robustness_probe.sh's, empty for today's defaults
        text = options.read_text().strip() if options.exists() else ""
        cells = [work.name + (f" (`{text}`)" if text else "")]
        for kind, strength, detailed in (("decimate", 0.5, True), ("remesh", 1.0, True), ("noise", 0.0025, False)):
            rows = groups.get((kind, strength, "fmm"), [])
            if not rows:
                cells.append("-")
                continue
            every = summarize(rows)
            parts = [every["forward"]]
            if detailed:
                parts += [summarize(three_or_more(rows))["forward"],
                          summarize(two_points(rows))["forward"]]
            cells.append(" / ".join(pct(x) if x == x else "-" for x in parts + [every["nodes"]]) +
                         f" ({every['n']})")  # "-": no such mesh
        poses = [r for r in read(work / "tosca_poses.csv") if r["method"] == "fmm"]
        cells.append(" / ".join(pct(x) for x in (mean(float(r["forward"]) for r in poses),
                                                 mean(r["nodes"] == r["reference_nodes"] for r in poses),
                                                 mode_share(poses, "fmm"))))
        out.append("| " + " | ".join(cells) + " |")
    if len(folders) > 1:
        out += ["", paired_table(folders)]
    return "\n".join(out)


# The figures paired_table compares: (name, perturbation, strength, the per-variant value).
PAIRED_FIGURES = [
    ("50 % decimation", "decimate", 0.5, lambda r: float(r["forward"])),
    ("1x remeshing", "remesh", 1.0, lambda r: float(r["forward"])),
    ("noise 0.25 %", "noise", 0.0025, lambda r: float(r["forward"])),
    ("same nodes, 1x remeshing", "remesh", 1.0, lambda r: float(r["nodes"] == r["variant_nodes"])),
]


def paired_difference(a, b, rng, draws=10000):
    """Mean of b - a over the variants both hold (dicts variant -> value), the
    variants where b is higher and lower, and a 95 % bootstrap interval of the
    mean (the variants resampled)."""
    keys = sorted(set(a) & set(b))
    d = np.array([b[k] - a[k] for k in keys])
    if not len(d):
        return None
    means = d[rng.integers(0, len(d), size=(draws, len(d)))].mean(axis=1)
    return d.mean(), int((d > 0).sum()), int((d < 0).sum()), np.percentile(means, [2.5, 97.5])


def paired_cells(base, other, rng):
    """One cell per PAIRED_FIGURES: folder `other` against folder `base`,
    variant by variant (fast marching), the difference in points, the
    variants gaining and losing, and its 95 % interval when the variants are
    resampled. A difference whose interval holds 0 is within what another
    draw of meshes could give."""
    base_rows, other_rows = ([r for r in sampling_rows(work) if r["method"] == "fmm"] for work in (base, other))

    def values(rows, kind, strength, value):
        return {(r["group"], r["mesh"]): value(r) for r in rows
                if r["kind"] == kind and float(r["strength"]) == strength}

    cells = []
    for _, kind, strength, value in PAIRED_FIGURES:
        r = paired_difference(values(base_rows, kind, strength, value), values(other_rows, kind, strength, value),
                              rng)
        cells.append("-" if r is None else
                     f"{100 * r[0]:+.1f} ({r[1]} / {r[2]}; {100 * r[3][0]:+.1f} to {100 * r[3][1]:+.1f})")
    return cells


def paired_table(folders):
    """Each folder against the first (paired_cells), as a Markdown table."""
    rng = np.random.default_rng(0)
    out = [f"Against {folders[0].name}, variant by variant: difference in points (variants gaining / losing; 95 % "
           "bootstrap interval)\n",
           "| folder | " + " | ".join(name for name, *_ in PAIRED_FIGURES) + " |",
           "|---|" + "---|" * len(PAIRED_FIGURES)]
    for work in folders[1:]:
        out.append("| " + " | ".join([work.name] + paired_cells(folders[0], work, rng)) + " |")
    return "\n".join(out)


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "--compare":
        print(compare([Path(a) for a in sys.argv[2:]]))
        return
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    work, report = Path(sys.argv[1]), Path(sys.argv[2])
    report.mkdir(parents=True, exist_ok=True)
    steps = read(work / "steps.tsv", "\t")
    total = next((int(s["seconds"]) for s in steps if s["step"] == "total"), None)
    # The commit that measured (robustness.sh writes it), not the one that writes the report.
    commit = (work / "commit").read_text().strip() if (work / "commit").exists() else "?"
    out = ["# Robustness: the invariance claims of Tierny et al. 2006, measured\n",
           f"`experiments/robustness.sh build` (commit {commit}; measurements `experiments/robustness.cpp`, this "
           f"report `tools/figures/robustness_report.py`). The measurements took {total} s on "
           f"{cpu_name()} with 2 threads (the build not counted):\n"]
    out += [f"- {s['step']}: {s['seconds']} s" for s in steps if s["step"] not in ("total", "report and plots")] + [""]
    out.append("Defaults (docs/method.md): geodesic distances by fast marching (`fmm`, the diameter search "
               "too), epsilon 0.15 and persistence filter 0.03 (one "
               "feature point per limb; the paper's 0.05 and reebkit's 0.01 before layout 9: docs/results.md, "
               "\"Feature points at the scale of a limb\", compares them), each feature point other than the diameter "
               "ends at the centre of the tips around the pair of extrema that eq. (6) joins (`--feature-site tips`; "
               "halfway between the pair in layouts 10-14, on the extremum before: sections 2 and 3 compare them), "
               "the diameter search started at the vertex farthest from the area centroid "
               "(`--diameter-start centroid`; from vertex 0 before layout 11: sections 2 and 3 compare them), up to "
               "3 extra sweeps, at most 4 full passes for the diameter ends, f1 and f2 together "
               "(`--max-search-passes 4`; no bound before layout 16: sections 2 and 3 compare them), "
               "leaves only at the maxima of f_q (`--leaves maxima`: the pits of the propagation "
               "cancelled; docs/results.md, \"Leaves at the maxima of f_q\", compares it with `propagation`). "
               "Dijkstra (`dijkstra`), the paper's method and reebkit's default before layout 7, is measured beside "
               "it in sections 2, 3 and 6: old and new side by side.\n")
    rigid_section(work, out)
    sampling_section(work, report, out)
    pose_section(work, report, out)
    classes_section(work, report, out)
    handpicked_section(work, out)
    timing_section(work, out)
    (report / "report.md").write_text("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
