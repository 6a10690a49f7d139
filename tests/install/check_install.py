#!/usr/bin/env python3
"""reebkit as others use it: installed by `cmake --install`, built on with
find_package(reebkit) or pkg-config (docs/install.md). Run by ctest:

  check_install.py install BUILD PREFIX
      cmake --install BUILD --prefix PREFIX, into an emptied PREFIX.
  check_install.py headers SOURCE PREFIX
      The installed headers are exactly those examples/ and python/ include,
      with what they include: none missing, none private, and no header of
      a dependency but Eigen's (the others stay inside the libraries).
  check_install.py example SOURCE PREFIX WORK BUILD --cxx CXX [--cxxflags F]
                   [--ldflags F] [CMAKE_ARGS...]
      examples/ built in WORK against PREFIX with find_package and with
      pkg-config, never seeing the source or build tree (BUILD); both
      programs' graph and query results equal those of the installed
      `reeb graph` and `reeb query`.
  check_install.py pip SOURCE WORK REEB [BUILD]
      `pip install ./python` into a new virtual environment in WORK (Debian's
      python3, --system-site-packages for numpy, nothing downloaded), BUILD's
      module packaged when given (setup.py's REEBKIT_BUILD_DIR), else built
      from scratch; then, from another folder, `import reebkit` finds the
      installed module and its graph equals `REEB graph`'s.
"""
import argparse
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.MULTILINE)
MESH = "elk.off"
K = 5


def run(*args, **kwargs):
    print("$", " ".join(map(str, args)), flush=True)
    return subprocess.run([str(a) for a in args], check=True, text=True, **kwargs)


def install(build, prefix):
    shutil.rmtree(prefix, ignore_errors=True)
    run(os.environ.get("CMAKE", "cmake"), "--install", build, "--prefix", prefix)


def reebkit_includes(path):
    return {h for h in INCLUDE.findall(Path(path).read_text()) if h.startswith("reebkit/")}


def headers(source, prefix):
    include = Path(prefix) / "include"
    installed = {str(p.relative_to(include)) for p in include.rglob("*.h")}
    seeds = {}
    for folder in ("examples", "python"):
        for path in sorted((Path(source) / folder).glob("*.[hc]*")):
            for h in reebkit_includes(path):
                seeds.setdefault(h, path)
    problems, needed, todo = [], set(), list(seeds.items())
    while todo:
        header, by = todo.pop()
        if header in needed:
            continue
        needed.add(header)
        if header not in installed:
            problems.append(f"{by} includes {header}, which is not installed: "
                            "add it to REEBKIT_PUBLIC_HEADERS in lib/CMakeLists.txt")
            continue
        text = (include / header).read_text()
        for h in INCLUDE.findall(text):
            if h.startswith("reebkit/"):
                todo.append((h, include / header))
            elif "/" in h and not h.startswith("Eigen/"):
                problems.append(f"{include / header} includes <{h}>: only Eigen's headers may be public")
    for extra in sorted(installed - needed):
        problems.append(f"{include / extra} is installed but neither examples/ nor python/ needs it: "
                        "remove it from REEBKIT_PUBLIC_HEADERS in lib/CMakeLists.txt")
    for p in problems:
        print(p)
    print(f"{len(installed)} headers installed, {len(needed)} needed, {len(problems)} problems")
    return 1 if problems else 0


def outside(text, trees, what, inside):
    """Fails when `text` (a file of the example's build) names the source or
    build tree (`inside`, the prefix and the example's own folder, may be in it)."""
    for folder in inside:
        text = text.replace(str(folder), "")
    for tree in trees:
        if str(tree) in text:
            sys.exit(f"{what} names {tree}: the example was not built against the installed tree only")


def example(source, prefix, work, build_tree, cxx, cxxflags, ldflags, cmake_args):
    source, prefix, work = Path(source).resolve(), Path(prefix).resolve(), Path(work).resolve()
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    cmake = os.environ.get("CMAKE", "cmake")
    trees = [source / "lib", source / "python", Path(build_tree).resolve()]
    inside = [prefix, work]

    # find_package(reebkit) from the installed tree only.
    build = work / "cmake-build"
    run(cmake, "-S", source / "examples", "-B", build, f"-DCMAKE_PREFIX_PATH={prefix}",
        f"-DCMAKE_CXX_COMPILER={cxx}", f"-DCMAKE_CXX_FLAGS={cxxflags}", f"-DCMAKE_EXE_LINKER_FLAGS={ldflags}",
        "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON", "-DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF", *cmake_args,
        stdout=subprocess.DEVNULL)
    cache = (build / "CMakeCache.txt").read_text()
    found = re.search(r"^reebkit_DIR:PATH=(.*)$", cache, re.MULTILINE).group(1)
    if not Path(found).resolve().is_relative_to(prefix):
        sys.exit(f"find_package(reebkit) found {found}, not the installed package under {prefix}")
    run(cmake, "--build", build)
    outside((build / "compile_commands.json").read_text(), trees, "compile_commands.json", inside)
    outside((build / "CMakeFiles/query_collection.dir/link.txt").read_text(), trees, "the link line", inside)
    programs = [build / "query_collection"]

    # pkg-config, as a Makefile would use it.
    env = dict(os.environ, PKG_CONFIG_PATH=str(prefix / "lib" / "pkgconfig"))
    flags = run("pkg-config", "--cflags", "--libs", "reebkit", env=env, capture_output=True).stdout.split()
    outside(" ".join(flags), trees, "pkg-config --cflags --libs reebkit", inside)
    programs.append(work / "query_collection_pc")
    run(cxx, "-std=c++17", *shlex.split(cxxflags), source / "examples" / "query_collection.cpp",
        "-o", programs[-1], *flags, *shlex.split(ldflags))

    # The installed command: a collection of the embedded meshes, the graph and the query.
    reeb = prefix / "bin" / "reeb"
    datasets = source / "datasets"
    run(reeb, "index", datasets, "-o", work / "datasets.h5", "--threads", "1", stdout=subprocess.DEVNULL)
    run(reeb, "graph", datasets / MESH, "-o", work / "graph.json", stdout=subprocess.DEVNULL)
    graph = json.loads((work / "graph.json").read_text())
    query = json.loads(run(reeb, "query", work / "datasets.h5", datasets / MESH, "-k", K, "--json",
                           capture_output=True).stdout)["results"]
    expected = [f"nodes {len(graph['nodes'])} edges {len(graph['edges'])} cycles {graph['cycles']} "
                f"leaves {graph['leaves']}"] + [(r["distance"], r["name"]) for r in query]
    if len(query) != K:
        sys.exit(f"reeb query listed {len(query)} results, not {K}")
    for program in programs:
        lines = run(program, datasets / MESH, work / "datasets.h5", K, capture_output=True).stdout.splitlines()
        got = lines[:1] + [(float(d), n) for d, n in (line.split(" ", 1) for line in lines[1:])]
        if got != expected:
            sys.exit(f"{program.name} printed\n  {got}\nwhere reeb graph and reeb query give\n  {expected}")
        print(f"{program.name}: {got[0]}, {K} results as reeb query's")
    return 0


PIP_CHECK = """
import json, sys
from pathlib import Path
import reebkit
venv, mesh = Path(sys.argv[1]).resolve(), sys.argv[2]
if not Path(reebkit.__file__).resolve().is_relative_to(venv):
    sys.exit(f"import reebkit found {reebkit.__file__}, not the module installed in {venv}")
g = reebkit.reeb_graph(*reebkit.load_mesh(mesh))
print(json.dumps({"version": reebkit.__version__, "edges": g.edges.tolist(), "cycles": g.cycles, "leaves": g.leaves,
                  "feature_points": g.feature_points.tolist(), "signature": g.signature.tolist()}))
"""


def pip(source, work, reeb, build=None):
    source, work = Path(source).resolve(), Path(work).resolve()
    shutil.rmtree(work, ignore_errors=True)
    (work / "elsewhere").mkdir(parents=True)
    venv = work / "venv"
    run("/usr/bin/python3", "-m", "venv", "--system-site-packages", venv)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "REEBKIT_BUILD_DIR")}
    if build:
        env["REEBKIT_BUILD_DIR"] = str(Path(build).resolve())
    run(venv / "bin" / "python", "-m", "pip", "install", "--no-build-isolation", "--no-index", source / "python",
        env=env, cwd=work)
    mesh = source / "datasets" / MESH
    got = json.loads(run(venv / "bin" / "python", "-c", PIP_CHECK, venv, mesh, env=env, cwd=work / "elsewhere",
                         capture_output=True).stdout)
    run(reeb, "graph", mesh, "-o", work / "graph.json", stdout=subprocess.DEVNULL)
    cli = json.loads((work / "graph.json").read_text())
    version = run(reeb, "--version", capture_output=True).stdout.splitlines()[0].split()[-1]
    expected = {"version": version, "edges": cli["edges"], "cycles": cli["cycles"], "leaves": cli["leaves"],
                "feature_points": cli["feature_points"], "signature": cli["signature"][0]}
    if got != expected:
        sys.exit(f"the pip-installed module gives\n  {got}\nwhere reeb graph gives\n  {expected}")
    print(f"pip-installed reebkit {got['version']}: {MESH} graph of {len(got['edges'])} edges, "
          f"{got['cycles']} cycles as reeb graph's")
    return 0


def main():
    if len(sys.argv) < 2 or sys.argv[1] not in ("install", "headers", "example", "pip"):
        sys.exit(__doc__)
    command, args = sys.argv[1], sys.argv[2:]
    if command == "install" and len(args) == 2:
        return install(*args)
    if command == "headers" and len(args) == 2:
        return headers(*args)
    if command == "pip" and len(args) in (3, 4):
        return pip(*args)
    parser = argparse.ArgumentParser(usage=__doc__)
    for name in ("source", "prefix", "work", "build"):
        parser.add_argument(name)
    parser.add_argument("--cxx", required=True)
    parser.add_argument("--cxxflags", default="")
    parser.add_argument("--ldflags", default="")
    a, cmake_args = parser.parse_known_args(args)
    return example(a.source, a.prefix, a.work, a.build, a.cxx, a.cxxflags, a.ldflags, cmake_args)


if __name__ == "__main__":
    sys.exit(main())
