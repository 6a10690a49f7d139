#!/usr/bin/env python3
"""The documentation is executed: every ```sh and ```python block of
README.md and docs/*.md runs, in file order (README.md first, then docs/ by
name), in one temporary folder that holds links to the checkout's datasets/,
tools/ and experiments/ and to the build folder as build/, so that later
blocks see what earlier ones wrote (the README tour's coll.h5). A shell block
runs under `bash -euo pipefail` with a `python3` first on the PATH that
refuses to run: the documented commands must name the Python that
`tools/run` installs the packages for (/usr/bin/python3), whatever python3
a user has first. A Python block runs with the Python the module was built
for, the module on PYTHONPATH.

A block may be preceded by a visible marker (an HTML comment, the last line
before the fence):
  <!-- doc-test: skip REASON -->   not run (REASON is required: shared data,
                                   a cluster, minutes of building);
  <!-- doc-test: usage -->         a synopsis: each line `build/tools/reeb CMD
                                   ...` is checked against `reeb CMD --help`
                                   (every --flag it names exists) instead.
Besides, every flag that `reeb CMD --help` lists under "analysis options" and
"matching options" is named in docs/command-line.md, every --flag written
there exists, and docs/collection-file.md names every analysis option.

usage: doc_blocks_test.py SOURCE_DIR BUILD_DIR PYTHON
Prints one line per block and the counts; exits 1 when a block fails.
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

MARKER = re.compile(r"^<!-- doc-test: (skip|usage)(?: (.*?))? -->$")
FENCE = re.compile(r"^```(\w*)\s*$")
FLAG = re.compile(r"(?<![\w-])--[a-z][a-z0-9-]*")


def blocks(path):
    """(line, language, text, marker, reason) of each fenced block of `path`."""
    lines = path.read_text().splitlines()
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start, language = i, m.group(1)
        j = i + 1
        while j < len(lines) and lines[j].rstrip() != "```":
            j += 1
        before = next((lines[k].strip() for k in range(start - 1, -1, -1) if lines[k].strip()), "")
        marker = MARKER.match(before)
        yield (start + 1, language, "\n".join(lines[start + 1:j]) + "\n",
               marker.group(1) if marker else None, (marker.group(2) or "") if marker else "")
        i = j + 1


def help_flags(reeb, command, section=None):
    """The --flags of `reeb COMMAND --help` (of one section only when given)."""
    text = subprocess.run([reeb, command, "--help"], capture_output=True, text=True, check=True).stdout
    if section:
        parts = re.split(r"\n(?=\S[^\n]*:\n)", text)
        text = "\n".join(p for p in parts if p.startswith(section))
    return set(FLAG.findall(text))


def check_usage(reeb, text):
    """Problems of a synopsis block: flags that `reeb CMD --help` lacks."""
    problems = []
    for line in text.splitlines():
        m = re.match(r"\s*build/tools/reeb (\w+)(.*)", line)
        if not m:
            continue
        known = help_flags(reeb, m.group(1))
        for flag in FLAG.findall(m.group(2)):
            if flag not in known:
                problems.append(f"reeb {m.group(1)} has no {flag}")
    return problems


def check_option_lists(source, reeb, python):
    """Problems of the docs' lists of options against the command line's."""
    problems = []
    command_line = (source / "docs" / "command-line.md").read_text()
    every = set()
    for script in sorted((source / "tools" / "figures").glob("*.py")):  # the figure scripts it documents too
        if script.name in command_line:
            every |= set(FLAG.findall(subprocess.run([python, str(script), "--help"], capture_output=True,
                                                     text=True, check=True).stdout))
    for command in ("features", "graph", "deform", "index", "info", "export", "match", "eval", "query",
                    "distances", "variants", "perturb"):
        every |= help_flags(reeb, command)
    for section, command in (("analysis options", "index"), ("matching options", "match")):
        for flag in sorted(help_flags(reeb, command, section)):
            if f"`{flag}" not in command_line:
                problems.append(f"docs/command-line.md does not name {flag} ({section})")
    for flag in sorted(set(FLAG.findall(command_line)) - every - {"--help", "--verbose", "--version"}):
        problems.append(f"docs/command-line.md names {flag}, which no command has")
    collection_file = (source / "docs" / "collection-file.md").read_text()
    for flag in sorted(help_flags(reeb, "index", "analysis options")):
        name = flag[2:].replace("-", "_")
        if f"`{name}`" not in collection_file:
            problems.append(f"docs/collection-file.md does not list the analysis option {name}")
    return problems


def main():
    source, build, python = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), sys.argv[3]
    reeb = str(build / "tools" / "reeb")
    ran = skipped = usage = 0
    failures = []
    with tempfile.TemporaryDirectory(prefix="reebkit-doc-") as folder:
        work = pathlib.Path(folder)
        for name in ("datasets", "tools", "experiments"):
            (work / name).symlink_to(source / name)
        (work / "build").symlink_to(build)
        shim = work / ".shim"
        shim.mkdir()
        (shim / "python3").write_text("#!/bin/sh\necho 'python3 first on the PATH is not the Python tools/run "
                                      "installs for: name /usr/bin/python3' >&2\nexit 97\n")
        (shim / "python3").chmod(0o755)
        env = dict(os.environ, PATH=f"{shim}:{os.environ['PATH']}", PYTHONPATH=str(build / "python"),
                   PYTHONDONTWRITEBYTECODE="1", MPLBACKEND="Agg")
        for doc in [source / "README.md"] + sorted((source / "docs").glob("*.md")):
            for line, language, text, marker, reason in blocks(doc):
                if language not in ("sh", "python"):
                    continue
                where = f"{doc.relative_to(source)}:{line}"
                if marker == "skip":
                    if not reason:
                        failures.append(f"{where}: a skipped block must say why")
                    print(f"skip  {where}: {reason}")
                    skipped += 1
                    continue
                if marker == "usage":
                    problems = check_usage(reeb, text)
                    print(f"usage {where}" + "".join(f"\n      {p}" for p in problems))
                    failures += [f"{where}: {p}" for p in problems]
                    usage += 1
                    continue
                command = ["bash", "-euo", "pipefail", "-c", text] if language == "sh" else [python, "-c", text]
                result = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True)
                ran += 1
                print(f"run   {where} ({language}): exit {result.returncode}")
                if result.returncode != 0:
                    failures.append(f"{where}: exit {result.returncode}\n{result.stdout[-3000:]}{result.stderr[-3000:]}")
    problems = check_option_lists(source, reeb, python)
    failures += problems
    for failure in failures:
        print(f"FAILED {failure}")
    print(f"{ran} blocks run, {usage} synopses checked, {skipped} skipped; {len(problems)} option list problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
