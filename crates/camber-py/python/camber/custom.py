"""Helpers for custom constraints written in Python (see docs/python.md).

A residual is a function ``residual(x)`` of a list of numbers returning a list of ``dim``
numbers. It must use only arithmetic and functions that accept dual numbers: ``+ - * / **``,
numpy's ufuncs on scalars (``np.sin(x[0])``, ``np.sqrt``, ``np.exp`` …, which call the dual
number's own method), or the methods of the numbers (``x[0].sin()``). ``abs`` and the ``math``
module do not accept dual numbers.
"""


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
