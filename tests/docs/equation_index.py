#!/usr/bin/env python3
"""Checks docs/equations.md against the code and the paper (CTest unit.equation_index).

Files move between folders (src/spectral, src/theory, tests/support) and functions get renamed;
the index must follow, so this fails, naming the label and the path, when
  (a) a label cited in the code has no row,
  (b) a row names a file that does not exist,
  (c) a row names a function that does not occur in its file,
  (d) a row's label is not a \\label of the paper (unless its formula is marked
      "not in the paper:"); skipped with a note when the paper is not beside the checkout.
Usage: equation_index.py SOURCE_DIR [--index FILE] [--paper FILE]
"""
import argparse
import os
import re
import sys

# Built from pieces so that this file does not cite a label itself.
LABEL = re.compile("eq" + r":[A-Za-z0-9_]+")
CITING_DIRS = ("src", "verification", "tests", "bench", os.path.join("paper", "scripts"))
NOT_IN_PAPER = "not in the paper:"
PAPER = os.path.join("..", "shared", "seeds", "000_2d217c07ecdc703c.txt")


def cells(line):
    """Cells of one markdown table row; '\\|' is a literal bar inside a cell."""
    parts = re.split(r"(?<!\\)\|", line.strip())
    return [p.strip().replace("\\|", "|") for p in parts[1:-1]]


def read_index(path):
    """{label: (formula, [(file, [names])], [checked files])} from the table rows."""
    rows = {}
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            row = cells(line) if line.lstrip().startswith("|") else []
            if not row or not LABEL.fullmatch(row[0]):
                continue
            if len(row) != 4:
                raise SystemExit(f"{path}:{number}: {row[0]}: expected 4 cells, found {len(row)}")
            implementation = []
            for item in filter(None, (s.strip() for s in row[2].split(";"))):
                file, _, names = item.partition(":")
                implementation.append((file.strip(), [n.strip() for n in names.split(",")
                                                      if n.strip()]))
            checked = [s.strip() for s in row[3].split(";") if s.strip()]
            rows[row[0]] = (row[1], implementation, checked)
    return rows


def cited_labels(source):
    """{label: first file citing it} over the code (the index itself is under docs/)."""
    cited = {}
    for top in CITING_DIRS:
        for folder, dirs, files in os.walk(os.path.join(source, top)):
            dirs[:] = sorted(d for d in dirs if d != "__pycache__" and not d.startswith("."))
            for name in sorted(files):
                path = os.path.join(folder, name)
                with open(path, "rb") as f:
                    data = f.read()
                if b"\0" in data:  # compiled or binary (.pyc, fuzz inputs): not a citation
                    continue
                for label in LABEL.findall(data.decode("utf-8", errors="ignore")):
                    cited.setdefault(label, os.path.relpath(path, source))
    return cited


def check(source, index_path, paper_path):
    problems = []
    rows = read_index(index_path)
    index = os.path.relpath(index_path, source)
    for label, where in sorted(cited_labels(source).items()):
        if label not in rows:
            problems.append(f"(a) {label}: cited in {where} but has no row in {index}")
    for label, (formula, implementation, checked) in sorted(rows.items()):
        if not implementation:
            problems.append(f"(c) {label}: no implementing function named")
        for file, names in implementation:
            path = os.path.join(source, file)
            if not os.path.isfile(path):
                problems.append(f"(b) {label}: {file} does not exist")
                continue
            if not names:
                problems.append(f"(c) {label}: {file}: no function named")
            with open(path, encoding="utf-8", errors="ignore") as f:
                # Not the #include lines: "bessel_ratio.hpp" does not define bessel_ratio.
                text = re.sub(r"(?m)^\s*#\s*include.*$", "", f.read())
            for name in names:
                if not re.search(r"(?<![A-Za-z0-9_])" + re.escape(name) + r"(?![A-Za-z0-9_])",
                                 text):
                    problems.append(f"(c) {label}: {name} does not occur in {file}")
        for file in checked:
            if not os.path.isfile(os.path.join(source, file)):
                problems.append(f"(b) {label}: {file} does not exist")
    if paper_path and os.path.isfile(paper_path):
        with open(paper_path, encoding="utf-8", errors="ignore") as f:
            paper_labels = set(re.findall(r"\\label\{(" + LABEL.pattern + r")\}", f.read()))
        for label, (formula, _, _) in sorted(rows.items()):
            marked = formula.lower().startswith(NOT_IN_PAPER)
            if label not in paper_labels and not marked:
                problems.append(f"(d) {label}: not a \\label of {paper_path} "
                                f"(mark its formula '{NOT_IN_PAPER}' if that is intended)")
            if label in paper_labels and marked:
                problems.append(f"(d) {label}: marked '{NOT_IN_PAPER}' but the paper has it")
    else:
        print(f"note: paper not found at {paper_path}: labels not checked against it (d)")
    return rows, problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source", help="the source tree (holds docs/, src/, tests/, ...)")
    parser.add_argument("--index", help="default: SOURCE/docs/equations.md")
    parser.add_argument("--paper", help=f"default: SOURCE/{PAPER}")
    args = parser.parse_args()
    source = os.path.abspath(args.source)
    index = args.index or os.path.join(source, "docs", "equations.md")
    paper = args.paper or os.path.normpath(os.path.join(source, PAPER))
    rows, problems = check(source, index, paper)
    for p in problems:
        print(f"FAIL {p}")
    print(f"{index}: {len(rows)} labels, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
