#!/usr/bin/env python3
"""paper/scripts/qss_lifetime_gpu.py against what it ports (CTest unit.qss_lifetime_gpu_script):
  - m_eq against the M_eq that verification_qss_lifetime computed in C++ (all_to_all.cpp) at its
    own U, stored in paper/full/beyond/data/qss_lifetime.h5, to 1e-9;
  - half_way against a line-by-line transcription of support/passage_time.hpp's loop, on random
    series rising and falling, and NaN where the series never passes;
  - power_law on an exact power law;
  - the conversion of the device check's output: datasets, attributes, the records kept, and a
    refusal when the binary does not match its JSON;
  - --extend: a longer run of a size replaces the stored one, the other sizes and their run's
    device stay, and a run whose shared records differ is refused with no file left;
  - the calls of one resumed run (--raw A,B): the later call's records once checked against the
    earlier's, sizes a call did not step kept, the wall times summed once (also with the first
    call already stored), refused where the second call did not resume or its records differ.
Usage: test_qss_lifetime_gpu.py PAPER_DIR
"""
import json
import math
import os
import sys
import tempfile

import h5py
import numpy as np


def passage_time_hpp(x, dt, width, target):
    """support/passage_time.hpp's half_way_passage, t0 = 0, as written there."""
    if len(x) <= width or width == 0:
        return math.nan
    start = sum(x[:width]) / width
    half = 0.5 * (start + target)
    sign = 1.0 if target >= start else -1.0
    window = start * width
    for i in range(width, len(x)):
        window += x[i] - x[i - width]
        if sign * (window / width - half) >= 0.0:
            return dt * (i + 1.0 - 0.5 * width)
    return math.nan


def write_raw(folder, device, sizes, B, records, shift=0.0, resumed_from=""):
    """A device check's qss_gpu.json and qss_gpu.f64: R = N + (replica, record) / 100 + shift,
    the energy -N/2 (1 + 1e-6 record)."""
    meta = {"device": device, "h": 0.1, "U": 0.69, "K": 1, "replicas": B, "lives": 3,
            "budget_s": 1, "wall_s": 1, "records": records, "seeds": "s", "sizes": sizes,
            "resumed_from": resumed_from}
    json.dump(meta, open(os.path.join(folder, "qss_gpu.json"), "w"))
    blob = []
    for s in sizes:
        R = np.arange(B * records, dtype=float).reshape(B, records) / 100 + s["N"] + shift
        E = -np.full((B, records), 0.5 * s["N"]) * (1 + 1e-6 * np.arange(records))
        blob += [R.ravel(), E.ravel()]
    np.concatenate(blob).astype("<f8").tofile(os.path.join(folder, "qss_gpu.f64"))


def main():
    paper = sys.argv[1]
    sys.path.insert(0, os.path.join(paper, "scripts"))
    import qss_lifetime_gpu as q

    with h5py.File(os.path.join(paper, "full", "beyond", "data", "qss_lifetime.h5"), "r") as f:
        d = f["data/lives"]
        cols = json.loads(d.attrs["columns"])
        for row in d[()]:
            U, M = row[cols.index("U")], row[cols.index("M_eq")]
            assert abs(q.m_eq(U) - M) < 1e-9, (U, q.m_eq(U), M)

    rng = np.random.default_rng(3)
    for trial in range(200):
        n = int(rng.integers(5, 300))
        width = int(rng.integers(1, 12))
        rising = trial % 2 == 0
        x = np.cumsum(rng.normal(0.01 if rising else -0.01, 0.05, n))
        target = float(rng.normal(1.0 if rising else -1.0, 0.5))
        a = q.half_way(x, 2.5, width, target)
        b = passage_time_hpp(list(x), 2.5, width, target)
        assert (math.isnan(a) and math.isnan(b)) or abs(a - b) < 1e-9, (trial, a, b)
    assert math.isnan(q.half_way(np.zeros(50), 1.0, 5, 1.0))

    ns = np.array([1e3, 2e3, 5e3, 1e4])
    slope, se, _ = q.power_law(ns, 3.0 * ns ** 1.7, 0.05 * ns ** 1.7)
    assert abs(slope - 1.7) < 1e-12 and se > 0

    with tempfile.TemporaryDirectory() as tmp:
        B, records = 2, 5
        sizes = [{"N": 1000, "record_every": 10, "steps_planned": 50, "steps_done": 50,
                  "records_written": 5},
                 {"N": 2000, "record_every": 20, "steps_planned": 100, "steps_done": 60,
                  "records_written": 3}]
        write_raw(tmp, "card A", sizes, B, records)
        out = os.path.join(tmp, "q.h5")
        q.convert(tmp, out, "abc")
        with h5py.File(out, "r") as f:
            assert f.attrs["git_commit"] == "abc" and f.attrs["replicas"] == B
            assert f["N2000/R_mean"].shape == (B, 3)
            assert abs(f["N1000/R_mean"][1, 2] - (1000 + 7 / 100)) < 1e-3
            assert abs(f["N2000/energy_drift"][0, 2] + 2e-6) < 1e-9
            assert f["N2000"].attrs["steps_done"] == 60
            assert f["N2000"].attrs["device"] == "card A"
        np.zeros(3).tofile(os.path.join(tmp, "qss_gpu.f64"))
        try:
            q.convert(tmp, os.path.join(tmp, "bad.h5"), "abc")
        except (SystemExit, ValueError):
            pass
        else:
            raise AssertionError("a binary that does not match its JSON was accepted")
        assert not os.path.exists(os.path.join(tmp, "bad.h5"))
        assert sorted(os.listdir(tmp)) == ["q.h5", "qss_gpu.f64", "qss_gpu.json"], os.listdir(tmp)

        # N = 2000 run further on another card: its first 3 records are the stored ones.
        longer = os.path.join(tmp, "longer")
        os.mkdir(longer)
        write_raw(longer, "card B", [dict(sizes[1], steps_done=100, records_written=5)], B, records)
        merged = os.path.join(tmp, "merged.h5")
        q.convert(longer, merged, "def", extend=out)
        with h5py.File(merged, "r") as f:
            assert sorted(f) == ["N1000", "N2000"]
            assert f["N2000/R_mean"].shape == (B, 5) and f["N2000"].attrs["device"] == "card B"
            assert f["N2000"].attrs["git_commit"] == "def"
            assert f["N1000"].attrs["device"] == "card A" and f["N1000"].attrs["git_commit"] == "abc"
            assert f.attrs["device"] == "card A; card B"
        # A shorter run of a size keeps the stored one; an equally long one replaces it.
        shorter = os.path.join(tmp, "shorter")
        os.mkdir(shorter)
        write_raw(shorter, "card B", [dict(sizes[1], steps_done=80, records_written=4)], B, records)
        q.convert(shorter, os.path.join(tmp, "again.h5"), "ghi", extend=merged)
        with h5py.File(os.path.join(tmp, "again.h5"), "r") as f:
            assert f["N2000"].attrs["git_commit"] == "def" and f["N2000/R_mean"].shape == (B, 5)
        q.convert(longer, os.path.join(tmp, "again.h5"), "ghi", extend=merged)
        with h5py.File(os.path.join(tmp, "again.h5"), "r") as f:
            assert f["N2000"].attrs["git_commit"] == "ghi"
        # The same size started elsewhere: not the same experiment.
        other = os.path.join(tmp, "other")
        os.mkdir(other)
        write_raw(other, "card C", [dict(sizes[1], steps_done=100, records_written=5)], B, records,
                  shift=1e-3)
        try:
            q.convert(other, os.path.join(tmp, "mixed.h5"), "jkl", extend=out)
        except SystemExit as e:
            assert "differ" in str(e), e
        else:
            raise AssertionError("a run whose shared records differ was merged")
        assert not os.path.exists(os.path.join(tmp, "mixed.h5"))
        # --replace: the same size on another record grid (another --lives) replaces it.
        q.convert(other, os.path.join(tmp, "replaced.h5"), "jkl", extend=out, replace=True)
        with h5py.File(os.path.join(tmp, "replaced.h5"), "r") as f:
            assert f["N2000"].attrs["device"] == "card C" and f["N1000"].attrs["device"] == "card A"
            # R_mean is stored in float32, whose spacing at 2000 is 2^-13 = 1.2e-4: within it of
            # the replacing run's 2000 + 1e-3, and 8 spacings from the stored run's 2000.
            assert abs(f["N2000/R_mean"][0, 0] - (2000 + 1e-3)) < 2.0**-13

        # One run in two calls, the second resumed from the first: the second's records, the
        # calls' wall times summed; a second call that did not resume, or whose records differ
        # from the first's, is refused.
        part = dict(sizes[1], steps_done=60, records_written=3)
        whole = dict(sizes[1], steps_done=100, records_written=5)
        calls = {}
        for name, size, shift, resumed in (("first", part, 0.0, ""), ("second", whole, 0.0, "r.bin"),
                                           ("fresh", whole, 0.0, ""), ("moved", whole, 1e-3, "r.bin")):
            calls[name] = os.path.join(tmp, name)
            os.mkdir(calls[name])
            write_raw(calls[name], "card D", [size], B, records, shift, resumed)
        chain = os.path.join(tmp, "chain.h5")
        q.convert(calls["first"] + "," + calls["second"], chain, "mno")
        with h5py.File(chain, "r") as f:
            assert f["N2000/R_mean"].shape == (B, 5) and f["N2000"].attrs["wall_s"] == 2
            assert f.attrs["wall_s"] == 2 and f["N2000"].attrs["budget_s"] == 2
        # The first call already stored, the chain given again: its wall counted once.
        first_h5 = os.path.join(tmp, "first.h5")
        q.convert(calls["first"], first_h5, "mno")
        q.convert(calls["first"] + "," + calls["second"], os.path.join(tmp, "again2.h5"), "mno",
                  extend=first_h5)
        with h5py.File(os.path.join(tmp, "again2.h5"), "r") as f:
            assert f.attrs["wall_s"] == 2 and f["N2000"].attrs["wall_s"] == 2
        # A second call that stepped one size of two, on another card: the other size stays as
        # the first call left it; the run names both cards.
        two, one = os.path.join(tmp, "two"), os.path.join(tmp, "one")
        os.mkdir(two)
        os.mkdir(one)
        write_raw(two, "card D", [dict(sizes[0], steps_done=30, records_written=3), part], B,
                  records)
        write_raw(one, "card E", [whole], B, records, resumed_from="r.bin")
        q.convert(two + "," + one, os.path.join(tmp, "subset.h5"), "stu")
        with h5py.File(os.path.join(tmp, "subset.h5"), "r") as f:
            assert f["N1000/R_mean"].shape == (B, 3) and f["N2000/R_mean"].shape == (B, 5)
            assert f["N1000"].attrs["device"] == "card D + card E" and f["N1000"].attrs["wall_s"] == 2
        for bad, why in (("fresh", "did not resume"), ("moved", "differ")):
            try:
                q.convert(calls["first"] + "," + calls[bad], os.path.join(tmp, "bad.h5"), "pqr")
            except SystemExit as e:
                assert why in str(e), e
            else:
                raise AssertionError(f"a second call ({bad}) was taken as the first's continuation")
            assert not os.path.exists(os.path.join(tmp, "bad.h5"))
    print("qss_lifetime_gpu.py: m_eq, half_way, power_law, convert, --extend and resumed calls "
          "as ported")


if __name__ == "__main__":
    main()
