#!/usr/bin/env bash
# Quick start, command 1: install, build, and run the built-in default job.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash ci/build.sh
build/bin/hmfnet demo
