"""Reads a results file written by `hmfnet simulate -o` (docs/simulation_output.md): every
dataset as a numpy array, the JSON attributes (parameters, network, provenance) as dicts."""
import json
import os

import numpy as np

from ._hmfnet import InputError


def read_run(path):
    """{"attributes": {...}, "points": {name: array}, "timeseries": {name: array}} plus, at the
    top level, the parameters, network and provenance records as dicts. A file that is missing,
    not HDF5 or not an hmfnet results file raises hmfnet.InputError (a ValueError) naming it, in
    the words of the module's network readers."""
    import h5py

    if not os.path.isfile(path):
        raise InputError(f"{path}: cannot open file for reading")
    try:
        f = h5py.File(path, "r")
    except OSError:
        # h5py's message names neither the file nor what was expected of it.
        raise InputError(f"{path}: not an HDF5 file (or cannot be read)") from None
    with f:
        attrs = {k: _value(v) for k, v in f.attrs.items()}
        if attrs.get("hmfnet_format") != "simulation":
            raise InputError(f"{path}: not an hmfnet results file "
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
