"""Curves to and from scipy and geomdl, exactly: the same degree, knots, control points and
weights, so every point agrees to rounding.

* scipy: ``scipy.interpolate.BSpline(t, c, k)`` is a B-spline with knots ``t``, coefficients
  ``c`` (one row per control point; rows beyond ``len(t) - k - 1`` are ignored, as scipy does)
  and degree ``k``. Its base interval [t[k], t[n]] is the camber curve's domain. scipy has no
  rational spline, so a NURBS curve goes to scipy only when its weights are all equal.
* geomdl: ``geomdl.BSpline.Curve`` and ``geomdl.NURBS.Curve``. geomdl rescales knot vectors
  to [0, 1] unless a curve is made with ``normalize_kv=False``; :func:`to_geomdl` makes it so,
  which keeps the parameters camber uses, and :func:`from_geomdl` reads whatever the curve holds.

Neither library is a dependency of camber: each converter imports its library when called.
"""

import numpy as np

from camber._native import BezierCurve, BSplineCurve, NurbsCurve

__all__ = ["to_scipy", "from_scipy", "to_geomdl", "from_geomdl"]


def _real(values, what):
    """``values`` as a float array, refusing complex numbers (numpy would drop their imaginary
    parts with only a warning)."""
    a = np.asarray(values)
    if np.iscomplexobj(a) or (a.dtype == object and any(isinstance(v, complex) for v in a.flat)):
        raise TypeError(f"the {what} are complex; camber curves are real")
    return a.astype(float)


def _knotted(curve):
    """(degree, knots, control points, weights or None) of a Bézier, B-spline or NURBS curve."""
    if isinstance(curve, NurbsCurve):
        return curve.degree, curve.knots, curve.control_points, curve.weights
    if isinstance(curve, BSplineCurve):
        return curve.degree, curve.knots, curve.control_points, None
    if isinstance(curve, BezierCurve):
        p = curve.degree
        return p, np.array([0.0] * (p + 1) + [1.0] * (p + 1)), curve.control_points, None
    raise TypeError(
        f"{type(curve).__name__} has no single knot vector to convert; "
        "expected a BezierCurve, BSplineCurve or NurbsCurve"
    )


def to_scipy(curve):
    """The curve as ``scipy.interpolate.BSpline`` (``extrapolate=False``: scipy answers NaN
    outside the domain, where camber raises).

    Raises TypeError for a curve without one knot vector (Hermite, composite) and ValueError
    for a NURBS curve whose weights differ (scipy has no rational spline).
    """
    from scipy.interpolate import BSpline

    degree, knots, points, weights = _knotted(curve)
    if weights is not None and not np.all(weights == weights[0]):
        raise ValueError(
            "a NURBS curve with unequal weights has no scipy BSpline form "
            f"(weights from {weights.min()} to {weights.max()})"
        )
    return BSpline(np.array(knots, dtype=float), np.array(points, dtype=float), int(degree),
                   extrapolate=False)


def from_scipy(spline):
    """A :class:`BSplineCurve` with the knots, coefficients and degree of the scipy
    ``BSpline`` ``spline`` (2 or 3 columns of coefficients; extra trailing rows ignored, as
    scipy does). Its domain is scipy's base interval [t[k], t[n]].

    Raises ValueError for coefficients that are not one row of 2 or 3 numbers per control
    point, or too few of them; camber's own checks name any bad knot or value.
    """
    t = _real(spline.t, "knots")
    c = _real(spline.c, "coefficients")
    k = int(spline.k)
    n = len(t) - k - 1
    if c.ndim != 2 or c.shape[1] not in (2, 3):
        raise ValueError(
            f"the spline's coefficients have shape {c.shape}; camber curves need one row of "
            "2 or 3 coordinates per control point"
        )
    if n < 1 or c.shape[0] < n:
        raise ValueError(
            f"{len(t)} knots of degree {k} need {max(n, 1)} coefficient rows, "
            f"the spline has {c.shape[0]}"
        )
    return BSplineCurve(k, t.tolist(), c[:n])


def to_geomdl(curve):
    """The curve as ``geomdl.BSpline.Curve`` (or ``geomdl.NURBS.Curve`` for a NURBS curve),
    made with ``normalize_kv=False`` so that its parameters are camber's.

    Raises TypeError for a curve without one knot vector (Hermite, composite).
    """
    from geomdl import BSpline, NURBS

    degree, knots, points, weights = _knotted(curve)
    out = (NURBS.Curve if weights is not None else BSpline.Curve)(normalize_kv=False)
    out.degree = int(degree)
    out.ctrlpts = np.asarray(points, dtype=float).tolist()
    if weights is not None:
        out.weights = np.asarray(weights, dtype=float).tolist()
    out.knotvector = np.asarray(knots, dtype=float).tolist()
    return out


def from_geomdl(curve):
    """A :class:`BSplineCurve`, or a :class:`NurbsCurve` when the geomdl curve has weights
    that are not all 1, with its degree, knot vector and (unweighted) control points.

    Raises ValueError for a geomdl curve of dimension other than 2 or 3.
    """
    degree = int(curve.degree)
    knots = _real(curve.knotvector, "knots").tolist()
    points = _real(curve.ctrlpts, "control points")
    if points.ndim != 2 or points.shape[1] not in (2, 3):
        raise ValueError(
            f"the geomdl curve's control points have shape {points.shape}; camber curves "
            "have 2 or 3 coordinates"
        )
    weights = getattr(curve, "weights", None)
    if weights is not None:
        weights = _real(weights, "weights")
        if np.any(weights != 1.0):
            return NurbsCurve(degree, knots, points, weights.tolist())
    return BSplineCurve(degree, knots, points)
