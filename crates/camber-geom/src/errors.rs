//! The error type of camber-geom: one enum whose variants carry the offending index and value.
//!
//! Values are reported as `f64` (the real part, for dual numbers) so that errors are the same
//! type whatever scalar the computation ran in.

/// Everything that can be wrong with geometric input.
///
/// ```
/// use camber_geom::{Error, KnotVector};
/// let err = KnotVector::<f64>::try_new(vec![0.0, 1.0, 0.5]).unwrap_err();
/// assert_eq!(err, Error::DecreasingKnots { index: 2, value: 0.5, previous: 1.0 });
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A number that must be finite is NaN or infinite.
    #[error("{what} {index} is not finite ({value})")]
    NonFinite {
        /// What the number is ("knot", "control point coordinate", "weight", "parameter", …).
        what: &'static str,
        /// Its index in the input (0 where there is a single value).
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A knot is smaller than the knot before it.
    #[error("knot {index} ({value}) is smaller than the knot before it ({previous})")]
    DecreasingKnots {
        /// Index of the offending knot.
        index: usize,
        /// Its value.
        value: f64,
        /// The value of the knot before it.
        previous: f64,
    },
    /// The knot count does not equal control points + degree + 1.
    #[error(
        "{control_points} control points of degree {degree} need {expected} knots, found {found}"
    )]
    KnotCount {
        /// Knots needed.
        expected: usize,
        /// Knots given.
        found: usize,
        /// Degree of the curve.
        degree: usize,
        /// Number of control points.
        control_points: usize,
    },
    /// Fewer control points than the degree requires (at least degree + 1).
    #[error("degree {degree} needs at least {needed} control points, found {found}")]
    TooFewControlPoints {
        /// Degree of the curve.
        degree: usize,
        /// Control points needed.
        needed: usize,
        /// Control points given.
        found: usize,
    },
    /// A knot vector too short to carry any basis function of the degree asked for.
    #[error("a knot vector of {found} knots is too short for degree {degree} (needs {needed})")]
    TooFewKnots {
        /// Degree asked for.
        degree: usize,
        /// Knots needed.
        needed: usize,
        /// Knots given.
        found: usize,
    },
    /// The parametric domain [min, max] has zero length.
    #[error("the parametric domain [{min}, {max}] is empty")]
    EmptyDomain {
        /// Start of the domain.
        min: f64,
        /// End of the domain.
        max: f64,
    },
    /// A weight is zero or negative.
    #[error("weight {index} is not positive ({value})")]
    NonPositiveWeight {
        /// Index of the weight.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// The number of weights differs from the number of control points.
    #[error("expected {expected} weights (one per control point), found {found}")]
    WeightCount {
        /// Weights needed.
        expected: usize,
        /// Weights given.
        found: usize,
    },
    /// A curve parameter lies outside the curve's domain.
    #[error("parameter {value} is outside the domain [{min}, {max}]")]
    ParameterOutsideDomain {
        /// The parameter.
        value: f64,
        /// Start of the domain.
        min: f64,
        /// End of the domain.
        max: f64,
    },
    /// An interval [start, end] that must have start < end does not.
    #[error("the interval [{start}, {end}] is empty or reversed")]
    InvalidInterval {
        /// Start of the interval.
        start: f64,
        /// End of the interval.
        end: f64,
    },
    /// Inserting a knot would raise its multiplicity above the degree.
    #[error(
        "inserting knot {value} {times} times onto multiplicity {multiplicity} exceeds degree {degree}"
    )]
    KnotMultiplicity {
        /// The knot value.
        value: f64,
        /// Its current multiplicity.
        multiplicity: usize,
        /// How many insertions were asked for.
        times: usize,
        /// Degree of the curve.
        degree: usize,
    },
    /// A point given as a list of coordinates has the wrong number of them.
    #[error("point {index} has {found} coordinates, expected {expected}")]
    Dimension {
        /// Index of the point.
        index: usize,
        /// Coordinates expected.
        expected: usize,
        /// Coordinates given.
        found: usize,
    },
    /// A direction (of a line, a segment, a tangent) has zero length.
    #[error("the {what} has zero length")]
    ZeroLength {
        /// Which direction ("line direction", "segment", …).
        what: &'static str,
    },
    /// A circle or arc radius is zero or negative.
    #[error("radius {value} is not positive")]
    NonPositiveRadius {
        /// The radius.
        value: f64,
    },
    /// A semi-axis of an ellipse or elliptic arc is zero or negative.
    ///
    /// ```
    /// use camber_geom::{Ellipse, Error};
    /// use nalgebra::Point2;
    /// let err = Ellipse::try_new(Point2::new(0.0, 0.0), 2.0, -0.5, 0.0).unwrap_err();
    /// assert_eq!(err, Error::NonPositiveSemiAxis { axis: "b", value: -0.5 });
    /// ```
    #[error("semi-axis {axis} of the ellipse ({value}) is not positive")]
    NonPositiveSemiAxis {
        /// Which semi-axis: "a" (along the rotated x axis) or "b".
        axis: &'static str,
        /// Its value.
        value: f64,
    },
    /// A circular arc whose sweep, end angle − start angle reduced modulo 2π, is zero: its
    /// start and end coincide (a whole turn is a circle, not an arc).
    ///
    /// ```
    /// use camber_geom::{CircularArc, Error};
    /// use nalgebra::Point2;
    /// let err = CircularArc::try_new(Point2::new(0.0, 0.0), 1.0, 0.5, 0.5).unwrap_err();
    /// assert_eq!(err, Error::DegenerateSweep { start: 0.5, end: 0.5 });
    /// ```
    #[error("the arc from angle {start} to angle {end} sweeps no angle (modulo 2π)")]
    DegenerateSweep {
        /// The start angle (radians).
        start: f64,
        /// The end angle (radians).
        end: f64,
    },
    /// An angle so large that f64 no longer resolves it (its spacing between neighbouring
    /// values would exceed 1e-12 rad).
    ///
    /// ```
    /// use camber_geom::{arc::MAX_ANGLE, CircularArc, Error};
    /// use nalgebra::Point2;
    /// let err = CircularArc::try_new(Point2::new(0.0, 0.0), 1.0, 0.0, 1e300).unwrap_err();
    /// assert_eq!(err, Error::AngleTooLarge { what: "arc end angle", value: 1e300, max: MAX_ANGLE });
    /// ```
    #[error("{what} {value:e} rad is larger in magnitude than {max:.1} rad")]
    AngleTooLarge {
        /// Which angle.
        what: &'static str,
        /// Its value (radians).
        value: f64,
        /// The largest magnitude accepted.
        max: f64,
    },
    /// A count that must be at least one is zero (segments of a subdivision, curves of a chain).
    #[error("{what} must be at least 1, found 0")]
    ZeroCount {
        /// What is counted.
        what: &'static str,
    },
    /// A curve of one fixed degree was expected (for example a cubic Bézier curve to convert to
    /// Hermite form) and a curve of another degree was given.
    ///
    /// ```
    /// use camber_geom::{BezierCurve, Error, HermiteCurve};
    /// use nalgebra::Point2;
    /// let line = BezierCurve::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)])?;
    /// let err = HermiteCurve::from_bezier(&line).unwrap_err();
    /// assert_eq!(err, Error::DegreeMismatch { expected: 3, found: 1 });
    /// # Ok::<(), Error>(())
    /// ```
    #[error("expected a curve of degree {expected}, found degree {found}")]
    DegreeMismatch {
        /// The degree required.
        expected: usize,
        /// The degree given.
        found: usize,
    },
    /// A B-spline or NURBS curve of degree 0 in a file: piecewise constant, with jumps at its
    /// knots, so not a curve that can be constrained or drawn. The library types accept
    /// degree 0 ([`BSplineCurve::try_new`](crate::BSplineCurve::try_new)); their file forms
    /// (serde) and sketches do not.
    ///
    /// ```
    /// use camber_geom::BSplineCurve2;
    /// let text = r#"{"degree": 0, "knots": [0, 1, 2], "control_points": [[0, 0], [1, 0]]}"#;
    /// let err = serde_json::from_str::<BSplineCurve2<f64>>(text).unwrap_err();
    /// assert!(err.to_string().starts_with("degree 0 is not supported"));
    /// ```
    #[error("degree 0 is not supported (a B-spline needs degree 1 or more)")]
    DegreeZero,
    /// A knot repeated more than degree + 1 times: the basis functions around it vanish.
    ///
    /// ```
    /// use camber_geom::{Error, KnotVector};
    /// let k = KnotVector::try_new(vec![0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0])?;
    /// assert_eq!(
    ///     k.check_for(1, 5).unwrap_err(),
    ///     Error::KnotMultiplicityTooHigh { value: 0.5, multiplicity: 3, max: 2 }
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    #[error("knot {value} is repeated {multiplicity} times, more than degree + 1 = {max}")]
    KnotMultiplicityTooHigh {
        /// The knot value.
        value: f64,
        /// How many times it occurs.
        multiplicity: usize,
        /// The most allowed: degree + 1.
        max: usize,
    },
    /// Knots spread so wide that their differences overflow f64 (`[-1e308, …, 1e308]`): the
    /// basis functions divide by those differences and would come out wrong.
    ///
    /// ```
    /// use camber_geom::{Error, KnotVector};
    /// let err = KnotVector::try_new(vec![-1e308, -1e308, 1e308, 1e308]).unwrap_err();
    /// assert_eq!(err, Error::KnotRangeTooWide { first: -1e308, last: 1e308 });
    /// ```
    #[error("the knots span [{first:e}, {last:e}], wider than f64 can subtract")]
    KnotRangeTooWide {
        /// The first knot.
        first: f64,
        /// The last knot.
        last: f64,
    },
    /// NURBS weights whose largest and smallest differ by more than
    /// [`MAX_WEIGHT_RATIO`](crate::nurbs::MAX_WEIGHT_RATIO): the small ones would vanish
    /// next to the large ones in f64.
    ///
    /// ```
    /// use camber_geom::{Error, KnotVector, NurbsCurve2};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::clamped_uniform(2, 3)?;
    /// let points = vec![Point2::new(1.0, 0.0), Point2::new(1.0, 1.0), Point2::new(0.0, 1.0)];
    /// let err = NurbsCurve2::try_new(2, knots, points, vec![1e-300, 1e300, 1e-300]).unwrap_err();
    /// assert_eq!(err, Error::WeightRatio { smallest: 1e-300, largest: 1e300, max: 1e15 });
    /// # Ok::<(), Error>(())
    /// ```
    #[error(
        "the weights range from {smallest:e} to {largest:e}, a ratio above {max:e} that f64 \
         cannot carry (scale them closer together)"
    )]
    WeightRatio {
        /// The smallest weight.
        smallest: f64,
        /// The largest weight.
        largest: f64,
        /// The largest ratio allowed.
        max: f64,
    },
    /// A reparameterization onto an interval where the knots cannot be represented: their
    /// span would overflow, or distinct knots would round onto one value (the shape would
    /// change).
    ///
    /// ```
    /// use camber_geom::{Error, KnotVector};
    /// let k = KnotVector::<f64>::clamped_uniform(1, 3)?;
    /// assert_eq!(
    ///     k.reparameterized(1, -1e308, 1e308).unwrap_err(),
    ///     Error::ReparamNotRepresentable { start: -1e308, end: 1e308 }
    /// );
    /// # Ok::<(), Error>(())
    /// ```
    #[error(
        "the interval [{start:e}, {end:e}] cannot carry the knots in f64 (their span would \
         overflow or distinct knots would merge)"
    )]
    ReparamNotRepresentable {
        /// Start of the interval asked for.
        start: f64,
        /// End of the interval asked for.
        end: f64,
    },
    /// A spline degree (given, or reached by degree elevation) above
    /// [`MAX_DEGREE`](crate::knots::MAX_DEGREE): the basis tables grow like the square of the
    /// degree, so an absurd degree from a file would exhaust memory instead of failing.
    ///
    /// ```
    /// use camber_geom::{Error, KnotVector};
    /// use camber_geom::knots::MAX_DEGREE;
    /// let err = KnotVector::<f64>::clamped_uniform(MAX_DEGREE + 1, MAX_DEGREE + 2).unwrap_err();
    /// assert_eq!(err, Error::DegreeTooHigh { degree: MAX_DEGREE + 1, max: MAX_DEGREE });
    /// ```
    #[error("degree {degree} is above the largest supported degree {max}")]
    DegreeTooHigh {
        /// The degree asked for (saturated at `usize::MAX` when the sum overflowed).
        degree: usize,
        /// The largest degree supported.
        max: usize,
    },
    /// A tolerance (arc length, fitting, knot removal, offset, intersection) that must be
    /// positive is zero or negative.
    ///
    /// ```
    /// use camber_geom::arc_length::arc_length;
    /// use camber_geom::{BezierCurve2, Error};
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)])?;
    /// assert_eq!(arc_length(&c, 0.0).unwrap_err(), Error::NonPositiveTolerance { value: 0.0 });
    /// # Ok::<(), Error>(())
    /// ```
    #[error("tolerance {value} is not positive")]
    NonPositiveTolerance {
        /// The tolerance given.
        value: f64,
    },
    /// An arc length outside [0, length of the curve].
    ///
    /// ```
    /// use camber_geom::arc_length::parameter_at_length;
    /// use camber_geom::{BezierCurve2, Error};
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(2.0, 0.0)])?;
    /// assert!(matches!(parameter_at_length(&c, 3.0, 1e-12), Err(Error::LengthOutsideCurve { .. })));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("arc length {value} is outside the curve's length [0, {length}]")]
    LengthOutsideCurve {
        /// The arc length asked for.
        value: f64,
        /// The curve's length.
        length: f64,
    },
    /// An extension target that does not lie beyond the end it extends (a new start must be
    /// below the domain start, a new end above the domain end; a length must be positive).
    ///
    /// ```
    /// use camber_geom::extend::CurveEnd;
    /// use camber_geom::{BezierCurve2, Error};
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)])?;
    /// assert!(matches!(c.extrapolated(CurveEnd::End, 0.5), Err(Error::ExtensionInsideDomain { .. })));
    /// # Ok::<(), Error>(())
    /// ```
    #[error("extension target {value} does not lie beyond the domain [{min}, {max}]")]
    ExtensionInsideDomain {
        /// The target parameter (or length).
        value: f64,
        /// Start of the domain.
        min: f64,
        /// End of the domain.
        max: f64,
    },
    /// Fewer data points than an interpolation or fit of this degree needs.
    #[error("{found} data points are too few for degree {degree} (at least {needed})")]
    TooFewDataPoints {
        /// Degree of the curve asked for.
        degree: usize,
        /// Points needed.
        needed: usize,
        /// Points given.
        found: usize,
    },
    /// Two consecutive data points coincide, so chord-length or centripetal parameters are not
    /// defined (point `index` equals point `index` − 1).
    #[error("data point {index} coincides with the point before it")]
    CoincidentDataPoints {
        /// Index of the repeated point.
        index: usize,
    },
    /// A linear system of an interpolation or fit is singular (the data and knots do not
    /// determine the control points).
    #[error("the {what} system is singular")]
    SingularSystem {
        /// Which system ("interpolation", "least-squares").
        what: &'static str,
    },
    /// A fit cannot reach its tolerance: even the interpolant (or, at a joint of a split fit,
    /// the most knots the data carry) errs more, as for a tolerance below the rounding of the
    /// data.
    #[error("the fit reaches {reached:e}, not the tolerance {tolerance:e}")]
    ToleranceNotMet {
        /// The tolerance asked for.
        tolerance: f64,
        /// The smallest largest error found.
        reached: f64,
    },
    /// A fit is split at its first or last data point, where no piece could lie before or after.
    #[error("split point {index} is not inside the data (points 1 to {last} − 1)")]
    SplitPointAtEnd {
        /// The data index asked for.
        index: usize,
        /// The index of the last data point.
        last: usize,
    },
    /// A knot value that is not an interior knot of the curve.
    #[error("{value} is not an interior knot of the curve")]
    KnotNotFound {
        /// The value asked for.
        value: f64,
    },
    /// A search (curve–curve intersection) produced more candidates than its limit, as for
    /// curves that overlap along a stretch.
    #[error("more than {limit} candidate {what}: the curves may overlap")]
    TooManyCandidates {
        /// What was counted.
        what: &'static str,
        /// The limit.
        limit: usize,
    },
    /// An iterative or adaptive routine (quadrature, subdivision, root finding, fitting, knot
    /// removal, intersection, offsets) spent its work budget before it was done
    /// ([`crate::budget`]): the input asks for more work than the limit allows, usually a
    /// tolerance too tight for the curve's scale or a pathological curve.
    ///
    /// ```
    /// use camber_geom::arc_length::arc_length_with;
    /// use camber_geom::budget::Budget;
    /// use camber_geom::{BezierCurve2, Error};
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 3.0),
    ///     Point2::new(2.0, 0.0)])?;
    /// let err = arc_length_with(&c, 1e-9, &Budget::default().with_max_work(10)).unwrap_err();
    /// assert_eq!(err, Error::BudgetExhausted { operation: "arc length", limit: 10 });
    /// assert!(err.to_string().contains("arc length"));
    /// # Ok::<(), Error>(())
    /// ```
    #[error(
        "the {operation} ran out of its work budget ({limit} work units): loosen the tolerance \
         or raise the budget (Budget::with_max_work)"
    )]
    BudgetExhausted {
        /// The routine that stopped ("arc length", "curve intersection", …).
        operation: &'static str,
        /// The limit it had, in work units.
        limit: u64,
    },
    /// A routine stopped because the stop flag of its [`Budget`](crate::budget::Budget) was
    /// set (Ctrl-C in Python, a cancel button, a deadline).
    ///
    /// ```
    /// use std::sync::atomic::AtomicBool;
    /// use std::sync::Arc;
    /// use camber_geom::budget::Budget;
    /// use camber_geom::offset::offset_with;
    /// use camber_geom::{BezierCurve2, Error};
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 3.0),
    ///     Point2::new(2.0, 0.0)])?;
    /// let stop = Budget::default().with_stop(Arc::new(AtomicBool::new(true)));
    /// assert_eq!(offset_with(&c, 0.1, 1e-6, &stop).unwrap_err(), Error::Cancelled { operation: "offset" });
    /// # Ok::<(), Error>(())
    /// ```
    #[error("the {operation} was cancelled")]
    Cancelled {
        /// The routine that stopped.
        operation: &'static str,
    },
    /// A count or order (a derivative order, a number of samples or pieces) above what the
    /// routine supports: checked before anything is allocated for it.
    ///
    /// ```
    /// use camber_geom::curve::MAX_DERIVATIVE_ORDER;
    /// use camber_geom::{BezierCurve2, Error, ParametricCurve};
    /// use nalgebra::Point2;
    /// let c = BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)])?;
    /// let err = c.derivatives(0.5, 1 << 40).unwrap_err();
    /// assert_eq!(err, Error::TooLarge { what: "derivative order", value: 1 << 40, max: MAX_DERIVATIVE_ORDER });
    /// # Ok::<(), Error>(())
    /// ```
    #[error("{what} {value} is above the largest supported, {max}")]
    TooLarge {
        /// What was counted.
        what: &'static str,
        /// The value asked for.
        value: usize,
        /// The largest supported.
        max: usize,
    },
    /// Two curves coincide along a stretch, so their meeting points are not isolated: the
    /// point search ([`intersect_curves`](crate::queries::intersect_curves)) names the first
    /// stretch; [`intersect_curves_with_overlaps`](crate::queries::intersect_curves_with_overlaps)
    /// reports every stretch as parameter intervals.
    #[error(
        "the curves overlap along a stretch (the first on [{a_start}, {a_end}], the second from \
         {b_start} to {b_end}); ask for the intersections with overlaps to get them as intervals"
    )]
    CurvesOverlap {
        /// Start of the stretch on the first curve.
        a_start: f64,
        /// End of the stretch on the first curve.
        a_end: f64,
        /// The second curve's parameter at `a_start`.
        b_start: f64,
        /// The second curve's parameter at `a_end`.
        b_end: f64,
    },
    /// A split or knot insertion at a parameter so close to a domain end or an existing knot
    /// that the new knot span would be narrower than f64 can evaluate across (its width below
    /// [`min_span_width`](crate::knots::min_span_width) of the domain).
    ///
    /// ```
    /// use camber_geom::{BSplineCurve2, Error, KnotVector};
    /// use nalgebra::Point2;
    /// let knots = KnotVector::clamped_uniform(2, 3)?;
    /// let c = BSplineCurve2::try_new(2, knots, vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0),
    ///     Point2::new(2.0, 0.0)])?;
    /// assert!(matches!(c.split(5e-324), Err(Error::DegenerateSpan { .. })));
    /// # Ok::<(), Error>(())
    /// ```
    #[error(
        "parameter {value} would make a knot span {width:e} wide, narrower than the smallest \
         span f64 can evaluate across here ({min:e})"
    )]
    DegenerateSpan {
        /// The parameter asked for.
        value: f64,
        /// The width of the span it would create.
        width: f64,
        /// The smallest width allowed.
        min: f64,
    },
}

/// Result with camber-geom's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;
