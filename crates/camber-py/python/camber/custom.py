"""Helpers for custom constraints written in Python (see docs/python.md).

A residual is a function ``residual(x)`` of a list of numbers returning a list of ``dim``
numbers. It must use only arithmetic and functions that accept dual numbers: ``+ - * / **``,
numpy's ufuncs on scalars (``np.sin(x[0])``, ``np.sqrt``, ``np.exp`` …, which call the dual
number's own method), or the methods of the numbers (``x[0].sin()``). ``abs`` and the ``math``
module do not accept dual numbers.
"""


def rows(func):
    """``func`` returning a list: a residual of one row may return its number alone (a float or
    a dual number); a list, tuple or numpy array passes through as a list."""

    def listed(x):
        out = func(x)
        if isinstance(out, (list, tuple)):
            return list(out)
        try:
            return list(out)
        except TypeError:
            return [out]

    listed.__name__ = getattr(func, "__name__", "residual")
    return listed


def row(func, i):
    """The i-th component of a vector residual, as a scalar function (for num_dual.hessian)."""

    def component(x):
        return func(x)[i]

    return component


def jacobian(func, x):
    """Values and exact Jacobian of ``func`` at ``x``, as camber computes them for a custom
    constraint: one call of ``func`` with num-dual's vector dual numbers."""
    import num_dual

    values, jac = num_dual.jacobian(func, [float(v) for v in x])
    return values, jac


def finite_difference_jacobian(func, x, h=1e-6):
    """Central differences of ``func`` at ``x`` (for checking a residual; camber never uses
    them)."""
    x = [float(v) for v in x]
    rows = len(func(x))
    jac = [[0.0] * len(x) for _ in range(rows)]
    for k in range(len(x)):
        up, down = list(x), list(x)
        up[k] += h
        down[k] -= h
        fu, fd = func(up), func(down)
        for i in range(rows):
            jac[i][k] = (float(fu[i]) - float(fd[i])) / (2 * h)
    return jac


def real(v):
    """The real part of a float or of a (possibly nested) num-dual number."""
    while True:
        try:
            return float(v)
        except TypeError:
            v = v.value


def control_points(x, start, count):
    """The ``count`` control points a curve argument puts into ``x`` from index ``start``
    (x₀, y₀, x₁, y₁, …), as a list of [x, y] pairs of (dual) numbers."""
    return [[x[start + 2 * j], x[start + 2 * j + 1]] for j in range(count)]


def curve_point(curve, points, u):
    """C(u) of a sketch curve whose control points are ``points`` (from
    :func:`control_points`, so dual numbers inside a residual), with the degree, knots and
    weights of ``curve`` (a camber curve object, e.g. ``sketch.curve(id)``, read before the
    solve). ``u`` may be a dual number too (an own parameter); it is clamped to the domain.
    Written with arithmetic only (de Boor's algorithm on homogeneous points), so dual numbers
    pass through and the derivatives stay exact."""
    kind = type(curve).__name__
    if kind == "BezierCurve":
        p = len(points) - 1
        knots = [0.0] * (p + 1) + [1.0] * (p + 1)
        weights = None
    elif kind in ("BSplineCurve", "NurbsCurve"):
        p = curve.degree
        knots = [float(k) for k in curve.knots]
        weights = [float(w) for w in curve.weights] if kind == "NurbsCurve" else None
    else:
        raise TypeError(f"curve_point: no control points to evaluate on a {kind}")
    n = len(points)
    if len(knots) != n + p + 1:
        raise ValueError(f"curve_point: {n} control points do not fit {len(knots)} knots")
    a, b = knots[p], knots[n]
    ur = min(max(real(u), a), b)
    if real(u) < a or real(u) > b:
        u = ur
    # The span k with knots[k] <= u < knots[k + 1] (the last non-empty span at b).
    k = p
    while k < n - 1 and knots[k + 1] <= ur:
        k += 1
    w = weights or [1.0] * n
    d = [[points[k - p + j][0] * w[k - p + j], points[k - p + j][1] * w[k - p + j], w[k - p + j]]
         for j in range(p + 1)]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = k - p + j
            alpha = (u - knots[i]) / (knots[i + p - r + 1] - knots[i])
            d[j] = [(1 - alpha) * d[j - 1][c] + alpha * d[j][c] for c in range(3)]
    return [d[p][0] / d[p][2], d[p][1] / d[p][2]]
