#!/usr/bin/env python3
"""The Python module's call overhead: reebkit.reeb_graph(V, F) against the same
C++ call (python/mesh_arrays.h: mesh_from_arrays + graph_of) on a torus of
100,000 faces, timed by build/bench/python_overhead_bench.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py build [ROUNDS]

Each round runs 5 calls on each side, alternating, so that both see the same
load; prints the median of every side and the overhead (target <= 5 %).
"""
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import reebkit

RUNS = 5


def main():
    build = pathlib.Path(sys.argv[1])
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    helper = build / "bench" / "python_overhead_bench"
    cpp, python = [], []
    with tempfile.TemporaryDirectory() as scratch:
        mesh = pathlib.Path(scratch) / "torus.off"
        for _ in range(rounds):
            out = subprocess.run([helper, mesh, str(RUNS)], capture_output=True, text=True, check=True).stdout
            cpp += [float(line) for line in out.split()]
            V, F = reebkit.load_mesh(mesh)
            for _ in range(RUNS):
                start = time.perf_counter()
                reebkit.reeb_graph(V, F)
                python.append(1000 * (time.perf_counter() - start))
    c, p = statistics.median(cpp), statistics.median(python)
    print(f"torus: {len(V)} vertices, {len(F)} faces; {len(cpp)} calls a side")
    print(f"C++    graph_of(mesh_from_arrays(V, F)): median {c:.1f} ms (min {min(cpp):.1f})")
    print(f"Python reebkit.reeb_graph(V, F):         median {p:.1f} ms (min {min(python):.1f})")
    print(f"overhead: {100 * (p - c) / c:+.1f} % of the median, {100 * (min(python) - min(cpp)) / min(cpp):+.1f} % of the min")


if __name__ == "__main__":
    main()
