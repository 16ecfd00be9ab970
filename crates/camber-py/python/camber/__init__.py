"""camber: geometric constraints on parametric curves, from Python.

Curves (Bézier, B-spline, NURBS, Hermite, and composite chains of them) from numpy arrays with vectorised evaluation,
sketches with every constraint kind, solve reports with per-constraint residuals, the DOF
analysis, drag sessions, iterative displacement, custom constraints differentiated exactly
with dual numbers, and batch solving in parallel. Curve operations: arc length and the
arc-length map, extension, fitting (interpolate, approximate, fit_to_tolerance), knot
removal, degree reduction, curve-curve intersection and distance, offsets; conversions to and
from scipy and geomdl in ``camber.interop``. See docs/python.md.
"""

from camber._native import (
    ArcLengthMap,
    BezierCurve,
    BSplineCurve,
    CamberError,
    CompositeCurve,
    Curve,
    DragSession,
    FileError,
    GeometryError,
    HermiteCurve,
    NurbsCurve,
    Sketch,
    SketchError,
    SolveError,
    SurfaceError,
    approximate,
    creased_face_case,
    deform_case_to_g1,
    fit_to_tolerance,
    interpolate,
    read_dxf,
    solve_many as _solve_many,
    write_dxf,
)
from camber.reports import SolveReport


def solve_many(items, threads=None, parameters=None):
    """Solves sketches in parallel, the GIL released (see ``camber._native.solve_many``).

    ``parameters`` turns it into a sweep of one sketch: a dict of equally long arrays (or a
    pandas DataFrame), one column per parameter; the result is one dict per row.
    """
    if parameters is not None:
        if hasattr(parameters, "columns"):  # a pandas DataFrame
            parameters = {str(c): parameters[c] for c in parameters.columns}
        parameters = {str(k): [float(v) for v in vals] for k, vals in dict(parameters).items()}
    return _solve_many(items, threads=threads, parameters=parameters)


__all__ = [
    "read_dxf",
    "write_dxf",
    "ArcLengthMap",
    "BezierCurve",
    "BSplineCurve",
    "CamberError",
    "CompositeCurve",
    "Curve",
    "DragSession",
    "FileError",
    "GeometryError",
    "HermiteCurve",
    "NurbsCurve",
    "Sketch",
    "SketchError",
    "SolveError",
    "SolveReport",
    "SurfaceError",
    "approximate",
    "creased_face_case",
    "deform_case_to_g1",
    "fit_to_tolerance",
    "interpolate",
    "solve_many",
]
