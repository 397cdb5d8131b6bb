"""Keyword arguments to a typed request (src/app): each keyword given (not None) sets the request's
field of that name, and the request's own check (its C++ validate) refuses values out of range
with the CLI's words. None leaves the CLI's default.

A bool is a number to Python (True == 1) but not to the CLI: only the options that the CLI
declares with add_flag (src/cli/command_options.cpp) take one; any other keyword given a bool
raises TypeError, so that ``T=False`` does not silently mean the default T and ``seed=True``
does not become seed 1."""
import numbers
import os

import numpy as np

# The CLI's add_flag options that a Python function exposes as keywords.
FLAGS = frozenset({"symmetrize", "self_loops", "resume", "node_data", "restart_each_K",
                   "K_across_replicas"})

# Options that take a list of numbers (one number is a list of one).
LISTS = frozenset({"K", "K_over_Kc"})

# Options whose value is a word or a path (the rest take numbers), for the TypeError's wording.
WORDS = frozenset({"momenta", "lambda2", "K_sweep", "output", "checkpoint", "integrator", "force",
                   "precision", "link", "device"})


def _is_bool(value):
    return isinstance(value, (bool, np.bool_))


def _not_a_bool(where, name, shown):
    kind = "a string" if name in WORDS else "a number"
    return TypeError(f"{where}: {name}={shown!r}: a bool is not {kind} ({name} takes {kind})")


def _flag(where, name, value):
    if not _is_bool(value):
        raise TypeError(f"{where}: {name}={value!r}: {name} is a flag (it takes True or False)")


def _check_seed(value):
    # The CLI's seed check (src/cli/seed_check.hpp: k_seed), with its words.
    if not isinstance(value, numbers.Integral) or not 0 <= int(value) < 2**64:
        raise ValueError(f"--seed: value {value} is not allowed "
                         "(allowed: an integer 0 <= seed < 2^64)")


def request(where, target, **options):
    """Sets each option given (not None) on the typed request ``target`` (``where``, the calling
    function's name, starts every TypeError's message); a value of the wrong type raises
    TypeError naming the keyword."""
    for name, value in options.items():
        if value is None:
            continue
        if name in FLAGS:
            _flag(where, name, value)
            setattr(target, name, bool(value))
            continue
        if _is_bool(value):
            raise _not_a_bool(where, name, value)
        if name == "seed":
            _check_seed(value)
        if isinstance(value, (list, tuple, np.ndarray)):
            if any(_is_bool(v) for v in value):
                raise _not_a_bool(where, name, value)
            value = [float(v) for v in value]
        elif isinstance(value, numbers.Real) and name in LISTS:
            value = [float(value)]  # one K, as --K 1.5 is
        elif isinstance(value, os.PathLike):
            value = os.fspath(value)
        try:
            setattr(target, name, value)
        except TypeError:
            kind = "a string" if name in WORDS else "a number"
            raise TypeError(f"{where}: {name}={value!r}: {name} takes {kind}") from None
    return target
