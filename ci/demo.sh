#!/usr/bin/env bash
# Quick start, command 1: install, build, and run the main job on its built-in default: a small
# end-to-end run of the paper pipeline (Tables I-II and Fig. 6 at CI scale, and their report).
# `make paper-figures` runs every table and figure; `build/bin/hmfnet demo` prints Tables I-II
# and a simulation-vs-theory comparison without the plotting stack.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash ci/build.sh
cmake --build build --target paper-demo
report=build/paper/demo/REPORT.md
sed -n '/^## Summary/,/^## Table I:/p' "$report" | sed '$d'
echo "Report: $report (figures in build/paper/demo/figures/)"
