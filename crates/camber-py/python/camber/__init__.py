"""camber: geometric constraints on parametric curves, from Python.

Curves (Bézier, B-spline, NURBS, Hermite) from numpy arrays with vectorised evaluation,
sketches with every constraint kind, solve reports with per-constraint residuals, the DOF
analysis, drag sessions, iterative displacement, custom constraints differentiated exactly
with dual numbers, and batch solving in parallel. See docs/python.md.
"""

from camber._native import (
    BezierCurve,
    BSplineCurve,
    CamberError,
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
    creased_face_case,
    deform_case_to_g1,
    solve_many,
)
from camber.reports import SolveReport

__all__ = [
    "BezierCurve",
    "BSplineCurve",
    "CamberError",
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
    "creased_face_case",
    "deform_case_to_g1",
    "solve_many",
]
