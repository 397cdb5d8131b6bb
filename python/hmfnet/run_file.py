"""Reads a results file written by `hmfnet simulate -o` (docs/simulation_output.md): every
dataset as a numpy array, the JSON attributes (parameters, network, provenance) as dicts."""
import json

import numpy as np


def read_run(path):
    """{"attributes": {...}, "points": {name: array}, "timeseries": {name: array}} plus, at the
    top level, the parameters, network and provenance records as dicts. Raises ValueError for a
    file that is not an hmfnet results file."""
    import h5py

    with h5py.File(path, "r") as f:
        attrs = {k: _value(v) for k, v in f.attrs.items()}
        if attrs.get("hmfnet_format") != "simulation":
            raise ValueError(f"{path}: not an hmfnet results file "
                             f"(hmfnet_format = {attrs.get('hmfnet_format')!r}, "
                             "expected 'simulation')")
        out = {"attributes": attrs}
        for group in ("points", "timeseries"):
            out[group] = {k: _dataset(d) for k, d in f[group].items()} if group in f else {}
    for key in ("parameters", "network", "provenance"):
        if isinstance(attrs.get(key), str):
            out[key] = json.loads(attrs[key])
    return out


def _value(v):
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, np.ndarray) and v.size == 1:
        return v.item()
    return v


def _dataset(d):
    a = d[()]
    if a.dtype.kind == "S":
        return np.char.decode(a).astype(str)
    return a
