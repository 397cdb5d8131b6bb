#!/usr/bin/env python3
"""Checks the layering rule of docs/development.md against the code (CTest unit.layering).

The rule: a folder of src/ includes only from itself and the folders listed above it in the
table of docs/development.md's "Layout" section. The order is read from that table, so the
document and this check cannot drift apart; every `#include "FOLDER/..."` of every file under
src/ (C++ and CUDA) is checked, and each violation is named with its file and line.
Usage: layering.py SOURCE_DIR
"""
import os
import re
import sys

TABLE_ROW = re.compile(r"^\| `src/([a-z_]+)`")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')
SOURCES = (".hpp", ".cpp", ".h", ".cu", ".cuh")


def folder_order(doc):
    order = []
    with open(doc, encoding="utf-8") as f:
        for line in f:
            m = TABLE_ROW.match(line)
            if m and m.group(1) not in order:
                order.append(m.group(1))
    return order


def violations(root, order):
    rank = {name: k for k, name in enumerate(order)}
    found = []
    src = os.path.join(root, "src")
    for folder in sorted(os.listdir(src)):
        base = os.path.join(src, folder)
        if not os.path.isdir(base):
            continue
        if folder not in rank:
            found.append(f"src/{folder}: not in the layering table of docs/development.md")
            continue
        for where, _, files in os.walk(base):
            for name in sorted(files):
                if not name.endswith(SOURCES):
                    continue
                path = os.path.join(where, name)
                with open(path, encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if m and m.group(1) in rank and rank[m.group(1)] > rank[folder]:
                            found.append(f"{os.path.relpath(path, root)}:{number}: {folder} "
                                         f"includes {m.group(1)}, a layer below it")
    return found


def main():
    root = sys.argv[1]
    order = folder_order(os.path.join(root, "docs", "development.md"))
    if len(order) < 5:
        print(f"layering.py: could not read the layering table ({order})")
        return 1
    found = violations(root, order)
    for v in found:
        print(v)
    print(f"layering.py: layers from the top: {', '.join(order)}; {len(found)} violations")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
