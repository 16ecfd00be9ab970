//! The residual of a custom constraint: the user's [`CustomResidual`] over typed arguments, a
//! plain [`camber_solve::Residual`] over point and scalar blocks, or a boxed
//! [`camber_solve::DynResidual`] with declared argument kinds; and their erasure into the one
//! object a [`super::Custom`] keeps, which makes the residual of each build.

use std::any::Any;
use std::sync::Arc;

use camber_solve::{DynResidual, Residual, Scalar};

use super::args::{ArgKind, Args, Layout};

/// A custom constraint's residual over typed arguments, written once generically over the
/// scalar type; its exact Jacobian comes from dual numbers like every built-in's.
///
/// ```
/// use camber_sketch::constraints::custom::{Arg, ArgKind, Args, Custom, CustomResidual};
/// use camber_sketch::{PointRef, Sketch};
/// use camber_geom::BezierCurve2;
/// use camber_solve::Scalar;
/// use nalgebra::Point2;
/// /// The curve passes through the point at its own free parameter s: C(s) − P = 0.
/// #[derive(Debug)]
/// struct Through;
/// impl CustomResidual for Through {
///     fn name(&self) -> &str { "through" }
///     fn dim(&self) -> usize { 2 }
///     fn arg_kinds(&self) -> Vec<ArgKind> { vec![ArgKind::Curve, ArgKind::Point, ArgKind::Scalar] }
///     fn eval<T: Scalar>(&self, a: &Args<'_, T>, out: &mut [T]) {
///         let (c, p) = (a.curve(0).point(a.scalar(2)), a.point(1));
///         out[0] = c[0] - p[0];
///         out[1] = c[1] - p[1];
///     }
/// }
/// let mut s = Sketch::new();
/// let c = s.add_bezier(BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 0.0)])?)?;
/// let p = s.add_point(Point2::new(1.0, 1.0))?;
/// let id = s.add_constraint(Custom::with_args(Through, vec![Arg::Curve(c), Arg::Point(PointRef::Point(p)), Arg::Param(0.5)]))?;
/// s.solve()?;
/// let Some(Arg::Param(u)) = s.constraint(id)?.as_custom().map(|k| k.args()[2]) else { panic!() };
/// let (on, q) = (s.curve_point(c, u)?, s.point(PointRef::Point(p))?);
/// assert!((on - q).norm() < 1e-10);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
pub trait CustomResidual: std::fmt::Debug + Send + Sync + 'static {
    /// A short name used in reports.
    fn name(&self) -> &str;
    /// Rows it contributes.
    fn dim(&self) -> usize;
    /// The kind of each argument it reads, in order (checked against the constraint's
    /// arguments when it is added).
    fn arg_kinds(&self) -> Vec<ArgKind>;
    /// Writes the residual into `out` (`dim()` entries).
    fn eval<T: Scalar>(&self, args: &Args<'_, T>, out: &mut [T]);
    /// Whether the residual is affine in the unknowns it reads.
    fn is_affine(&self) -> bool {
        false
    }
}

/// The residual of one build: a user residual with its arguments' places.
#[derive(Debug)]
struct Built<R> {
    inner: Arc<R>,
    layout: Layout,
}

impl<R: CustomResidual> Residual for Built<R> {
    fn name(&self) -> &str {
        self.inner.name()
    }
    fn dim(&self) -> usize {
        self.inner.dim()
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.layout.sizes.clone())
    }
    fn is_affine(&self) -> bool {
        self.inner.is_affine()
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        self.inner.eval(
            &Args {
                x,
                layout: &self.layout,
            },
            out,
        );
    }
}

/// A plain [`camber_solve::Residual`] over point (and scalar) blocks as a custom residual.
#[derive(Debug)]
pub(super) struct Plain<R>(pub(super) R);

impl<R: Residual> CustomResidual for Plain<R> {
    fn name(&self) -> &str {
        self.0.name()
    }
    fn dim(&self) -> usize {
        self.0.dim()
    }
    fn arg_kinds(&self) -> Vec<ArgKind> {
        // Checked to be Some(…) of 1s and 2s before the constraint is accepted.
        self.0
            .block_sizes()
            .unwrap_or_default()
            .iter()
            .map(|n| if *n == 2 { ArgKind::Point } else { ArgKind::Scalar })
            .collect()
    }
    fn eval<T: Scalar>(&self, args: &Args<'_, T>, out: &mut [T]) {
        self.0.eval(args.blocks(), out);
    }
    fn is_affine(&self) -> bool {
        self.0.is_affine()
    }
}

/// The object-safe face of a user residual: it makes the residual of one build.
pub(super) trait Erased: std::fmt::Debug + Send + Sync {
    fn name(&self) -> &str;
    /// The declared argument kinds (`None`: a plain residual that declares no block sizes).
    fn arg_kinds(&self) -> Option<Vec<ArgKind>>;
    fn build(&self, layout: Layout) -> Arc<dyn DynResidual>;
    fn as_any(&self) -> &dyn Any;
}

#[derive(Debug)]
pub(super) struct Typed<R>(pub(super) Arc<R>);

impl<R: CustomResidual> Erased for Typed<R> {
    fn name(&self) -> &str {
        self.0.name()
    }
    fn arg_kinds(&self) -> Option<Vec<ArgKind>> {
        Some(self.0.arg_kinds())
    }
    fn build(&self, layout: Layout) -> Arc<dyn DynResidual> {
        Arc::new(Built {
            inner: self.0.clone(),
            layout,
        })
    }
    fn as_any(&self) -> &dyn Any {
        &*self.0
    }
}

#[derive(Debug)]
pub(super) struct PlainErased<R>(pub(super) Arc<Plain<R>>);

impl<R: Residual> Erased for PlainErased<R> {
    fn name(&self) -> &str {
        self.0 .0.name()
    }
    fn arg_kinds(&self) -> Option<Vec<ArgKind>> {
        let sizes = self.0 .0.block_sizes()?;
        sizes
            .iter()
            .all(|n| *n == 1 || *n == 2)
            .then(|| self.0.arg_kinds())
    }
    fn build(&self, layout: Layout) -> Arc<dyn DynResidual> {
        Arc::new(Built {
            inner: self.0.clone(),
            layout,
        })
    }
    fn as_any(&self) -> &dyn Any {
        &self.0 .0
    }
}

/// A boxed residual with its argument kinds declared (see [`super::Custom::boxed`]): the
/// residual reads the blocks of its arguments in order, as a plain residual does, and gives
/// its own derivatives through the object-safe face.
#[derive(Debug)]
pub(super) struct Boxed {
    pub(super) inner: Arc<dyn DynResidual>,
    pub(super) kinds: Vec<ArgKind>,
}

impl Erased for Boxed {
    fn name(&self) -> &str {
        self.inner.name()
    }
    fn arg_kinds(&self) -> Option<Vec<ArgKind>> {
        Some(self.kinds.clone())
    }
    fn build(&self, layout: Layout) -> Arc<dyn DynResidual> {
        Arc::new(BoxedBuild {
            inner: self.inner.clone(),
            sizes: layout.sizes,
        })
    }
    fn as_any(&self) -> &dyn Any {
        self.inner.as_any()
    }
}

/// The residual of one build of a [`Boxed`] one: the same object, with the block sizes of the
/// build's arguments (a curve gives one block per control point).
#[derive(Debug)]
struct BoxedBuild {
    inner: Arc<dyn DynResidual>,
    sizes: Vec<usize>,
}

impl DynResidual for BoxedBuild {
    fn name(&self) -> &str {
        self.inner.name()
    }
    fn dim(&self) -> usize {
        self.inner.dim()
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.sizes.clone())
    }
    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        sizes == self.sizes.as_slice()
    }
    fn is_affine(&self) -> bool {
        self.inner.is_affine()
    }
    fn values(&self, x: &[&[f64]], out: &mut [f64]) -> camber_solve::Result<()> {
        self.inner.values(x, out)
    }
    fn jacobian(&self, x: &[&[f64]], values: &mut [f64], jac: &mut [f64]) -> camber_solve::Result<()> {
        self.inner.jacobian(x, values, jac)
    }
    fn jacobian_active(
        &self,
        x: &[&[f64]],
        active: &[bool],
        values: &mut [f64],
        jac: &mut [f64],
    ) -> camber_solve::Result<()> {
        self.inner.jacobian_active(x, active, values, jac)
    }
    fn weighted_hessian(
        &self,
        x: &[&[f64]],
        weights: &[f64],
        active: &[bool],
        out: &mut [f64],
    ) -> camber_solve::Result<bool> {
        self.inner.weighted_hessian(x, weights, active, out)
    }
    fn as_any(&self) -> &dyn Any {
        self.inner.as_any()
    }
}
