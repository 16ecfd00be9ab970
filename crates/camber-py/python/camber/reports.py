"""Solve reports as Python objects.

``Sketch.solve`` returns a :class:`SolveReport`. It wraps the library's report (its serde form:
``{"components": [{"component": {"entities", "constraints"}, "report": {"status", "solver",
"reason", "iterations", "residuals", "displacement_norm", "rank", "dof", "redundant",
"conflicting", "elapsed"}}], "warnings": [...]}``) and adds the views a script needs most.
"""


class SolveReport:
    """The outcome of a solve: one report per component solved, and the warnings."""

    def __init__(self, data):
        self.data = data

    @property
    def components(self):
        """One dict per component solved: {"component": {...}, "report": {...}}."""
        return self.data["components"]

    @property
    def warnings(self):
        """Near-degenerate input found before the solve: dicts with "kind" and "message"."""
        return self.data["warnings"]

    @property
    def residuals(self):
        """The largest absolute residual of every constraint solved, by constraint id."""
        out = {}
        for c in self.components:
            for r in c["report"]["residuals"]:
                out[r["constraint"]] = r["max_abs"]
        return out

    @property
    def max_residual(self):
        """The largest residual over every constraint (0.0 when nothing was solved)."""
        return max(self.residuals.values(), default=0.0)

    @property
    def dof(self):
        """Degrees of freedom left, summed over the components solved."""
        return sum(c["report"]["dof"] for c in self.components)

    @property
    def status(self):
        """The status of each component solved ("solved", "already_satisfied", …)."""
        return [c["report"]["status"] for c in self.components]

    @property
    def solvers(self):
        """The solver each component used."""
        return [c["report"]["solver"] for c in self.components]

    @property
    def elapsed(self):
        """Solver time in seconds, summed over the components."""
        return sum(c["report"]["elapsed"] for c in self.components)

    def as_dict(self):
        """The report as plain data (what ``json.dumps`` takes)."""
        return self.data

    def __repr__(self):
        return (
            f"<SolveReport: {len(self.components)} component(s), status {self.status}, "
            f"DOF {self.dof}, max residual {self.max_residual:.3g}>"
        )
