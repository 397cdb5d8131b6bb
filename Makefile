# Thin front end for the CMake build (the build itself lives in build/).
#   make paper-figures               quick preset: paper/REPORT.md and paper/figures/ in minutes
#   make paper-figures PRESET=full   the paper's N, T and K grids (wall time: docs/verification.md)
#   make test                        the CI test suite (ci/test.sh)
PRESET ?= quick
BUILD ?= build
JOBS ?= $(shell nproc)

.PHONY: paper-figures build test

build:
	bash ci/build.sh

paper-figures: build
	cmake -S . -B $(BUILD) -DHMFNET_PAPER_PRESET=$(PRESET) > /dev/null
	cmake --build $(BUILD) --target paper-figures -j $(JOBS)

test:
	bash ci/test.sh
