//! Expression evaluation: POV-Ray's operators, promotion rules, constants and functions.

use crate::diag::{Diagnostic, Span};
use crate::eval::value::{Value, Vector, srgb_decode};
use crate::eval::{Evaluator, lang::keywords};
use crate::syntax::{BinOp, ColourPart, Expr, ExprKind, Slot, UnOp};

/// Functions whose value is a string (evaluated by `Evaluator::string`).
pub(in crate::eval) const STRING_FUNCTIONS: [&str; 8] = [
    "concat", "str", "vstr", "chr", "substr", "strupr", "strlwr", "datetime",
];

/// POV-Ray's tolerance for `=`, `!=` and truth (`ftrue`): |x| > 1e-10 is true.
const EQUALITY_TOLERANCE: f64 = 1e-10;

type Result<T> = std::result::Result<T, Diagnostic>;

impl Evaluator<'_> {
    /// Whether a float counts as true (POV-Ray's |x| > 1e-10).
    pub(in crate::eval) fn truth(&mut self, e: &Expr) -> Result<bool> {
        Ok(self.float(e)?.abs() > EQUALITY_TOLERANCE)
    }

    /// Evaluates an expression to a value; a number that is not finite (an overflow such as
    /// `1e308*10`, `exp(1000)` or `1e400`, or a NaN such as `val("nan")`) is an error here,
    /// at the innermost expression that made it.
    pub(in crate::eval) fn eval(&mut self, expr: &Expr) -> Result<Value> {
        let value = self.eval_unchecked(expr)?;
        if value.is_finite() {
            Ok(value)
        } else {
            Err(Diagnostic::error(
                "this value is not a finite number (it overflows or is undefined)",
                expr.span,
            ))
        }
    }

    fn eval_unchecked(&mut self, expr: &Expr) -> Result<Value> {
        match &expr.kind {
            ExprKind::Number(n) => Ok(Value::Float(*n)),
            ExprKind::Vector(items) => {
                if items.len() > 5 {
                    return Err(Diagnostic::error(
                        format!(
                            "a vector has 2 to 5 components, this one has {}",
                            items.len()
                        ),
                        expr.span,
                    ));
                }
                let mut comps = Vec::with_capacity(items.len());
                for item in items {
                    comps.push(self.float(item)?);
                }
                Ok(Value::Vector(Vector::new(&comps)))
            }
            ExprKind::Str(_) => Ok(Value::Str(self.string(expr)?)),
            ExprKind::Call(name, _, _, _) if STRING_FUNCTIONS.contains(&name.as_str()) => {
                Ok(Value::Str(self.string(expr)?))
            }
            ExprKind::PlainVector(c, len) => Ok(Value::Vector(Vector {
                c: *c,
                len: *len as usize,
            })),
            ExprKind::Ident(name, slot) => self.ident(name, *slot, expr.span),
            ExprKind::Unary(op, operand) => {
                let v = self.eval(operand)?;
                match op {
                    UnOp::Plus => Ok(v),
                    UnOp::Neg => map_components(&v, |c| -c)
                        .ok_or_else(|| type_error("a number", &v, operand.span)),
                    UnOp::Not => {
                        let f = self.expect_float(&v, operand.span)?;
                        Ok(Value::Float(bool_value(f.abs() <= EQUALITY_TOLERANCE)))
                    }
                }
            }
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b),
            ExprKind::Ternary(c, a, b) => {
                // POV-Ray evaluates both branches (it reads them), so a rand() in the one not
                // taken still draws its number.
                let cond = self.float(c)?;
                let (va, vb) = (self.eval(a)?, self.eval(b)?);
                Ok(if cond.abs() > EQUALITY_TOLERANCE {
                    va
                } else {
                    vb
                })
            }
            ExprKind::Call(name, name_span, slot, args) => {
                self.call(name, *name_span, *slot, args, expr.span)
            }
            ExprKind::Member(base, name, span) => {
                let v = self.eval(base)?;
                self.member(&v, name, *span, base.span)
            }
            ExprKind::Colour(parts) => self.colour(parts),
            ExprKind::Index(..) => self.index_expr(expr),
            ExprKind::Item(node) => self.item_value(node),
            ExprKind::Shifted(e, by) => {
                self.lang.slot_shift += by;
                let v = self.eval(e);
                self.lang.slot_shift -= by;
                v
            }
            ExprKind::Bulk(_) => Err(Diagnostic::error(
                "a list of mesh2 entries cannot stand here",
                expr.span,
            )),
        }
    }

    /// Evaluates an expression that must be a float.
    pub(in crate::eval) fn float(&mut self, expr: &Expr) -> Result<f64> {
        let v = self.eval(expr)?;
        self.expect_float(&v, expr.span)
    }

    pub(in crate::eval) fn expect_float(&self, v: &Value, span: Span) -> Result<f64> {
        match v {
            Value::Float(f) => Ok(*f),
            _ => Err(type_error("a float", v, span)),
        }
    }

    /// Evaluates an expression in a 3-vector context: a float promotes to all three components.
    pub(in crate::eval) fn vec3(&mut self, expr: &Expr) -> Result<glam::DVec3> {
        let v = self.eval(expr)?;
        match v {
            Value::Float(f) => Ok(glam::DVec3::splat(f)),
            Value::Vector(v) => Ok(v.vec3()),
            _ => Err(type_error("a vector", &v, expr.span)),
        }
    }

    /// The value of the name `name` bound in `slot`, or of the built-in constant it names.
    pub(in crate::eval) fn ident(&mut self, name: &str, slot: Slot, span: Span) -> Result<Value> {
        if let Some(v) = self.bound(slot) {
            return self.usable(name, v.clone(), span);
        }
        let v3 = |x, y, z| Value::Vector(Vector::new(&[x, y, z]));
        Ok(match name {
            "pi" => Value::Float(std::f64::consts::PI),
            "x" => v3(1.0, 0.0, 0.0),
            "y" => v3(0.0, 1.0, 0.0),
            "z" => v3(0.0, 0.0, 1.0),
            "t" => Value::Vector(Vector::new(&[0.0, 0.0, 0.0, 1.0])),
            "u" => Value::Vector(Vector::new(&[1.0, 0.0])),
            "v" => Value::Vector(Vector::new(&[0.0, 1.0])),
            "true" | "yes" | "on" => Value::Float(1.0),
            "false" | "no" | "off" => Value::Float(0.0),
            "clock" => Value::Float(self.options.clock.clock),
            "clock_on" => Value::Float(f64::from(u8::from(self.options.clock.on))),
            "clock_delta" => Value::Float(self.options.clock.delta),
            "frame_number" => Value::Float(self.options.clock.frame as f64),
            "initial_frame" => Value::Float(self.options.clock.frames.0 as f64),
            "final_frame" => Value::Float(self.options.clock.frames.1 as f64),
            "initial_clock" => Value::Float(self.options.clock.clocks.0),
            "final_clock" => Value::Float(self.options.clock.clocks.1),
            "image_width" => Value::Float(self.options.width as f64),
            "image_height" => Value::Float(self.options.height as f64),
            "version" => Value::Float(self.lang.version.unwrap_or(3.7)),
            "input_file_name" => Value::Str(self.lang.input_file_name.clone()),
            // Days since 2000-01-01 00:00 UTC (POV-Ray's clock for `datetime`).
            "now" => {
                let since_epoch = std::time::SystemTime::now()
                    .duration_since(std::time::UNIX_EPOCH)
                    .map_or(0.0, |d| d.as_secs_f64());
                Value::Float((since_epoch - 946_684_800.0) / 86_400.0)
            }
            _ => return Err(self.unknown_word(name, span)),
        })
    }

    fn binary(&mut self, op: BinOp, a: &Expr, b: &Expr) -> Result<Value> {
        let va = self.eval(a)?;
        let vb = self.eval(b)?;
        let span = Span {
            end: b.span.end,
            ..a.span
        };
        match op {
            BinOp::Add | BinOp::Sub | BinOp::Mul | BinOp::Div => {
                let f = match op {
                    BinOp::Add => |x: f64, y: f64| x + y,
                    BinOp::Sub => |x, y| x - y,
                    BinOp::Mul => |x, y| x * y,
                    _ => |x, y| x / y,
                };
                let (ca, la) = va
                    .components()
                    .ok_or_else(|| type_error("a number", &va, a.span))?;
                let (cb, lb) = vb
                    .components()
                    .ok_or_else(|| type_error("a number", &vb, b.span))?;
                if op == BinOp::Div && vb.components().is_some_and(|(c, n)| c[..n].contains(&0.0)) {
                    return Err(Diagnostic::error("division by zero", b.span));
                }
                let is_colour = matches!(va, Value::Colour(_)) || matches!(vb, Value::Colour(_));
                if la == 1 && lb == 1 && !is_colour {
                    return Ok(Value::Float(f(ca[0], cb[0])));
                }
                // Promote: a float fills every component; vectors of different sizes are
                // padded with zeros.
                let len = if is_colour { 5 } else { la.max(lb) };
                let pick = |c: [f64; 5], l: usize, i: usize| if l == 1 { c[0] } else { c[i] };
                let mut out = [0.0; 5];
                for (i, o) in out.iter_mut().enumerate().take(len) {
                    *o = f(pick(ca, la, i), pick(cb, lb, i));
                }
                Ok(if is_colour {
                    Value::Colour(out)
                } else {
                    Value::Vector(Vector { c: out, len })
                })
            }
            // Strings compare by their characters' codes (POV-Ray's strcmp).
            BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge | BinOp::Eq | BinOp::Ne
                if matches!(va, Value::Str(_)) =>
            {
                let (Value::Str(x), Value::Str(y)) = (&va, &vb) else {
                    return Err(type_error("a string", &vb, b.span));
                };
                let order = x.chars().cmp(y.chars());
                let r = match op {
                    BinOp::Lt => order.is_lt(),
                    BinOp::Le => order.is_le(),
                    BinOp::Gt => order.is_gt(),
                    BinOp::Ge => order.is_ge(),
                    BinOp::Eq => order.is_eq(),
                    _ => order.is_ne(),
                };
                Ok(Value::Float(bool_value(r)))
            }
            _ => {
                let x = self.expect_float(&va, a.span)?;
                let y = self.expect_float(&vb, b.span)?;
                let _ = span;
                let r = match op {
                    BinOp::Lt => x < y,
                    BinOp::Le => x <= y + EQUALITY_TOLERANCE,
                    BinOp::Gt => x > y,
                    BinOp::Ge => x + EQUALITY_TOLERANCE >= y,
                    BinOp::Eq => (x - y).abs() <= EQUALITY_TOLERANCE,
                    BinOp::Ne => (x - y).abs() > EQUALITY_TOLERANCE,
                    BinOp::And => x.abs() > EQUALITY_TOLERANCE && y.abs() > EQUALITY_TOLERANCE,
                    _ => x.abs() > EQUALITY_TOLERANCE || y.abs() > EQUALITY_TOLERANCE,
                };
                Ok(Value::Float(bool_value(r)))
            }
        }
    }

    fn member(&mut self, v: &Value, name: &str, span: Span, base_span: Span) -> Result<Value> {
        let (c, len) = v
            .components()
            .ok_or_else(|| type_error("a vector or colour", v, base_span))?;
        let index = match name {
            "x" | "u" | "red" => 0,
            "y" | "v" | "green" => 1,
            "z" | "blue" => 2,
            "t" | "filter" => 3,
            "transmit" => 4,
            "gray" | "grey" => return Ok(Value::Float(0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2])),
            _ => {
                return Err(Diagnostic::error(
                    format!(
                        "unknown component `.{name}` (expected .x .y .z .t .u .v .red .green .blue .filter .transmit .gray)"
                    ),
                    span,
                ));
            }
        };
        if len == 1 || index >= len {
            return Err(Diagnostic::error(
                format!("`.{name}` does not exist on {}", v.kind_name()),
                span,
            ));
        }
        Ok(Value::Float(c[index]))
    }

    fn colour(&mut self, parts: &[ColourPart]) -> Result<Value> {
        let mut c = [0.0; 5];
        for part in parts {
            match part {
                ColourPart::Base(e) => {
                    let v = self.eval(e)?;
                    c = crate::eval::value::colour5(&v)
                        .ok_or_else(|| type_error("a colour", &v, e.span))?;
                }
                ColourPart::Typed(kw, e) => {
                    let v = self.eval(e)?;
                    let (comps, len) = v
                        .components()
                        .ok_or_else(|| type_error("a colour", &v, e.span))?;
                    let comps = if len == 1 { [comps[0]; 5] } else { comps };
                    let srgb = kw.starts_with('s');
                    if srgb && self.lang.assumed_gamma.is_none() {
                        return Err(Diagnostic::error(
                            format!(
                                "`{kw}` needs `assumed_gamma` to be set first in global_settings"
                            ),
                            e.span,
                        ));
                    }
                    let channels = kw.trim_start_matches('s');
                    // Which of filter/transmit this keyword sets, in the order the vector gives them.
                    let (filter, transmit) = match channels {
                        // `rgb` of four or five values keeps the filter (and transmit) given,
                        // as POV-Ray does, with its warning.
                        "rgb" if len >= 4 => {
                            self.warn(Diagnostic::warning(
                                "`rgb` takes three values; the filter (and transmit) after them are kept, as in POV-Ray (which warns of a suspicious expression after rgb)",
                                e.span,
                            ));
                            (Some(3), (len == 5).then_some(4))
                        }
                        "rgb" => (None, None),
                        "rgbf" => (Some(3), None),
                        "rgbt" => (None, Some(3)),
                        _ => (Some(3), Some(4)),
                    };
                    for (i, ci) in c.iter_mut().enumerate().take(3) {
                        *ci = if srgb {
                            self.srgb_to_linear(comps[i])
                        } else {
                            comps[i]
                        };
                    }
                    c[3] = filter.map_or(0.0, |i| comps[i]);
                    c[4] = transmit.map_or(0.0, |i| comps[i]);
                }
                ColourPart::Channel(kw, e) => {
                    let f = self.float(e)?;
                    match kw.as_str() {
                        "red" => c[0] = f,
                        "green" => c[1] = f,
                        "blue" => c[2] = f,
                        "filter" => c[3] = f,
                        "transmit" => c[4] = f,
                        // POV-Ray's old name of filter (before 2.0), read as filter.
                        "alpha" => {
                            self.warn(Diagnostic::warning(
                                "`alpha` is POV-Ray's old name of `filter`: read as filter (POV-Ray warns too)",
                                e.span,
                            ));
                            c[3] = f;
                        }
                        _ => {
                            return Err(Diagnostic::error(
                                format!("`{kw}` is not a colour channel that can be set"),
                                e.span,
                            ));
                        }
                    }
                }
            }
        }
        Ok(Value::Colour(c))
    }

    /// An sRGB-encoded channel converted into working gamma.
    fn srgb_to_linear(&self, v: f64) -> f64 {
        let linear = srgb_decode(v);
        match self.lang.assumed_gamma {
            Some(g) if g != 1.0 => linear.max(0.0).powf(1.0 / g),
            _ => linear,
        }
    }

    /// `name(args)`: a declared function or spline (bound in `slot`), or a built-in function.
    pub(in crate::eval) fn call(
        &mut self,
        name: &str,
        name_span: Span,
        slot: Slot,
        args: &[Expr],
        span: Span,
    ) -> Result<Value> {
        match self.bound(slot) {
            Some(Value::Function(f)) => {
                let f = std::sync::Arc::clone(f);
                return self.call_function(&f, name, args, span);
            }
            Some(Value::Spline(s)) => {
                let s = std::sync::Arc::clone(s);
                return self.call_spline(&s, name, args, span);
            }
            _ => {}
        }
        if let Some(v) = self.call_special(name, args, span)? {
            return Ok(v);
        }
        // The arguments' values, with where each is written: parameter `i` of the function.
        let mut values = Vec::with_capacity(args.len());
        let mut spans = Vec::with_capacity(args.len());
        for a in args {
            values.push(self.eval(a)?);
            spans.push(a.span);
        }
        let arity = |n: usize| check_arity(name, n, values.len(), span);
        let f = |i: usize, me: &Self| -> Result<f64> { me.expect_float(&values[i], spans[i]) };
        let v3 = |i: usize| -> Result<glam::DVec3> {
            match &values[i] {
                Value::Float(x) => Ok(glam::DVec3::splat(*x)),
                Value::Vector(v) => Ok(v.vec3()),
                other => Err(type_error("a vector", other, spans[i])),
            }
        };
        let domain = |ok: bool| -> Result<()> {
            if ok {
                Ok(())
            } else {
                Err(Diagnostic::error(
                    format!("`{name}`: argument out of its domain"),
                    span,
                ))
            }
        };
        let unary: Option<fn(f64) -> f64> = match name {
            "abs" => Some(f64::abs),
            "acosh" => Some(f64::acosh),
            "asinh" => Some(f64::asinh),
            "atan" => Some(f64::atan),
            "atanh" => Some(f64::atanh),
            "ceil" => Some(f64::ceil),
            "cos" => Some(f64::cos),
            "cosh" => Some(f64::cosh),
            "degrees" => Some(f64::to_degrees),
            "radians" => Some(f64::to_radians),
            "exp" => Some(f64::exp),
            "floor" => Some(f64::floor),
            "int" => Some(f64::trunc),
            "sin" => Some(f64::sin),
            "sinh" => Some(f64::sinh),
            "tan" => Some(f64::tan),
            "tanh" => Some(f64::tanh),
            _ => None,
        };
        if let Some(g) = unary {
            arity(1)?;
            return Ok(Value::Float(g(f(0, self)?)));
        }
        let result = match name {
            "acos" | "asin" => {
                arity(1)?;
                let x = f(0, self)?.clamp(-1.0, 1.0);
                if name == "acos" { x.acos() } else { x.asin() }
            }
            "sqrt" => {
                arity(1)?;
                let x = f(0, self)?;
                domain(x >= 0.0)?;
                x.sqrt()
            }
            "ln" | "log" => {
                arity(1)?;
                let x = f(0, self)?;
                domain(x > 0.0)?;
                if name == "ln" { x.ln() } else { x.log10() }
            }
            "atan2" | "div" | "mod" | "pow" => {
                arity(2)?;
                let (a, b) = (f(0, self)?, f(1, self)?);
                match name {
                    "atan2" => a.atan2(b),
                    "div" => {
                        domain(b != 0.0)?;
                        (a / b).trunc()
                    }
                    "mod" => {
                        domain(b != 0.0)?;
                        a % b
                    }
                    _ => {
                        domain(!(a == 0.0 && b == 0.0))?;
                        a.powf(b)
                    }
                }
            }
            "max" | "min" => {
                if args.is_empty() {
                    return Err(Diagnostic::error(
                        format!("`{name}` needs at least one argument"),
                        span,
                    ));
                }
                let mut acc = f(0, self)?;
                for i in 1..args.len() {
                    let x = f(i, self)?;
                    acc = if name == "max" {
                        acc.max(x)
                    } else {
                        acc.min(x)
                    };
                }
                acc
            }
            "select" => {
                if args.len() != 3 && args.len() != 4 {
                    return Err(Diagnostic::error("`select` takes 3 or 4 arguments", span));
                }
                let a = f(0, self)?;
                let pick = if args.len() == 3 {
                    if a < 0.0 { 1 } else { 2 }
                } else if a < 0.0 {
                    1
                } else if a == 0.0 {
                    2
                } else {
                    3
                };
                return Ok(values[pick].clone());
            }
            "vdot" => {
                arity(2)?;
                v3(0)?.dot(v3(1)?)
            }
            "vlength" => {
                arity(1)?;
                v3(0)?.length()
            }
            "vturbulence" => {
                // vturbulence(lambda, omega, octaves, P): POV-Ray's vector turbulence at P.
                arity(4)?;
                let t = crate::noise::Turbulence {
                    amount: glam::DVec3::ONE,
                    lambda: f64::from(f(0, self)? as f32),
                    omega: f64::from(f(1, self)? as f32),
                    octaves: (f(2, self)? as i64).clamp(1, 10) as u32,
                };
                return Ok(Value::Vector(Vector::from_vec3(t.vector(v3(3)?))));
            }
            "vcross" => {
                arity(2)?;
                return Ok(Value::Vector(Vector::from_vec3(v3(0)?.cross(v3(1)?))));
            }
            "vnormalize" => {
                arity(1)?;
                let v = v3(0)?;
                domain(v.length() > 0.0)?;
                return Ok(Value::Vector(Vector::from_vec3(v.normalize())));
            }
            "vaxis_rotate" => {
                arity(3)?;
                let axis = v3(1)?;
                domain(axis.length() > 0.0)?;
                let m = glam::DMat3::from_axis_angle(axis.normalize(), f(2, self)?.to_radians());
                return Ok(Value::Vector(Vector::from_vec3(m * v3(0)?)));
            }
            "vrotate" => {
                arity(2)?;
                let m = rotation(v3(1)?);
                return Ok(Value::Vector(Vector::from_vec3(m.transform_point3(v3(0)?))));
            }
            _ if keywords::is_unsupported_function(name) => {
                return Err(self.unknown_word(name, name_span));
            }
            _ => {
                return Err(Diagnostic::error(
                    format!("unknown function `{name}`"),
                    name_span,
                ));
            }
        };
        Ok(Value::Float(result))
    }
}

fn map_components(v: &Value, f: impl Fn(f64) -> f64) -> Option<Value> {
    Some(match v {
        Value::Float(x) => Value::Float(f(*x)),
        Value::Vector(vec) => {
            let mut out = *vec;
            for c in out.c.iter_mut().take(vec.len) {
                *c = f(*c);
            }
            Value::Vector(out)
        }
        Value::Colour(c) => Value::Colour(c.map(f)),
        _ => return None,
    })
}

fn bool_value(b: bool) -> f64 {
    if b { 1.0 } else { 0.0 }
}

/// "expected X, found Y" at `span`.
pub(in crate::eval) fn type_error(expected: &str, found: &Value, span: Span) -> Diagnostic {
    Diagnostic::error(
        format!("expected {expected}, found {}", found.kind_name()),
        span,
    )
}

/// The error for a call of `name` with `found` arguments where it takes `wanted`.
pub(in crate::eval) fn check_arity(
    name: &str,
    wanted: usize,
    found: usize,
    span: Span,
) -> Result<()> {
    if found == wanted {
        return Ok(());
    }
    let plural = if wanted == 1 { "" } else { "s" };
    Err(Diagnostic::error(
        format!("`{name}` takes {wanted} argument{plural}, found {found}"),
        span,
    ))
}

/// A call's `N` arguments, or the error naming how many `name` takes.
pub(in crate::eval) fn arguments<'e, const N: usize>(
    name: &str,
    args: &'e [Expr],
    span: Span,
) -> Result<&'e [Expr; N]> {
    check_arity(name, N, args.len(), span)?;
    args.try_into()
        .map_err(|_| Diagnostic::error(format!("`{name}` takes {N} arguments"), span))
}

impl Evaluator<'_> {
    /// Functions that do not simply take numbers: `defined(Name)`, the string functions that
    /// give numbers, `file_exists`, and the bitwise ones.
    fn call_special(&mut self, name: &str, args: &[Expr], span: Span) -> Result<Option<Value>> {
        if matches!(name, "trace" | "inside" | "min_extent" | "max_extent") {
            return self.object_question(name, args, span).map(Some);
        }
        let f = match name {
            "defined" => {
                let [arg] = arguments(name, args, span)?;
                let ExprKind::Ident(_, slot) = &arg.kind else {
                    return Err(Diagnostic::error("`defined` takes an identifier", arg.span));
                };
                bool_value(self.bound(*slot).is_some())
            }
            "strlen" => {
                let [text] = arguments(name, args, span)?;
                self.string(text)?.chars().count() as f64
            }
            "strcmp" => {
                let [a, b] = arguments(name, args, span)?;
                let (a, b) = (self.string(a)?, self.string(b)?);
                match a.cmp(&b) {
                    std::cmp::Ordering::Less => -1.0,
                    std::cmp::Ordering::Equal => 0.0,
                    std::cmp::Ordering::Greater => 1.0,
                }
            }
            "val" => {
                let [text] = arguments(name, args, span)?;
                let text = self.string(text)?;
                // Like C's atof: the longest leading number, 0 if none.
                let t = text.trim_start();
                (1..=t.len())
                    .rev()
                    .find_map(|n| t.get(..n).and_then(|p| p.parse::<f64>().ok()))
                    .unwrap_or(0.0)
            }
            "asc" => {
                let [text] = arguments(name, args, span)?;
                self.string(text)?
                    .chars()
                    .next()
                    .map_or(0.0, |c| c as u32 as f64)
            }
            "file_exists" => {
                let [file] = arguments(name, args, span)?;
                let file = self.string(file)?;
                // A file outside the allowed folders does not exist for the scene.
                bool_value(self.sandbox.find(&file).is_ok())
            }
            "dimensions" | "dimension_size" => self.array_dimensions(name, args, span)?,
            "seed" => {
                let [seed] = arguments(name, args, span)?;
                // POV-Ray converts the seed to a C int (truncation), then to an unsigned long.
                let seed = self.float(seed)? as i64 as u32;
                self.lang.rand_streams.push(seed);
                (self.lang.rand_streams.len() - 1) as f64
            }
            "rand" => {
                let [stream] = arguments(name, args, span)?;
                let i = self.float(stream)?;
                let Some(state) = self
                    .lang
                    .rand_streams
                    .get_mut(i as usize)
                    .filter(|_| i >= 0.0)
                else {
                    return Err(Diagnostic::error(
                        "`rand` needs a stream made by `seed(…)`",
                        stream.span,
                    ));
                };
                // POV-Ray's stream: a 32-bit linear congruential generator, scaled to [0, 1].
                *state = state.wrapping_mul(1_812_433_253).wrapping_add(12_345);
                f64::from(*state) / f64::from(u32::MAX)
            }
            "bitwise_and" | "bitwise_or" | "bitwise_xor" => {
                let [first, rest @ ..] = args else {
                    return Err(Diagnostic::error(format!("`{name}` needs arguments"), span));
                };
                let mut acc = self.float(first)? as i64;
                for a in rest {
                    let x = self.float(a)? as i64;
                    acc = match name {
                        "bitwise_and" => acc & x,
                        "bitwise_or" => acc | x,
                        _ => acc ^ x,
                    };
                }
                acc as f64
            }
            _ => return Ok(None),
        };
        Ok(Some(Value::Float(f)))
    }
}

/// `rotate <a, b, c>` (degrees): about x by a, then y by b, then z by c (left-handed sense).
pub(in crate::eval) fn rotation(degrees: glam::DVec3) -> glam::DMat4 {
    let r = degrees * (std::f64::consts::PI / 180.0);
    glam::DMat4::from_rotation_z(r.z)
        * glam::DMat4::from_rotation_y(r.y)
        * glam::DMat4::from_rotation_x(r.x)
}
