"""Keyword arguments to the CLI's tokens: ``K_over_Kc=[1, 2]`` -> ``--K-over-Kc 1,2``; True
flags -> ``--flag``; None and False -> nothing (the CLI's default). Floats are written with
repr, which reads back to the same double."""
import numbers

import numpy as np


def _text(value):
    if isinstance(value, (bool, np.bool_)):
        raise TypeError("a flag inside a list")
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    return str(value)


def tokens(**options):
    out = []
    for name, value in options.items():
        if value is None or value is False:
            continue
        option = "--" + name.replace("_", "-")
        if value is True:
            out.append(option)
        elif isinstance(value, (list, tuple, np.ndarray)):
            out += [option, ",".join(_text(v) for v in value)]
        else:
            out += [option, _text(value)]
    return out
