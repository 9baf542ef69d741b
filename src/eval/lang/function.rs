//! `function [(a, b, …)] { … }`: compiled into a [`Function`] when declared, as POV-Ray
//! compiles it: parameters by position, declared floats folded in as constants, other
//! declared functions called, POV-Ray's maths and `internal(N)`. The operators are POV-Ray's
//! function syntax (`+ - * /`, comparisons, `&`, `|`, unary `-`); `!` and `? :` are not in it.

use crate::diag::{Diagnostic, Span};
use crate::eval::lang::expr::{check_arity, type_error};
use crate::eval::{Evaluator, Result, Value};
use crate::func::spline::{Spline, SplineKind};
use crate::func::{Function, Internal, Math1, Math2, Op};
use crate::syntax::{BinOp, Expr, ExprKind, Node, NodeKind, Slot, UnOp, View};
use std::sync::Arc;

impl Evaluator<'_> {
    /// A `function { … }` node, compiled.
    pub(in crate::eval) fn function(&mut self, node: &Node) -> Result<Arc<Function>> {
        let params: Vec<String> = match node
            .children
            .iter()
            .find(|c| c.kind == NodeKind::FunctionParams)
        {
            // (The words of `(a, b c)`, commas optional, as POV-Ray reads them.)
            Some(p) => {
                let mut lexer = crate::syntax::lexer::Lexer::new(&p.word, 0..p.word.len());
                std::iter::from_fn(|| lexer.next().ok().flatten())
                    .filter(|t| t.kind == crate::syntax::lexer::TokenKind::Word)
                    .map(|t| t.text(&p.word).to_string())
                    .collect()
            }
            None => vec!["x".into(), "y".into(), "z".into()],
        };
        // `function { spline { … } }`: the spline of its parameter.
        if let Some(body) = node.children.iter().find(|c| c.kind == NodeKind::Spline) {
            let spline = self.spline(body)?;
            return Ok(Arc::new(Function::native(Arc::new(spline))));
        }
        // `function { transform { … } }`: the point it takes, transformed.
        if let Some(body) = node.children.iter().find(|c| c.kind == NodeKind::Transform) {
            let t = self.transform(body)?;
            return Ok(Arc::new(Function::native(Arc::new(TransformFunction(
                t.matrix,
            )))));
        }
        // `function { pigment { … } }`, `function { pattern { … } }`.
        if let Some(body) = node
            .children
            .iter()
            .find(|c| matches!(c.kind, NodeKind::Pigment | NodeKind::PatternFunction))
        {
            if let Some(p) = node
                .children
                .iter()
                .find(|c| c.kind == NodeKind::FunctionParams)
            {
                return Err(Diagnostic::error(
                    "a pigment or pattern function takes no parameters (its point is x, y, z), as in POV-Ray",
                    p.span,
                ));
            }
            return self
                .native_function(body)
                .map(|n| Arc::new(Function::native(n)));
        }
        let View::Function { body: Some(body) } = node.view() else {
            return Err(Diagnostic::error(
                "this function has no body",
                node.word_span,
            ));
        };
        // `function { internal(N) }`: one of POV-Ray's built-in functions.
        if let ExprKind::Call(name, _, _, args) = &body.kind {
            if name == "internal" {
                let [n] = args.as_slice() else {
                    return Err(check_arity("internal", 1, args.len(), body.span).unwrap_err());
                };
                let n = self.float(n)? as i64;
                return match Internal::numbered(n) {
                    Some(f) => Ok(Arc::new(Function::internal(f))),
                    None => Err(Diagnostic::error(
                        format!("POV-Ray has no internal function {n} (they are numbered 0 to 78)"),
                        body.span,
                    )),
                };
            }
        }
        let mut code = Vec::new();
        self.compile(body, &params, &mut code)?;
        Function::new(params.len(), code).map(Arc::new).ok_or_else(|| {
            Diagnostic::error(
                format!(
                    "this function nests too deeply (more than {} values at once, or functions calling functions more than {} deep)",
                    crate::func::MAX_STACK,
                    crate::func::MAX_NESTING
                ),
                body.span,
            )
        })
    }

    /// `spline { [S] [kind] t, V … }`: a declared spline copied first (its kind kept unless
    /// another is named), then the entries, as POV-Ray reads them.
    pub(in crate::eval) fn spline(&mut self, node: &Node) -> Result<Spline> {
        let View::Spline { values } = node.view() else {
            return Err(crate::eval::malformed(node, "a spline"));
        };
        // (A declared spline first: copied.)
        let declared = match values {
            [
                Expr {
                    kind: ExprKind::Ident(_, slot),
                    ..
                },
                rest @ ..,
            ] => match self.bound(*slot) {
                Some(Value::Spline(s)) => Some(((**s).clone(), rest)),
                _ => None,
            },
            _ => None,
        };
        let (mut spline, args) = declared.unwrap_or((Spline::new(SplineKind::Linear), values));
        for item in &node.children {
            match SplineKind::named(&item.word) {
                Some(named) if item.kind == NodeKind::IdentRef => spline = spline.with_kind(named),
                // (`#default { … }` among the entries: run where it stands, as POV-Ray does.)
                _ if item.kind == NodeKind::Default => self.statement(item)?,
                _ => return Err(self.unknown_item(item, "spline")),
            }
        }
        let pairs = args.chunks_exact(2);
        if let [last] = pairs.remainder() {
            return Err(Diagnostic::error(
                "a spline's entries come in pairs: a parameter, then its vector",
                last.span,
            ));
        }
        let mut entries = Vec::with_capacity(pairs.len());
        for pair in pairs {
            let [t_expr, v_expr] = pair else {
                continue;
            };
            let t = self.float(t_expr)?;
            let v = self.eval(v_expr)?;
            let (values, terms) = match v {
                // (A float stands for a vector of it, as POV-Ray promotes it.)
                Value::Float(f) => ([f; 5], 1),
                Value::Vector(v) => (v.c, v.len),
                Value::Colour(c) => (c, 5),
                other => return Err(type_error("a vector", &other, v_expr.span)),
            };
            self.charge(1, "spline entry", t_expr.span)?;
            entries.push((t, values, terms));
        }
        spline.extend(entries);
        if spline.is_empty() {
            return Err(Diagnostic::error(
                "a spline needs at least one entry",
                node.word_span,
            ));
        }
        Ok(spline)
    }

    /// `S(t)` or `S(t, kind)`: the spline's vector at t.
    pub(in crate::eval) fn call_spline(
        &mut self,
        spline: &Spline,
        name: &str,
        args: &[Expr],
        span: Span,
    ) -> Result<Value> {
        let (t, kind) = match args {
            [t] => (t, None),
            [t, kind] => (t, Some(kind)),
            _ => {
                return Err(Diagnostic::error(
                    format!("the spline `{name}` takes a parameter and, optionally, a spline kind"),
                    span,
                ));
            }
        };
        let t = self.float(t)?;
        let v = match kind {
            Some(e) => {
                let kind = match &e.kind {
                    ExprKind::Ident(k, _) => SplineKind::named(k),
                    _ => None,
                }
                .ok_or_else(|| {
                    Diagnostic::error(
                        "expected linear_spline, quadratic_spline, cubic_spline or natural_spline",
                        e.span,
                    )
                })?;
                spline.with_kind(kind).at(t)
            }
            None => spline.at(t),
        };
        Ok(Value::Vector(crate::eval::value::Vector::new(
            &v[..spline.terms],
        )))
    }

    /// Appends the program of `e` to `code`.
    fn compile(&mut self, e: &Expr, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        let not_here = |what: &str, span: Span| {
            Err(Diagnostic::error(
                format!("{what} cannot stand in a function (POV-Ray's function syntax)"),
                span,
            ))
        };
        match &e.kind {
            ExprKind::Number(n) => code.push(Op::Const(*n)),
            ExprKind::Ident(name, slot) => {
                // As in POV-Ray, u is the parameter x and v the parameter y.
                let alias = |a: &str, b: &str| params.iter().position(|p| p == a || p == b);
                let register = match name.as_str() {
                    "x" | "u" => alias("x", "u"),
                    "y" | "v" => alias("y", "v"),
                    _ => None,
                };
                if let Some(i) = register.or_else(|| params.iter().rposition(|p| p == name)) {
                    code.push(Op::Arg(i as u8));
                    return Ok(());
                }
                match self.ident(name, *slot, e.span)? {
                    Value::Float(f) => code.push(Op::Const(f)),
                    Value::Function(_) => {
                        return Err(Diagnostic::error(
                            format!(
                                "the function `{name}` is called with its arguments: {name}(x, y, z)"
                            ),
                            e.span,
                        ));
                    }
                    other => {
                        return Err(Diagnostic::error(
                            format!(
                                "`{name}` is {} here: a function uses numbers, its parameters and other functions",
                                other.kind_name()
                            ),
                            e.span,
                        ));
                    }
                }
            }
            ExprKind::Unary(op, a) => match op {
                UnOp::Plus => self.compile(a, params, code)?,
                UnOp::Neg => {
                    self.compile(a, params, code)?;
                    code.push(Op::Neg);
                }
                UnOp::Not => return not_here("`!`", e.span),
            },
            ExprKind::Binary(op, a, b) => {
                self.compile(a, params, code)?;
                self.compile(b, params, code)?;
                code.push(match op {
                    BinOp::Add => Op::Add,
                    BinOp::Sub => Op::Sub,
                    BinOp::Mul => Op::Mul,
                    BinOp::Div => Op::Div,
                    BinOp::Lt => Op::Lt,
                    BinOp::Le => Op::Le,
                    BinOp::Gt => Op::Gt,
                    BinOp::Ge => Op::Ge,
                    BinOp::Eq => Op::Eq,
                    BinOp::Ne => Op::Ne,
                    BinOp::And => Op::And,
                    BinOp::Or => Op::Or,
                });
            }
            ExprKind::Call(name, name_span, slot, args) => {
                self.compile_call(name, *name_span, *slot, args, e.span, params, code)?
            }
            ExprKind::Ternary(..) => return not_here("`? :` (use select(a, b, c))", e.span),
            ExprKind::Member(base, member, member_span) => {
                // `F(x, y, z).red`: one value of a vector function (a pigment's colour …).
                let ExprKind::Call(name, name_span, slot, args) = &base.kind else {
                    return not_here(
                        "a member (`.x`, `.red` …) of anything but a pigment or spline function's value",
                        e.span,
                    );
                };
                let f = match self.ident(name, *slot, *name_span)? {
                    Value::Function(f) => f,
                    other => {
                        return Err(Diagnostic::error(
                            format!("`{name}` is {}, not a function", other.kind_name()),
                            *name_span,
                        ));
                    }
                };
                let Some(native) = f.vector.clone() else {
                    return Err(Diagnostic::error(
                        format!("`{name}` gives one number: it has no member `.{member}`"),
                        *member_span,
                    ));
                };
                let index = member_index(member, native.size()).ok_or_else(|| {
                    Diagnostic::error(
                        format!(
                            "`.{member}` is not a member of `{name}`'s value (x, y, z, t, u, v, red, green, blue, filter, transmit, gray)"
                        ),
                        *member_span,
                    )
                })?;
                check_arity(name, f.params, args.len(), base.span)?;
                for a in args {
                    self.compile(a, params, code)?;
                }
                code.push(Op::Native(native, index));
            }
            ExprKind::Vector(_) | ExprKind::PlainVector(..) => return not_here("a vector", e.span),
            ExprKind::Str(_) => return not_here("a string", e.span),
            ExprKind::Index(..) => {
                // An array element holding a float is a constant.
                match self.eval(e)? {
                    Value::Float(f) => code.push(Op::Const(f)),
                    other => {
                        return Err(Diagnostic::error(
                            format!(
                                "this element is {}: a function uses numbers",
                                other.kind_name()
                            ),
                            e.span,
                        ));
                    }
                }
            }
            _ => return not_here("this", e.span),
        }
        Ok(())
    }

    #[allow(clippy::too_many_arguments)]
    fn compile_call(
        &mut self,
        name: &str,
        name_span: Span,
        slot: Slot,
        args: &[Expr],
        span: Span,
        params: &[String],
        code: &mut Vec<Op>,
    ) -> Result<()> {
        let operands = |ev: &mut Self, code: &mut Vec<Op>| -> Result<()> {
            for a in args {
                ev.compile(a, params, code)?;
            }
            Ok(())
        };
        if let Some(m) = Math1::named(name) {
            check_arity(name, 1, args.len(), span)?;
            operands(self, code)?;
            code.push(Op::Math1(m));
        } else if let Some(m) = Math2::named(name) {
            check_arity(name, 2, args.len(), span)?;
            operands(self, code)?;
            code.push(Op::Math2(m));
        } else if name == "min" || name == "max" {
            if args.len() < 2 {
                return Err(Diagnostic::error(
                    format!("`{name}` takes at least 2 arguments"),
                    span,
                ));
            }
            if args.len() > 255 {
                return Err(Diagnostic::error(
                    format!("`{name}` takes at most 255 arguments here"),
                    span,
                ));
            }
            operands(self, code)?;
            let n = args.len() as u8;
            code.push(if name == "min" {
                Op::Min(n)
            } else {
                Op::Max(n)
            });
        } else if name == "sum" || name == "prod" {
            // sum(i, a, b, f): the term is a function of this one's parameters and i.
            let [counter, from, to, term_expr] =
                crate::eval::lang::expr::arguments(name, args, span)?;
            let ExprKind::Ident(var, _) = &counter.kind else {
                return Err(Diagnostic::error(
                    format!("`{name}` counts with a name: {name}(i, a, b, f)"),
                    counter.span,
                ));
            };
            if params.len() + 1 > crate::func::MAX_STACK {
                return Err(Diagnostic::error(
                    format!("`{name}` nested too deeply"),
                    span,
                ));
            }
            self.compile(from, params, code)?;
            self.compile(to, params, code)?;
            let mut inner: Vec<String> = params.to_vec();
            inner.push(var.clone());
            let mut term = Vec::new();
            self.compile(term_expr, &inner, &mut term)?;
            let term = Function::new(inner.len(), term).ok_or_else(|| {
                Diagnostic::error(
                    format!("the term of this `{name}` nests too deeply"),
                    term_expr.span,
                )
            })?;
            code.push(Op::Loop(Arc::new(term), name == "prod"));
        } else if name == "select" {
            if !(3..=4).contains(&args.len()) {
                return Err(Diagnostic::error("`select` takes 3 or 4 arguments", span));
            }
            operands(self, code)?;
            code.push(if args.len() == 3 {
                Op::Select3
            } else {
                Op::Select4
            });
        } else {
            match self.ident(name, slot, name_span)? {
                Value::Function(f) if f.vector.is_some() => {
                    return Err(Diagnostic::error(
                        format!(
                            "`{name}` gives several values: a function uses one of them, as in {name}(x, y, z).red or .gray"
                        ),
                        span,
                    ));
                }
                Value::Function(f) => {
                    check_arity(name, f.params, args.len(), span)?;
                    operands(self, code)?;
                    code.push(Op::Call(f));
                }
                other => {
                    return Err(Diagnostic::error(
                        format!(
                            "`{name}` is {}, not a function this function can call",
                            other.kind_name()
                        ),
                        name_span,
                    ));
                }
            }
        }
        Ok(())
    }

    /// The noise generator functions use while the scene is read (global_settings' so far,
    /// else POV-Ray's default for the version).
    pub(in crate::eval) fn noise_generator(&self) -> u8 {
        self.lang
            .noise_generator
            .unwrap_or(if self.lang.version.is_some_and(|v| v < 3.5 - 1e-9) {
                1
            } else {
                2
            })
    }

    /// `F(a, b, …)` in an expression: the declared function's value.
    pub(in crate::eval) fn call_function(
        &mut self,
        f: &Function,
        name: &str,
        args: &[Expr],
        span: Span,
    ) -> Result<Value> {
        check_arity(name, f.params, args.len(), span)?;
        let mut values = Vec::with_capacity(args.len());
        for a in args {
            values.push(self.float(a)?);
        }
        let generator = self.noise_generator();
        Ok(match &f.vector {
            Some(native) => {
                let v = native.eval(&values, generator);
                match native.size() {
                    5 => Value::Colour(v),
                    n => Value::Vector(crate::eval::value::Vector::new(&v[..n])),
                }
            }
            None => Value::Float(f.eval(&values, generator)),
        })
    }
}

/// The value `.member` picks from a vector function's `size` values (POV-Ray's names).
fn member_index(member: &str, size: usize) -> Option<crate::func::Member> {
    let i: crate::func::Member = match member {
        "x" | "u" | "red" => 0,
        "y" | "v" | "green" => 1,
        "z" | "blue" => 2,
        "t" | "filter" => 3,
        "transmit" => 4,
        "gray" | "grey" => return Some(crate::func::GRAY),
        _ => return None,
    };
    (usize::from(i) < size.max(3)).then_some(i)
}

/// `function { transform { … } }`: f(x, y, z) is the point (x, y, z) transformed (a vector).
#[derive(Debug, PartialEq)]
struct TransformFunction(glam::DMat4);

impl crate::func::Native for TransformFunction {
    fn params(&self) -> usize {
        3
    }

    fn size(&self) -> usize {
        3
    }

    fn eval(&self, args: &[f64], _generator: u8) -> [f64; 5] {
        let &[x, y, z, ..] = args else {
            return [0.0; 5];
        };
        let p = self.0.transform_point3(glam::DVec3::new(x, y, z));
        [p.x, p.y, p.z, 0.0, 0.0]
    }

    fn same(&self, other: &dyn crate::func::Native) -> bool {
        crate::func::same_data(self, other)
    }
}
