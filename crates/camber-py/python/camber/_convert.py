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
