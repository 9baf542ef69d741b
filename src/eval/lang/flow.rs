//! The language's values and declarations: `#declare`/`#local` bindings and their scopes
//! (macro calls and included files), `#ifdef`'s test, strings and their functions, the
//! evaluation budget.
//!
//! The directives themselves are carried out by the directive reader (`reader.rs`) where it
//! meets them; what is here is what they and the rest of evaluation share.

use crate::diag::{Diagnostic, Span};
use crate::eval::{
    Evaluator, Result, Value,
    lang::expr::{STRING_FUNCTIONS, check_arity, type_error},
};
use crate::syntax::{self, ExprKind, Node, NodeKind, ValueSyntax, View};
use std::sync::Arc;

/// Longest string a string function may make (a string doubled in a loop stops here).
pub const MAX_STRING_BYTES: usize = 1 << 20;
/// Widest field and most decimals `str`/`vstr` write.
const MAX_FORMAT_WIDTH: f64 = 1000.0;

/// Deepest nesting of macro calls.
pub const MAX_MACRO_DEPTH: usize = 200;
/// Deepest nesting of include files.
pub const MAX_INCLUDE_DEPTH: usize = 64;

/// A declared macro: its parameters and where its body's text lies.
#[derive(Clone, Debug)]
pub struct Macro {
    pub(in crate::eval) params: Vec<String>,
    pub(in crate::eval) body: Span,
    pub(in crate::eval) name_span: Span,
}

/// One macro call (or included file) in progress: the variables its parameters and `#local`s
/// shadow (restored when it returns) and its by-reference arguments (parameter, caller's
/// variable).
#[derive(Default)]
pub(in crate::eval) struct Frame {
    pub(in crate::eval) saved: Vec<(String, Option<Arc<Value>>)>,
    pub(in crate::eval) by_reference: Vec<(String, String)>,
}

/// A block item handler.
pub(in crate::eval) type Handler<'h, 'a> = dyn FnMut(&mut Evaluator<'a>, &Node) -> Result<()> + 'h;

impl<'a> Evaluator<'a> {
    /// Hands each of `items` to `f` in order, one evaluation step each.
    pub(in crate::eval) fn each_item(
        &mut self,
        items: &[Node],
        f: &mut Handler<'_, 'a>,
    ) -> Result<()> {
        for item in items {
            self.charge(1, "statement", item.word_span)?;
            match item.view() {
                // (A member a loop made again: its words are bound `by` slots further on.)
                View::Again { member, by } => {
                    self.lang.slot_shift += by;
                    let result = f(self, member);
                    self.lang.slot_shift -= by;
                    result?
                }
                _ => f(self, item)?,
            }
        }
        Ok(())
    }

    /// Binds `name` to `value`.
    pub(in crate::eval) fn set(&mut self, name: String, value: Value) {
        self.lang.env.insert(name, Arc::new(value));
    }

    /// The value of a declared value's syntax.
    pub(in crate::eval) fn declared_value(&mut self, syntax: &ValueSyntax) -> Result<Value> {
        let value = match syntax {
            ValueSyntax::Expr(e) => self.eval(e),
            ValueSyntax::Item(item) => match item.kind {
                NodeKind::Array => return self.array_value(item),
                NodeKind::Function => self.function(item).map(Value::Function),
                NodeKind::IdentRef => self.lookup(item),
                _ => self.item_value(item),
            },
        };
        value.or_else(unsupported_later)
    }

    /// Binds a declaration's value: `node` is its head (name, subscripts, deprecation).
    /// `local` is, for `#local`, the number of macro and include frames open where the
    /// directive stands: the name is local to the innermost of those (not to a macro called
    /// while the value was read).
    pub(in crate::eval) fn bind_declared(
        &mut self,
        node: &Node,
        local: Option<usize>,
        value: Value,
    ) -> Result<()> {
        let View::Declare {
            deprecation,
            name: name_node,
            subscripts,
        } = node.view()
        else {
            return Err(crate::eval::malformed(node, "a declaration"));
        };
        let name = name_node.word.to_string();
        let subs: Vec<&Node> = subscripts
            .iter()
            .filter(|c| c.kind == NodeKind::Subscript)
            .collect();
        if !subs.is_empty() {
            if let Value::Unsupported(d) = value {
                return Err(*d);
            }
            return self.assign_element(name_node, &subs, value);
        }
        if let Some(depth) = local {
            self.shadow_in(&name, depth);
        }
        match deprecation {
            Some(d) => {
                let View::Deprecation(message) = d.view() else {
                    return Err(crate::eval::malformed(d, "deprecated"));
                };
                let message = self.string(message)?;
                self.lang.deprecated.insert(name.clone(), message);
            }
            None => {
                self.lang.deprecated.remove(&name);
            }
        }
        self.set(name, value);
        Ok(())
    }

    /// A declared float, vector or colour without its `;` (at `at`): accepted with a warning
    /// before version 3.5, refused after, as POV-Ray does.
    pub(in crate::eval) fn missing_semicolon(&mut self, at: Span) -> Result<()> {
        if self.lang.version.is_some_and(|v| v < 3.5 - 1e-9) {
            self.warn(Diagnostic::warning(
                "a declared float, vector or colour wants a `;` after it (POV-Ray warns before version 3.5)",
                at,
            ));
            return Ok(());
        }
        Err(Diagnostic::error(
            "expected `;`: a declared float, vector or colour ends with one from version 3.5 on (as in POV-Ray; before it, a warning)",
            at,
        ))
    }

    /// Records the current value of `name` in the innermost macro frame (once), so that it is
    /// restored when the macro returns.
    pub(in crate::eval) fn shadow(&mut self, name: &str) {
        self.shadow_in(name, self.lang.frames.len());
    }

    /// [`Evaluator::shadow`] in the frame that was innermost when `depth` frames were open.
    fn shadow_in(&mut self, name: &str, depth: usize) {
        if let Some(frame) = depth
            .checked_sub(1)
            .and_then(|i| self.lang.frames.get_mut(i))
        {
            if !frame.saved.iter().any(|(n, _)| n == name) {
                frame
                    .saved
                    .push((name.to_string(), self.lang.env.get(name).cloned()));
            }
        }
    }

    /// Whether `#ifdef (Name)` finds `Name` declared (a variable or a macro), or, for
    /// `(A[i])`, the array element assigned.
    pub(in crate::eval) fn defined(&mut self, name: &Node) -> Result<bool> {
        if name.children.is_empty() {
            return Ok(self.lang.env.contains_key(name.word.as_str())
                || self.lang.macros.contains_key(name.word.as_str()));
        }
        self.element_assigned(name)
    }

    /// `#default { texture/pigment/finish/normal … }`: the defaults of what follows.
    pub(in crate::eval) fn default_directive(&mut self, node: &Node) -> Result<()> {
        self.statement(node)
    }

    /// A string value: a literal, `concat(…)`, `str(v, w, p)`, or a declared string.
    pub(in crate::eval) fn string(&mut self, e: &syntax::Expr) -> Result<String> {
        match &e.kind {
            ExprKind::Str(s) => Ok(crate::eval::lang::files::unescape(s)),
            ExprKind::Call(name, _, _, args) if STRING_FUNCTIONS.contains(&name.as_str()) => {
                let text = self.string_call(name, args, e.span)?;
                if text.len() > MAX_STRING_BYTES {
                    return Err(Diagnostic::error(
                        format!(
                            "`{name}` makes a string of {} bytes; trace allows at most {MAX_STRING_BYTES}",
                            text.len()
                        ),
                        e.span,
                    ));
                }
                Ok(text)
            }
            _ => match self.eval(e)? {
                Value::Str(s) => Ok(s),
                other => Err(type_error("a string", &other, e.span)),
            },
        }
    }

    /// The string functions, by name (`name` is one of [`STRING_FUNCTIONS`]).
    fn string_call(&mut self, name: &str, args: &[syntax::Expr], span: Span) -> Result<String> {
        use crate::eval::lang::expr::arguments;
        Ok(match name {
            "datetime" => {
                let (days, format) = match args {
                    [days] => (days, None),
                    [days, format] => (days, Some(format)),
                    _ => return Err(check_arity(name, 2, args.len(), span).unwrap_err()),
                };
                let days = self.float(days)?;
                let format = match format {
                    Some(f) => {
                        let text = self.string(f)?;
                        if text.is_empty() {
                            return Err(Diagnostic::error("empty format string", f.span));
                        }
                        text
                    }
                    None => "%Y-%m-%d %H:%M:%SZ".to_string(),
                };
                crate::eval::lang::datetime::format(days, &format)
            }
            "concat" => {
                if args.is_empty() {
                    check_arity(name, 1, 0, span)?;
                }
                let mut out = String::new();
                for a in args {
                    out += &self.string(a)?;
                    if out.len() > MAX_STRING_BYTES {
                        break; // reported by the caller
                    }
                }
                out
            }
            "chr" => {
                let [code] = arguments(name, args, span)?;
                let code = self.float(code)? as u32;
                char::from_u32(code).map(String::from).unwrap_or_default()
            }
            "substr" => {
                let [text, start, len] = arguments(name, args, span)?;
                let text = self.string(text)?;
                let (start, len) = (self.float(start)?, self.float(len)?);
                let count = text.chars().count() as f64;
                if !(start >= 1.0 && len >= 0.0 && start - 1.0 + len <= count) {
                    return Err(Diagnostic::error(
                        "substr: position and length outside the string",
                        span,
                    ));
                }
                text.chars()
                    .skip(start as usize - 1)
                    .take(len as usize)
                    .collect()
            }
            "strupr" | "strlwr" => {
                let [text] = arguments(name, args, span)?;
                let text = self.string(text)?;
                if name == "strupr" {
                    text.to_uppercase()
                } else {
                    text.to_lowercase()
                }
            }
            "str" => {
                let [v, width, precision] = arguments(name, args, span)?;
                let v = self.float(v)?;
                let (width, precision) = (self.float(width)?, self.float(precision)?);
                format_float(v, width, precision, span)?
            }
            _ => {
                // vstr(N, V, separator, width, precision)
                let [n, v_expr, separator, width, precision] = arguments(name, args, span)?;
                let n = self.float(n)?.clamp(1.0, 5.0) as usize;
                let v = self.eval(v_expr)?;
                let Some((components, _)) = v.components() else {
                    return Err(type_error("a vector", &v, v_expr.span));
                };
                let separator = self.string(separator)?;
                let (width, precision) = (self.float(width)?, self.float(precision)?);
                let mut parts = Vec::with_capacity(n);
                // Missing components (and all but the first of a float) are zeros.
                for c in &components[..n] {
                    parts.push(format_float(*c, width, precision, span)?);
                }
                parts.join(&separator)
            }
        })
    }

    /// Counts `cost` steps against the scene's evaluation budget
    /// ([`LoadOptions::max_steps`](crate::eval::LoadOptions)), shared by everything the scene runs:
    /// a statement or block item is one step, a loop pass one, a macro call a few (see
    /// `reader.rs`). Nested loops cannot run for hours.
    pub(in crate::eval) fn charge(&mut self, cost: u64, what: &str, span: Span) -> Result<()> {
        let before = self.lang.steps;
        self.lang.steps = before.saturating_add(cost);
        // (The caller's cancel flag, looked at once every 4096 steps.)
        if (before ^ self.lang.steps) >> 12 != 0 && self.options.cancel.is_cancelled() {
            return Err(Diagnostic::error(
                format!("evaluation stopped at this {what}: the load was cancelled"),
                span,
            ));
        }
        if self.lang.steps <= self.options.max_steps {
            return Ok(());
        }
        Err(Diagnostic::error(
            format!(
                "evaluation stopped at this {what}: the scene has used its budget of {} steps (statements, loop passes, macro calls; an endless loop?)",
                self.options.max_steps
            ),
            span,
        )
        .with_note("raise the limit with --max-steps N"))
    }

    /// Leaves the innermost macro (or include file): copies by-reference arguments back,
    /// restores shadowed variables.
    pub(in crate::eval) fn return_from_macro(&mut self) {
        let frame = self.lang.frames.pop().expect("a macro frame");
        let back: Vec<(String, Arc<Value>)> = frame
            .by_reference
            .iter()
            .filter_map(|(param, caller)| {
                self.lang
                    .env
                    .get(param)
                    .map(|v| (caller.clone(), v.clone()))
            })
            .collect();
        for (name, old) in frame.saved.into_iter().rev() {
            match old {
                Some(v) => self.lang.env.insert(name, v),
                None => self.lang.env.remove(&name),
            };
        }
        for (caller, v) in back {
            self.lang.env.insert(caller, v);
        }
    }

    /// `file:line:col` of a span.
    pub(in crate::eval) fn location(&self, span: Span) -> String {
        self.sources.location(span)
    }
}

fn unsupported_later(d: Diagnostic) -> Result<Value> {
    // (Using a declaration that was itself outside the subset defers the same way.)
    if d.message.starts_with("unsupported:") || d.message.contains("cannot be used: unsupported:") {
        Ok(Value::Unsupported(Box::new(d)))
    } else {
        Err(d)
    }
}

/// A number as `str(V, L, P)` writes it: at least `width` characters (padded with zeros when
/// `width` is negative), `precision` decimals (6 when negative). Widths and precisions are
/// bounded by [`MAX_FORMAT_WIDTH`].
fn format_float(v: f64, width: f64, precision: f64, span: Span) -> Result<String> {
    if width.abs() > MAX_FORMAT_WIDTH || precision > MAX_FORMAT_WIDTH || width.is_nan() {
        return Err(Diagnostic::error(
            format!("`str`: width and precision are at most {MAX_FORMAT_WIDTH}"),
            span,
        ));
    }
    let precision = if precision < 0.0 {
        6
    } else {
        precision as usize
    };
    let w = width.abs() as usize;
    Ok(if width < 0.0 {
        format!("{v:0w$.precision$}")
    } else {
        format!("{v:w$.precision$}")
    })
}
