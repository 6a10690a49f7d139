#!/usr/bin/env python3
"""robustness_report.py --compare on tables whose figures are known: two work
folders of made-up sampling and pose rows (probes, the first without
options, the second with), the printed tables checked cell by cell (the fast-marching rows
only, failed variants left out): the figures of each folder, then the second
against the first, variant by variant.

usage: robustness_compare_test.py SOURCE_DIR
"""
import csv
import subprocess
import sys
import tempfile
from pathlib import Path

SAMPLING = ["mesh", "method", "kind", "strength", "vertices", "variant_vertices", "features", "variant_features",
            "forward", "backward", "nodes", "variant_nodes", "leaves", "variant_leaves", "cycles", "variant_cycles",
            "distance", "rank", "seconds"]
POSES = ["mesh", "class", "reference", "method", "features", "reference_features", "forward", "backward", "nodes",
         "reference_nodes", "leaves", "reference_leaves", "distance"]


def write(path, fields, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "0") for k in fields})


def sample(mesh, kind, strength, features, forward, same_nodes, method="fmm", rank="1"):
    return {"mesh": mesh, "method": method, "kind": kind, "strength": strength, "features": features,
            "forward": forward, "nodes": "5", "variant_nodes": "5" if same_nodes else "7", "rank": rank}


def main():
    script = Path(sys.argv[1]) / "tools" / "figures" / "robustness_report.py"
    with tempfile.TemporaryDirectory() as tmp:
        a, b = Path(tmp) / "a", Path(tmp) / "b"
        for work in (a, b):
            work.mkdir()
        write(a / "sampling_x.csv", SAMPLING, [
            # 50 % decimation: a 3-point mesh at 1, a 2-point one at 0.5; nodes kept on one.
            sample("m1", "decimate", "0.5", "3", "1.0000", True),
            sample("m2", "decimate", "0.5", "2", "0.5000", False),
            sample("m2", "decimate", "0.5", "2", "0.0000", False, method="dijkstra"),  # not fast marching
            sample("m3", "decimate", "0.5", "2", "0.0000", False, rank="-1"),  # could not be analysed
            # 1x remeshing: two 4-point meshes at 0.75 and 0.25, nodes kept on both.
            sample("m1", "remesh", "1", "4", "0.7500", True),
            sample("m2", "remesh", "1", "4", "0.2500", True),
            sample("m1", "noise", "0.0025", "3", "0.9000", True),
        ])
        write(a / "tosca_poses.csv", POSES, [
            {"mesh": "cat1", "class": "cat", "reference": "cat0", "method": "fmm", "forward": "1.0",
             "nodes": "11", "reference_nodes": "11"},
            {"mesh": "cat2", "class": "cat", "reference": "cat0", "method": "fmm", "forward": "0.5",
             "nodes": "13", "reference_nodes": "11"},
            {"mesh": "cat3", "class": "cat", "reference": "cat0", "method": "fmm", "forward": "0.0",
             "nodes": "13", "reference_nodes": "11"},
            {"mesh": "cat1", "class": "cat", "reference": "cat0", "method": "dijkstra", "forward": "0.0",
             "nodes": "9", "reference_nodes": "11"},
        ])
        (a / "options").write_text("\n")  # a probe of today's defaults: named alone
        (b / "options").write_text("--option epsilon=0.2\n")
        # The same group and mesh as a's first remeshing row: paired with it.
        write(b / "sampling_x.csv", SAMPLING, [sample("m1", "remesh", "1", "2", "1.0000", False)])
        write(b / "tosca_poses.csv", POSES, [
            {"mesh": "dog1", "class": "dog", "reference": "dog0", "method": "fmm", "forward": "1.0",
             "nodes": "9", "reference_nodes": "9"}])
        # /usr/bin/python3, as the experiment scripts run it (Debian's matplotlib).
        table = subprocess.run(["/usr/bin/python3", str(script), "--compare", str(a), str(b)], check=True,
                               capture_output=True, text=True).stdout.strip().splitlines()
    expected = [
        # decimation: all (1 + 0.5) / 2, 3+ 1, 2 points 0.5, nodes 1 of 2; remeshing: 0.5, 0.5, no
        # 2-point mesh (-), nodes 2 of 2; noise 0.9, 1 of 1; poses: forward 0.5, 1 of 3 as the
        # first, the class's most common count (13, with the first pose's 11: 2 of 4).
        "| a | 75.0 % / 100.0 % / 50.0 % / 50.0 % (2) | 50.0 % / 50.0 % / - / 100.0 % (2) | "
        "90.0 % / 100.0 % (1) | 50.0 % / 33.3 % / 50.0 % |",
        "| b (`--option epsilon=0.2`) | - | 100.0 % / - / 100.0 % / 0.0 % (1) | - | 100.0 % / 100.0 % / 100.0 % |",
        "",
        "Against a, variant by variant: difference in points (variants gaining / losing; 95 % bootstrap interval)",
        "",
        "| folder | 50 % decimation | 1x remeshing | noise 0.25 % | same nodes, 1x remeshing |",
        "|---|---|---|---|---|",
        # m1 remeshed: 0.75 -> 1 (+25 points), its node count kept -> not (-100); one pair, so every
        # resampling gives the same mean; b has no decimated or noisy variant.
        "| b | - | +25.0 (1 / 0; +25.0 to +25.0) | - | -100.0 (0 / 1; -100.0 to -100.0) |",
    ]
    if table[2:] != expected:
        print("got:\n" + "\n".join(table) + "\nexpected:\n" + "\n".join(expected))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
