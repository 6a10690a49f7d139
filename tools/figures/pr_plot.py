#!/usr/bin/python3
"""Plot precision-recall curves written by `reeb eval` (pr.csv: method, curve,
recall, precision) to PNG and SVG: the micro-averaged curve of every method,
one line each, so that several methods share one plot.

Needs only Debian's python3-matplotlib.

    pr_plot.py pr.csv OUT.png OUT.svg [--curve micro|macro|CLASS] [--title T]
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The same curves give the same SVG bytes on every run: its element ids come
# from this salt instead of a random one, and it carries no date.
plt.rcParams["svg.hashsalt"] = "reebkit"


def read_curves(path, curve):
    """{method: ([recall], [precision])} of the rows whose curve is `curve`, in file order."""
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["curve"] != curve:
                continue
            recall, precision = curves.setdefault(row["method"], ([], []))
            recall.append(float(row["recall"]))
            precision.append(float(row["precision"]))
    return curves


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("svg")
    parser.add_argument("--curve", default="micro", help="micro, macro or a class name (default micro)")
    parser.add_argument("--title", default=None)
    args = parser.parse_args()

    curves = read_curves(args.csv, args.curve)
    if not curves:
        sys.exit(f"{args.csv}: no '{args.curve}' curve")
    fig, ax = plt.subplots(figsize=(5.5, 4.5))
    for method, (recall, precision) in curves.items():
        ax.plot(recall, precision, marker="o", markersize=3, label=method)
    ax.set_xlim(0, 1.02)
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("recall")
    ax.set_ylabel("precision (interpolated)")
    ax.set_title(args.title or f"precision-recall ({args.curve} average)")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="lower left", fontsize="small")  # the curves fall from the upper left: that corner stays empty
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    fig.savefig(args.svg, metadata={"Date": None})


if __name__ == "__main__":
    main()
