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
    print("hmfdata: columns by name, and errors naming file, dataset and column: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
