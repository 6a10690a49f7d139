#!/usr/bin/env python3
"""compare_collections.py A.h5 B.h5: exit 0 when the two collection files
hold the same content, as h5py reads them: every dataset equal (values,
shape, type; NaN equal to NaN) but `timings`, the same groups and
attributes, the file attributes but the provenance of the run (`command`,
`created`); else print each difference and exit 1."""
import sys

import h5py
import numpy as np

SKIPPED_DATASETS = {"timings"}
SKIPPED_FILE_ATTRIBUTES = {"command", "created"}


def same_values(a, b):
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind == "f":
        return bool(np.array_equal(a, b, equal_nan=True))
    return bool(np.array_equal(a, b))


def attributes(obj, skipped=()):
    return {k: obj.attrs[k] for k in obj.attrs if k not in skipped}


def compare(a, b, out):
    names = set(a) | set(b)
    for name in sorted(names):
        if name not in a or name not in b:
            out.append(f"{name}: only in {'the first' if name in a else 'the second'} file")
            continue
        x, y = a[name], b[name]
        if isinstance(x, h5py.Group) != isinstance(y, h5py.Group):
            out.append(f"{x.name}: a group in one file only")
            continue
        xa, ya = attributes(x), attributes(y)
        if xa.keys() != ya.keys() or any(not same_values(xa[k], ya[k]) for k in xa):
            out.append(f"{x.name}: attributes differ")
        if isinstance(x, h5py.Group):
            compare(x, y, out)
        elif name not in SKIPPED_DATASETS:
            if x.dtype.kind == "O" or h5py.check_string_dtype(x.dtype):
                same = x.shape == y.shape and list(x.asstr()[()]) == list(y.asstr()[()])
            else:
                same = same_values(x[()], y[()])
            if not same:
                out.append(f"{x.name}: values differ")


def main():
    first, second = sys.argv[1:3]
    differences = []
    with h5py.File(first, "r") as a, h5py.File(second, "r") as b:
        xa, ya = attributes(a, SKIPPED_FILE_ATTRIBUTES), attributes(b, SKIPPED_FILE_ATTRIBUTES)
        if xa.keys() != ya.keys() or any(not same_values(xa[k], ya[k]) for k in xa):
            differences.append("file attributes differ")
        compare(a, b, differences)
        count = int(a["count"][0])
    for d in differences:
        print(d)
    if not differences:
        print(f"same content: {count} entries")
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main())
