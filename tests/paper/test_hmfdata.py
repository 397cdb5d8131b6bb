#!/usr/bin/env python3
"""paper/scripts/hmfdata.py reads columns by the names a driver stored (CTest unit.hmfdata_columns).

Writes a tiny file in the layout of verification/support/claim_check.cpp with h5py and checks
that columns are found by name, and that a missing column or a table without names fails with
an error naming the file, the dataset and the column. Usage: test_hmfdata.py PAPER_SCRIPTS_DIR
"""
import json
import os
import sys
import tempfile

import h5py
import numpy as np


def write_driver_file(path):
    with h5py.File(path, "w") as f:
        for key, value in {"hmfnet_format": "verification", "driver": "tiny", "claim": "c",
                           "scale": "ci", "passed": 1, "checks": "[]"}.items():
            f.attrs[key] = value
        data = f.create_group("data")
        table = data.create_dataset("points", data=np.array([[1.0, 10.0], [2.0, 20.0]]))
        table.attrs["columns"] = json.dumps(["K/K_c", "R"])
        named = data.create_dataset("constants", data=np.array([0.5, 7.0]))
        named.attrs["columns"] = json.dumps(["sigma0", "N"])
        data.create_dataset("unnamed", data=np.zeros((2, 2)))


def expect_error(kind, call, *needles):
    try:
        call()
    except kind as e:
        message = str(e)
        missing = [n for n in needles if n not in message]
        if missing:
            raise AssertionError(f"error '{message}' does not name {missing}")
        return
    raise AssertionError(f"expected {kind.__name__}, nothing raised")


def check_summary(directory, hmfdata):
    """make_report's summary: a file written before the cost attributes existed gets blank cells,
    one with them gets work [G], stepping share, rate = work / stepping seconds, ranks x threads;
    every row has as many cells as the header."""
    import make_report
    with h5py.File(os.path.join(directory, "costed.h5"), "w") as f:
        for key, value in {"hmfnet_format": "verification", "driver": "costed", "claim": "c",
                           "scale": "ci", "passed": 1, "checks": "[]", "wall_seconds": 10.0,
                           "force_evaluations": 100.0, "paper_evaluations": 400.0,
                           "kernel_work": 6e9, "kernel_seconds": 8.0, "threads": 2,
                           "ranks": 3}.items():
            f.attrs[key] = value
        f.create_group("data")
    results = {name: hmfdata.load(directory, name) for name in ("tiny", "costed")}
    lines = make_report.summary(results)
    header = next(line for line in lines if line.startswith("| driver |"))
    rows = {line.split("|")[1].strip(): line for line in lines if line.startswith("| `")}
    for row in rows.values():
        assert row.count("|") == header.count("|"), (row, header)
    cells = [c.strip() for c in rows["`costed`"].split("|")[1:-1]]
    assert cells[4:] == ["100", "4.00x", "6", "80%", "0.75", "3 x 2"], cells
    assert all(c.strip() == "" for c in rows["`tiny`"].split("|")[5:-1]), rows["`tiny`"]


def main():
    sys.path.insert(0, sys.argv[1])
    import hmfdata

    with tempfile.TemporaryDirectory() as directory:
        path = os.path.join(directory, "tiny.h5")
        write_driver_file(path)
        result = hmfdata.load(directory, "tiny")
        points = result.table("points")
        assert list(points["R"]) == [10.0, 20.0], points["R"]
        assert list(points["K/K_c"]) == [1.0, 2.0]
        assert len(points) == 2
        constants = result.table("constants")
        assert constants["N"] == 7.0 and constants["sigma0"] == 0.5
        expect_error(KeyError, lambda: points["R_sim"], path, "/data/points", "'R_sim'", "R")
        expect_error(KeyError, lambda: constants["K"], path, "/data/constants", "'K'")
        expect_error(KeyError, lambda: result.table("unnamed"), path, "/data/unnamed",
                     "no column names")
        expect_error(KeyError, lambda: result.table("absent"), "tiny", "absent")
        check_summary(directory, hmfdata)
        # Stored data of another kind beside the drivers' (qss_lifetime_gpu.h5): not loaded as
        # a driver's output, and load refuses it by name.
        stored = os.path.join(directory, "stored.h5")
        with h5py.File(stored, "w") as f:
            f.attrs["replicas"] = 32
        assert hmfdata.is_verification_output(path)
        assert not hmfdata.is_verification_output(stored)
        expect_error(ValueError, lambda: hmfdata.load(directory, "stored"), stored,
                     "not a verification output")
    print("hmfdata: columns by name, and errors naming file, dataset and column; the report's "
          "summary on files with and without the cost attributes; stored data told apart: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
