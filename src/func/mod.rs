//! User functions (`function { … }`), compiled once to a small stack machine and run millions
//! of times (isosurfaces): no allocation and no tree walking per evaluation.
//!
//! A function is a program of [`Op`]s over its parameters (x, y, z by default). Declared
//! floats are folded in as constants when the function is compiled, as POV-Ray does; calls to
//! other declared functions run their programs; `internal(N)` is one of POV-Ray's built-in
//! functions (functions.inc names them `f_sphere`, `f_torus` …: [`Internal`]).

use glam::DVec3;
use std::sync::Arc;

mod internal;
pub mod spline;

pub use internal::Internal;

/// The deepest stack a function may need (deeper expressions are refused when compiled).
pub const MAX_STACK: usize = 64;

/// The deepest chain of functions calling functions (deeper chains are refused when
/// compiled, so that no evaluation runs out of stack).
pub const MAX_NESTING: usize = 64;

/// One-argument maths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Math1 {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sinh,
    Cosh,
    Tanh,
    Asinh,
    Acosh,
    Atanh,
    Abs,
    Radians,
    Degrees,
    Int,
    Floor,
    Ceil,
    Sqrt,
    Exp,
    Ln,
    Log,
    Sqr,
}

impl Math1 {
    fn apply(self, a: f64) -> f64 {
        use Math1::*;
        match self {
            Sin => a.sin(),
            Cos => a.cos(),
            Tan => a.tan(),
            Asin => a.asin(),
            Acos => a.acos(),
            Atan => a.atan(),
            Sinh => a.sinh(),
            Cosh => a.cosh(),
            Tanh => a.tanh(),
            Asinh => a.asinh(),
            Acosh => a.acosh(),
            Atanh => a.atanh(),
            Abs => a.abs(),
            Radians => a * std::f64::consts::PI / 180.0,
            Degrees => a * 180.0 / std::f64::consts::PI,
            Int => a.trunc(),
            Floor => a.floor(),
            Ceil => a.ceil(),
            Sqrt => a.sqrt(),
            Exp => a.exp(),
            Ln => a.ln(),
            Log => a.log10(),
            Sqr => a * a,
        }
    }

    /// The function a name calls, if it is one of these.
    pub fn named(name: &str) -> Option<Math1> {
        use Math1::*;
        Some(match name {
            "sin" => Sin,
            "cos" => Cos,
            "tan" => Tan,
            "asin" => Asin,
            "acos" => Acos,
            "atan" => Atan,
            "sinh" => Sinh,
            "cosh" => Cosh,
            "tanh" => Tanh,
            "asinh" => Asinh,
            "acosh" => Acosh,
            "atanh" => Atanh,
            "abs" => Abs,
            "radians" => Radians,
            "degrees" => Degrees,
            "int" => Int,
            "floor" => Floor,
            "ceil" => Ceil,
            "sqrt" => Sqrt,
            "exp" => Exp,
            "ln" => Ln,
            "log" => Log,
            "sqr" => Sqr,
            _ => return None,
        })
    }
}

/// Two-argument maths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Math2 {
    Atan2,
    Pow,
    /// `mod(a, b)`: C's fmod.
    Mod,
    /// `div(a, b)`: the truncated quotient.
    Div,
}

impl Math2 {
    fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            Math2::Atan2 => a.atan2(b),
            Math2::Pow => a.powf(b),
            Math2::Mod => a % b,
            Math2::Div => (a / b).trunc(),
        }
    }

    /// The function a name calls, if it is one of these.
    pub fn named(name: &str) -> Option<Math2> {
        Some(match name {
            "atan2" => Math2::Atan2,
            "pow" => Math2::Pow,
            "mod" => Math2::Mod,
            "div" => Math2::Div,
            _ => return None,
        })
    }
}

/// A function made of something other than an expression: a pattern's value, a pigment's
/// colour, a spline's point (`function { pattern { … } }`, `function { pigment { … } }`,
/// `function { spline { … } }`). The layer that made it evaluates it; programs call it
/// through this trait (one dynamic call, small beside evaluating a pattern or a pigment).
///
/// A native is data: two natives are the same function when they are of one kind and hold
/// equal values ([`Native::same`]), so that a scene read twice from one text compares equal
/// (`trace watch` keeps what did not change).
pub trait Native: Send + Sync + std::fmt::Debug + std::any::Any {
    /// How many values it takes (x, y, z for a pattern or a pigment; 1 for a spline).
    fn params(&self) -> usize;
    /// How many values it gives (1 for a pattern, 5 for a colour, a spline's terms).
    fn size(&self) -> usize;
    /// Its values for `args` (the first [`Native::size`] of them meaningful), noise from
    /// `generator` where it has no generator of its own.
    fn eval(&self, args: &[f64], generator: u8) -> [f64; 5];
    /// Whether `other` is the same function: of this kind, with equal data (see
    /// [`same_data`]).
    fn same(&self, other: &dyn Native) -> bool;
}

/// [`Native::same`] for a native of type `T` compared by its `PartialEq`.
pub fn same_data<T: Native + PartialEq>(a: &T, other: &dyn Native) -> bool {
    let other: &dyn std::any::Any = other;
    other.downcast_ref::<T>().is_some_and(|b| a == b)
}

/// Whether two shared natives are the same function (the same one, or equal data).
fn same_native(a: &Arc<dyn Native>, b: &Arc<dyn Native>) -> bool {
    std::ptr::addr_eq(Arc::as_ptr(a), Arc::as_ptr(b)) || a.same(&**b)
}

/// A shared [`Native`], in patterns; equal to the same function ([`Native::same`]).
#[derive(Clone, Debug)]
pub struct NativeRef(pub Arc<dyn Native>);

impl PartialEq for NativeRef {
    fn eq(&self, other: &NativeRef) -> bool {
        same_native(&self.0, &other.0)
    }
}

/// Which value of a [`Native`] a program uses: 0 to 4 (`.x`/`.red` … `.transmit`), or
/// [`GRAY`] (`.gray`: POV-Ray's weighted sum of red, green and blue).
pub type Member = u8;
/// The `.gray` member.
pub const GRAY: Member = 5;

/// One step of a function's program.
#[derive(Clone, Debug)]
#[allow(missing_docs)]
pub enum Op {
    Const(f64),
    /// The function's parameter i.
    Arg(u8),
    Add,
    Sub,
    Mul,
    Div,
    Neg,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
    Math1(Math1),
    Math2(Math2),
    /// `min`/`max` of the top n values.
    Min(u8),
    Max(u8),
    /// `select(a, b, c)`: b where a < 0, else c.
    Select3,
    /// `select(a, b, c, d)`: b where a < 0, c where a = 0, else d.
    Select4,
    /// Another function, called with the top n values.
    Call(Arc<Function>),
    /// A built-in function, called with the top n values (x, y, z first).
    Internal(Internal, u8),
    /// A native function called with its parameters' count of top values; one of its values.
    Native(Arc<dyn Native>, Member),
    /// `sum(i, a, b, f)` or `prod(i, a, b, f)` (`true`): pops b and a, and runs the term f
    /// (a function of this function's parameters and i) for i = a, a + 1, … while i ≤ b.
    Loop(Arc<Function>, bool),
}

/// The most terms `sum` and `prod` add or multiply in one evaluation (a hostile bound such as
/// 1e15 stops there).
pub const MAX_LOOP_TERMS: u32 = 1 << 20;

/// A compiled function.
#[derive(Clone, Debug)]
pub struct Function {
    /// How many values it takes.
    pub params: usize,
    /// A function of several values (a pigment's colour, a spline's point): called in an
    /// expression it gives them all, in another function one member of it (`F(x, y, z).red`).
    /// Its program gives its first value.
    pub vector: Option<Arc<dyn Native>>,
    code: Box<[Op]>,
    /// The most values its program holds at once.
    depth: usize,
    /// 1 + the deepest nesting of the functions it calls.
    nesting: usize,
}

/// Functions are equal when they run the same program: equal operations, the functions they
/// call equal in turn, their natives the same ([`Native::same`]). Two reads of one text give
/// equal functions.
impl PartialEq for Function {
    fn eq(&self, other: &Function) -> bool {
        self.same_as(other, &mut Vec::new())
    }
}

impl Function {
    /// Equality, with the pairs of called functions already found equal in `equal` (a
    /// function called many times in a call graph is compared once, not once per path).
    fn same_as(
        &self,
        other: &Function,
        equal: &mut Vec<(*const Function, *const Function)>,
    ) -> bool {
        if std::ptr::eq(self, other) {
            return true;
        }
        let vector = match (&self.vector, &other.vector) {
            (None, None) => true,
            (Some(a), Some(b)) => same_native(a, b),
            _ => false,
        };
        if self.params != other.params || !vector || self.code.len() != other.code.len() {
            return false;
        }
        let mut callee = |a: &Arc<Function>, b: &Arc<Function>| {
            let pair = (Arc::as_ptr(a), Arc::as_ptr(b));
            if Arc::ptr_eq(a, b) || equal.contains(&pair) {
                return true;
            }
            let same = a.same_as(b, equal);
            if same {
                equal.push(pair);
            }
            same
        };
        self.code.iter().zip(&other.code).all(|pair| match pair {
            (Op::Call(a), Op::Call(b)) => callee(a, b),
            (Op::Loop(a, pa), Op::Loop(b, pb)) => pa == pb && callee(a, b),
            (Op::Native(a, ma), Op::Native(b, mb)) => ma == mb && same_native(a, b),
            (Op::Const(a), Op::Const(b)) => a.to_bits() == b.to_bits(),
            (Op::Arg(a), Op::Arg(b)) | (Op::Min(a), Op::Min(b)) | (Op::Max(a), Op::Max(b)) => {
                a == b
            }
            (Op::Math1(a), Op::Math1(b)) => a == b,
            (Op::Math2(a), Op::Math2(b)) => a == b,
            (Op::Internal(a, na), Op::Internal(b, nb)) => a == b && na == nb,
            // (Operations with data of their own matched above: same kind, no data.)
            (a, b) => std::mem::discriminant(a) == std::mem::discriminant(b),
        })
    }
}

impl Function {
    /// A function of `params` values running `code`; `None` if the program is not well formed,
    /// needs more than [`MAX_STACK`] values at once or calls functions nested deeper than
    /// [`MAX_NESTING`].
    pub fn new(params: usize, code: Vec<Op>) -> Option<Function> {
        let mut depth: usize = 0;
        let mut deepest = 0;
        let mut nesting = 1;
        for op in &code {
            if let Op::Call(f) | Op::Loop(f, _) = op {
                nesting = nesting.max(f.nesting + 1);
            }
            let (pops, pushes) = match op {
                Op::Const(_) | Op::Arg(_) => (0, 1),
                Op::Neg | Op::Math1(_) => (1, 1),
                Op::Select3 => (3, 1),
                Op::Select4 => (4, 1),
                Op::Min(n) | Op::Max(n) | Op::Internal(_, n) => (*n as usize, 1),
                Op::Call(f) => (f.params, 1),
                Op::Native(f, _) => (f.params(), 1),
                Op::Loop(f, _) if f.params != params + 1 || f.params > MAX_STACK => return None,
                _ => (2, 1),
            };
            if let Op::Arg(i) = op {
                if *i as usize >= params {
                    return None;
                }
            }
            depth = depth.checked_sub(pops)? + pushes;
            deepest = deepest.max(depth);
        }
        (depth == 1 && deepest <= MAX_STACK && nesting <= MAX_NESTING).then(|| Function {
            params,
            vector: None,
            code: code.into_boxed_slice(),
            depth: deepest,
            nesting,
        })
    }

    /// The function of `internal` (x, y, z and its parameters).
    pub fn internal(internal: Internal) -> Function {
        let n = internal.arity();
        let mut code: Vec<Op> = (0..n as u8).map(Op::Arg).collect();
        code.push(Op::Internal(internal, n as u8));
        Function {
            params: n,
            vector: None,
            code: code.into_boxed_slice(),
            depth: n,
            nesting: 1,
        }
    }

    /// The function of `native`: its first value, or (of several) all of them as a vector
    /// function.
    pub fn native(native: Arc<dyn Native>) -> Function {
        let n = native.params();
        let mut code: Vec<Op> = (0..n as u8).map(Op::Arg).collect();
        code.push(Op::Native(Arc::clone(&native), 0));
        Function {
            params: n,
            vector: (native.size() > 1).then_some(native),
            code: code.into_boxed_slice(),
            depth: n.max(1),
            nesting: 1,
        }
    }

    /// Its value for `args` (as many as it takes), noise from `generator`.
    pub fn eval(&self, args: &[f64], generator: u8) -> f64 {
        // (A small stack for the usual small function: clearing 64 values costs as much as
        // running one.)
        if self.depth <= 16 {
            self.run::<16>(args, generator)
        } else {
            self.run::<MAX_STACK>(args, generator)
        }
    }

    fn run<const N: usize>(&self, args: &[f64], generator: u8) -> f64 {
        let mut stack = [0.0f64; N];
        let mut top = 0usize;
        macro_rules! pop {
            () => {{
                top -= 1;
                stack[top]
            }};
        }
        for op in self.code.iter() {
            let v = match op {
                Op::Const(c) => *c,
                Op::Arg(i) => args[*i as usize],
                Op::Neg => -pop!(),
                Op::Math1(m) => m.apply(pop!()),
                Op::Math2(m) => {
                    let b = pop!();
                    let a = pop!();
                    m.apply(a, b)
                }
                Op::Min(n) | Op::Max(n) => {
                    let n = *n as usize;
                    top -= n;
                    let values = &stack[top..top + n];
                    if matches!(op, Op::Min(_)) {
                        values.iter().copied().fold(f64::INFINITY, f64::min)
                    } else {
                        values.iter().copied().fold(f64::NEG_INFINITY, f64::max)
                    }
                }
                Op::Select3 => {
                    let c = pop!();
                    let b = pop!();
                    let a = pop!();
                    if a < 0.0 { b } else { c }
                }
                Op::Select4 => {
                    let d = pop!();
                    let c = pop!();
                    let b = pop!();
                    let a = pop!();
                    if a < 0.0 {
                        b
                    } else if a == 0.0 {
                        c
                    } else {
                        d
                    }
                }
                Op::Call(f) => {
                    top -= f.params;
                    f.eval(&stack[top..top + f.params], generator)
                }
                Op::Internal(f, n) => {
                    let n = *n as usize;
                    top -= n;
                    let mut a = [0.0; 16];
                    a[..n].copy_from_slice(&stack[top..top + n]);
                    f.apply(&a[..n], generator)
                }
                Op::Loop(term, product) => {
                    let end = pop!();
                    let mut i = pop!();
                    let n = args.len();
                    let mut a = [0.0; MAX_STACK];
                    a[..n].copy_from_slice(args);
                    let mut acc = if *product { 1.0 } else { 0.0 };
                    let mut terms = 0;
                    while i <= end && terms < MAX_LOOP_TERMS {
                        a[n] = i;
                        let v = term.eval(&a[..=n], generator);
                        acc = if *product { acc * v } else { acc + v };
                        i += 1.0;
                        terms += 1;
                    }
                    acc
                }
                Op::Native(f, member) => {
                    let n = f.params();
                    top -= n;
                    let v = f.eval(&stack[top..top + n], generator);
                    match *member {
                        GRAY => 0.297 * v[0] + 0.589 * v[1] + 0.114 * v[2],
                        i => v[i as usize],
                    }
                }
                binary => {
                    let b = pop!();
                    let a = pop!();
                    let truth = |t: bool| if t { 1.0 } else { 0.0 };
                    match binary {
                        Op::Add => a + b,
                        Op::Sub => a - b,
                        Op::Mul => a * b,
                        Op::Div => a / b,
                        Op::Lt => truth(a < b),
                        Op::Le => truth(a <= b),
                        Op::Gt => truth(a > b),
                        Op::Ge => truth(a >= b),
                        Op::Eq => truth(a == b),
                        Op::Ne => truth(a != b),
                        Op::And => truth(a != 0.0 && b != 0.0),
                        _ => truth(a != 0.0 || b != 0.0),
                    }
                }
            };
            stack[top] = v;
            top += 1;
        }
        stack[0]
    }

    /// Its value at a point (a function of x, y, z; further parameters 0).
    pub fn at(&self, p: DVec3, generator: u8) -> f64 {
        if self.params <= 8 {
            let mut a = [0.0; 8];
            a[..3].copy_from_slice(&p.to_array());
            return self.eval(&a[..self.params.max(3)], generator);
        }
        let mut a = [0.0; MAX_STACK];
        a[..3].copy_from_slice(&p.to_array());
        self.eval(&a[..self.params.max(3)], generator)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f_0(x) = x + k, f_i(x) = f_{i-1}(x) + f_{i-1}(x): each level calls the one below twice.
    fn doubling(levels: usize, k: f64) -> Arc<Function> {
        let mut f = Arc::new(Function::new(1, vec![Op::Arg(0), Op::Const(k), Op::Add]).unwrap());
        for _ in 1..levels {
            let code = vec![
                Op::Arg(0),
                Op::Call(f.clone()),
                Op::Arg(0),
                Op::Call(f.clone()),
                Op::Add,
            ];
            f = Arc::new(Function::new(1, code).unwrap());
        }
        f
    }

    #[test]
    fn functions_compare_as_programs() {
        // Built twice, apart: equal, and compared in time linear in the call graph (a
        // comparison along every path would take 2^60 steps).
        let (a, b) = (doubling(60, 1.0), doubling(60, 1.0));
        assert!(!Arc::ptr_eq(&a, &b));
        assert!(a == b);
        // A constant deep below differs.
        assert!(a != doubling(60, 2.0));
        assert!(doubling(3, 1.0) != doubling(4, 1.0));
        // Natives: equal data of one kind are the same; another kind or other data are not.
        let spline = |y: f64| {
            let mut s = spline::Spline::new(spline::SplineKind::Linear);
            s.insert(0.0, [0.0; 5], 1);
            s.insert(1.0, [y, 0.0, 0.0, 0.0, 0.0], 1);
            Function::native(Arc::new(s))
        };
        assert!(spline(1.0) == spline(1.0));
        assert!(spline(1.0) != spline(2.0));
        let empty = |kind| NativeRef(Arc::new(spline::Spline::new(kind)));
        assert!(empty(spline::SplineKind::Linear) == empty(spline::SplineKind::Linear));
        assert!(empty(spline::SplineKind::Linear) != empty(spline::SplineKind::Cubic));
    }

    #[test]
    fn arithmetic_and_calls() {
        // x*x + y*y + z*z − 1
        let f = Function::new(
            3,
            vec![
                Op::Arg(0),
                Op::Arg(0),
                Op::Mul,
                Op::Arg(1),
                Op::Arg(1),
                Op::Mul,
                Op::Add,
                Op::Arg(2),
                Op::Arg(2),
                Op::Mul,
                Op::Add,
                Op::Const(1.0),
                Op::Sub,
            ],
        )
        .unwrap();
        assert_eq!(f.eval(&[1.0, 2.0, 2.0], 2), 8.0);
        let g = Arc::new(f);
        // g(x, 0, 0) * 2, selected
        let h = Function::new(
            1,
            vec![
                Op::Arg(0),
                Op::Arg(0),
                Op::Const(0.0),
                Op::Const(0.0),
                Op::Call(g),
                Op::Const(5.0),
                Op::Select3,
            ],
        )
        .unwrap();
        assert_eq!(h.eval(&[-1.0], 2), 0.0);
        assert_eq!(h.eval(&[2.0], 2), 5.0);
        assert!(Function::new(1, vec![Op::Add]).is_none());
        assert!(Function::new(1, vec![Op::Arg(1)]).is_none());
    }

    /// A chain of functions each calling the one before stops at MAX_NESTING.
    #[test]
    fn nesting_is_bounded() {
        let mut f = Arc::new(Function::new(1, vec![Op::Arg(0)]).unwrap());
        for _ in 1..MAX_NESTING {
            f = Arc::new(Function::new(1, vec![Op::Arg(0), Op::Call(f)]).unwrap());
        }
        assert_eq!(f.eval(&[2.5], 2), 2.5);
        assert!(Function::new(1, vec![Op::Arg(0), Op::Call(f)]).is_none());
    }

    #[test]
    fn internals() {
        let sphere = Function::internal(Internal::Sphere);
        assert_eq!(sphere.eval(&[0.0, 3.0, 4.0, 2.0], 2), 3.0);
        let torus = Function::internal(Internal::Torus);
        assert!((torus.eval(&[1.0, 0.0, 0.0, 1.0, 0.25], 2) + 0.25).abs() < 1e-12);
        let b = Function::internal(Internal::RoundedBox);
        // A unit box with corners rounded 0.1: 0 on its face.
        assert!(b.eval(&[1.0, 0.0, 0.0, 0.1, 1.0, 1.0, 1.0], 2).abs() < 1e-5);
    }
}
