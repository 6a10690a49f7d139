#!/usr/bin/env python3
"""Fails when a file of lib/reebkit/<stage>/ includes a header of a stage that
<stage> does not build on.

The stages and their direct dependencies are those declared by the
reebkit_stage() lines of lib/CMakeLists.txt, which CMake writes to
STAGE_FILE (one "stage: dependency dependency ..." line each) when it
configures: the link order of the stage libraries and the include order
checked here are one declaration.

usage: check_stage_order.py STAGE_FILE LIB_DIR
"""
import re
import sys
from pathlib import Path

INCLUDE = re.compile(r'^\s*#\s*include\s*"reebkit/([a-z_]+)/([^"]+)"', re.MULTILINE)


def read_stages(stage_file):
    stages = {}
    for line in Path(stage_file).read_text().splitlines():
        if not line.strip():
            continue
        name, _, deps = line.partition(":")
        stages[name.strip()] = deps.replace(";", " ").split()
    return stages


def closures(stages):
    """Every stage a stage builds on, directly or not; exits on a cycle."""
    done, active, out = set(), [], {}

    def visit(stage):
        if stage in done:
            return
        if stage in active:
            sys.exit("stage cycle: " + " -> ".join(active[active.index(stage):] + [stage]))
        active.append(stage)
        reach = set()
        for dep in stages[stage]:
            if dep not in stages:
                sys.exit(f"stage '{stage}' depends on '{dep}', which is not a declared stage")
            visit(dep)
            reach |= {dep} | out[dep]
        active.pop()
        out[stage] = reach
        done.add(stage)

    for stage in stages:
        visit(stage)
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    stages = read_stages(sys.argv[1])
    reach = closures(stages)
    lib = Path(sys.argv[2]) / "reebkit"
    problems, checked = [], 0
    for path in sorted(lib.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        stage = path.relative_to(lib).parts[0]
        if stage not in stages:
            problems.append(f"{path}: folder '{stage}' is not a stage declared in lib/CMakeLists.txt")
            continue
        text = path.read_text()
        for match in INCLUDE.finditer(text):
            target, header = match.group(1), match.group(2)
            checked += 1
            if target == stage or target in reach[stage]:
                continue
            line = text.count("\n", 0, match.start()) + 1
            problems.append(f"{path}:{line}: includes reebkit/{target}/{header}, but stage '{stage}' "
                            f"builds only on: {', '.join(sorted(reach[stage])) or 'nothing'}")
    for p in problems:
        print(p)
    print(f"{len(stages)} stages, {checked} includes checked, {len(problems)} against the stage order")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
