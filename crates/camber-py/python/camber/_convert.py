"""Helpers the native module calls: plain JSON values from numpy objects."""

import numpy as np


def plain(obj):
    """A JSON-serialisable form of numpy arrays and scalars (used as json.dumps' default)."""
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, tuple):
        return list(obj)
    raise TypeError(f"{type(obj).__name__} is not JSON serialisable")


def non_finite(obj, path=""):
    """The path (``distance``, ``target.point[1]``) and value of the first NaN or infinite
    number inside ``obj`` (dicts, lists, tuples, numpy arrays and scalars), or None."""
    if isinstance(obj, np.ndarray):
        obj = obj.tolist()
    elif isinstance(obj, np.generic):
        obj = obj.item()
    if isinstance(obj, float):
        return None if np.isfinite(obj) else (path or "value", obj)
    if isinstance(obj, dict):
        items = ((f"{path}.{k}" if path else str(k), v) for k, v in obj.items())
    elif isinstance(obj, (list, tuple)):
        items = ((f"{path}[{i}]", v) for i, v in enumerate(obj))
    else:
        return None
    for p, v in items:
        found = non_finite(v, p)
        if found is not None:
            return found
    return None
