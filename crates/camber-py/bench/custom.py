"""Cost of a custom constraint written in Python, per evaluation: the residual with floats,
its exact Jacobian (one num_dual.jacobian call), values + Jacobian + weighted Hessian as a solve
asks for them (camber._native._custom_derivatives), and a whole solve of a point held at a
distance by a Python residual against the built-in ``distance`` kind.

    python crates/camber-py/bench/custom.py
"""

import timeit

import numpy as np
import num_dual

import camber
from camber._native import _custom_derivatives


def residual(x):
    return [
        x[0] * x[1] - np.sin(x[2]) + x[3] ** 3,
        np.exp(0.1 * x[0]) / (2.0 + x[1] * x[1]) + np.sqrt(1.0 + x[2] * x[2]) * x[3],
    ]


def per_call(stmt, number=2000):
    return min(timeit.repeat(stmt, number=number, repeat=5)) / number


def distance_sketch(custom):
    s = camber.Sketch()
    p, q = s.add_point([0, 0]), s.add_point([3, 1])
    s.add_constraint("fixed", target={"point": {"point": p}})
    if custom:
        s.add_custom(lambda x: [(x[2] - x[0]) ** 2 + (x[3] - x[1]) ** 2 - 4.0], [p, q], dim=1)
    else:
        s.add_constraint("distance", a={"point": p}, b={"point": q}, distance=2.0)
    return s


def main():
    x = [0.3, -0.7, 1.1, 0.4]
    print(f"residual with floats:            {per_call(lambda: residual(x)) * 1e6:7.1f} us")
    print(f"num_dual.jacobian (exact J):     {per_call(lambda: num_dual.jacobian(residual, x)) * 1e6:7.1f} us")
    full = per_call(lambda: _custom_derivatives(residual, [2, 1, 1], x, 2, [1.0, 1.0]), 500)
    print(f"values + J + Hessian via camber: {full * 1e6:7.1f} us")
    for custom in (False, True):
        t = per_call(lambda: distance_sketch(custom).solve(), 200)
        print(f"build + solve, {'custom (Python)' if custom else 'built-in distance'}: {t * 1e6:7.1f} us")


if __name__ == "__main__":
    main()
