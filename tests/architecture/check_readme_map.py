#!/usr/bin/env python3
"""Keeps the README's map true: every header, test file and command its
"## Map" table names must exist.

- a header `reebkit/<stage>/<step>.h` must be a file under lib/;
- a test `tests/<stage>/<file>` must exist and be listed in tests/CMakeLists.txt;
- a command `reeb <sub> ...` (or a bare `<sub>` continuing a list) must be a
  subcommand that `reeb --help` lists, and an option `--flag` must be offered
  by `reeb <sub> --help` of some subcommand.

usage: check_readme_map.py SOURCE_DIR REEB_BINARY
"""
import re
import subprocess
import sys
from pathlib import Path


def map_rows(readme):
    lines = readme.read_text().splitlines()
    start = lines.index("## Map")
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("## "):
            break
        if line.startswith("|") and not line.startswith("|---") and not line.startswith("| step"):
            cells = [c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
            rows.append(cells)
    return rows


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    source, reeb = Path(sys.argv[1]), sys.argv[2]
    help_text = subprocess.run([reeb, "--help"], capture_output=True, text=True).stdout
    subcommands = set(re.findall(r"^  ([a-z]+)\s", help_text, re.MULTILINE))
    if not subcommands:
        sys.exit(f"could not read the subcommands from `{reeb} --help`")
    options = set()
    for sub in subcommands:
        text = subprocess.run([reeb, sub, "--help"], capture_output=True, text=True).stdout
        options |= set(re.findall(r"--[a-z][a-z0-9-]*", text))
    tests_cmake = (source / "tests" / "CMakeLists.txt").read_text()

    problems, rows = [], map_rows(source / "README.md")
    if not rows:
        problems.append("README.md has no rows under '## Map'")
    for step, header, command, test in rows:
        for h in re.findall(r"`([^`]+)`", header):
            if not (source / "lib" / h).is_file():
                problems.append(f"{step}: header {h} is not in lib/")
        for t in re.findall(r"`([^`]+)`", test):
            if not (source / t).is_file():
                problems.append(f"{step}: test {t} does not exist")
            elif t.removeprefix("tests/") not in tests_cmake:
                problems.append(f"{step}: test {t} is not built by tests/CMakeLists.txt")
        for c in re.findall(r"`([^`]+)`", command):
            words = c.replace("\\|", "|").split()
            if words[0] == "reeb":
                words = words[1:]
            if words[0].startswith("--"):
                if words[0] not in options:
                    problems.append(f"{step}: no subcommand offers {words[0]}")
            elif words[0] not in subcommands:
                problems.append(f"{step}: `reeb {words[0]}` is not a subcommand")
            for flag in (w for w in words[1:] if w.startswith("--")):
                if flag not in options:
                    problems.append(f"{step}: no subcommand offers {flag}")
    for p in problems:
        print(p)
    print(f"{len(rows)} map rows checked, {len(problems)} problems")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
