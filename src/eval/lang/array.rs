//! Arrays: `#declare A = array[3] {…}`, `#declare A[i] = …`, `A[i]` in expressions and where
//! an item may stand (`object { A[i] }`), `dimensions(A)` and `dimension_size(A, n)`.
//!
//! As in POV-Ray, an array is a value: `#declare B = A;` copies it, subscripts truncate toward
//! zero, every element has the same type, and reading an element never assigned is an error.
//! An element may be an array (`array[2] { array[2] {1, 2}, array[3] {3, 4, 5} }`), read and
//! assigned with more subscripts (`A[1][2]`).

use crate::diag::{Diagnostic, Span};
use crate::eval::Evaluator;
use crate::eval::value::{Array, Value};
use crate::syntax::view::Element;
use crate::syntax::{Expr, ExprKind, Node, NodeKind, Slot, View};

type Result<T> = std::result::Result<T, Diagnostic>;

/// More elements than this in one array is an error (a typo such as `array[1e9]`, not a scene).
const MAX_ELEMENTS: usize = 1 << 24;

/// Where the array a name stands for is found: bound in the unit being evaluated (an element
/// read), or among the declarations (an element assigned, or tested by `#ifdef`).
#[derive(Clone, Copy)]
enum Holder {
    Bound(Slot),
    Declared,
}

impl Evaluator<'_> {
    /// `array[d1][d2]… { … }`.
    pub(in crate::eval) fn array_value(&mut self, node: &Node) -> Result<Value> {
        let mut dims = Vec::new();
        for (sub, size) in node.children.iter().filter_map(|c| match c.view() {
            View::Subscript(size) => Some((c, size)),
            _ => None,
        }) {
            let n = self.float(size)?.trunc();
            if !(1.0..=MAX_ELEMENTS as f64).contains(&n) {
                return Err(Diagnostic::error(
                    format!("an array dimension must be from 1 to {MAX_ELEMENTS}, found {n}"),
                    sub.span,
                ));
            }
            dims.push(n as usize);
        }
        let total = dims.iter().try_fold(1usize, |acc, &d| acc.checked_mul(d));
        let Some(total) = total.filter(|&t| t <= MAX_ELEMENTS) else {
            return Err(Diagnostic::error(
                format!("an array may hold at most {MAX_ELEMENTS} elements"),
                node.span,
            ));
        };
        let mut array = Array {
            dims,
            items: Vec::new(),
        };
        match node.children.iter().find(|c| c.kind == NodeKind::ArrayInit) {
            Some(init) => {
                let dims = array.dims.clone();
                self.array_init(init, &dims, &mut array.items)?;
            }
            None => array.items = vec![None; total],
        }
        Ok(Value::Array(Box::new(array)))
    }

    /// The elements of `init`, which must have the shape `dims`, appended to `out`.
    fn array_init(
        &mut self,
        init: &Node,
        dims: &[usize],
        out: &mut Vec<Option<Value>>,
    ) -> Result<()> {
        let elems = &init.children;
        if elems.len() != dims[0] {
            return Err(Diagnostic::error(
                format!(
                    "this array dimension has {} elements, the initializer gives {}",
                    dims[0],
                    elems.len()
                ),
                init.span,
            ));
        }
        for elem in elems {
            let nested = match elem.view() {
                View::ArrayElem(Element::Item(inner)) if inner.kind == NodeKind::ArrayInit => {
                    Some(inner)
                }
                _ => None,
            };
            match (nested, dims.len()) {
                (Some(inner), n) if n > 1 => self.array_init(inner, &dims[1..], out)?,
                (None, 1) => {
                    let value = match elem.view() {
                        View::ArrayElem(Element::Item(item)) if item.kind == NodeKind::Array => {
                            self.array_value(item)?
                        }
                        View::ArrayElem(Element::Item(item)) => self.item_value(item)?,
                        View::ArrayElem(Element::Value(value)) => self.eval(value)?,
                        _ => return Err(crate::eval::malformed(elem, "an array element")),
                    };
                    if let Some(Some(first)) = out.first() {
                        same_kind(first, &value, elem.span)?;
                    }
                    out.push(Some(value));
                }
                (Some(_), _) => {
                    return Err(Diagnostic::error(
                        "expected an element, found `{` (the array has fewer dimensions)",
                        elem.span,
                    ));
                }
                (None, _) => {
                    return Err(Diagnostic::error(
                        format!(
                            "expected `{{` opening the {} elements of a dimension",
                            dims[1]
                        ),
                        elem.span,
                    ));
                }
            }
        }
        Ok(())
    }

    /// The row-major position of the element `name[subscripts…]` in each array along the way:
    /// an array's element may itself be an array, subscripted further (`A[1][2]` of an array
    /// of arrays).
    fn element_path(
        &mut self,
        name: &str,
        holder: Holder,
        name_span: Span,
        subs: &[&Expr],
    ) -> Result<Vec<usize>> {
        let mut indices = Vec::with_capacity(subs.len());
        for sub in subs {
            indices.push((self.float(sub)?.trunc(), sub.span));
        }
        let mut array = match self.holder_value(name, holder) {
            Some(Value::Array(a)) => a,
            Some(other) => {
                return Err(Diagnostic::error(
                    format!("`{name}` is {}, not an array", other.kind_name()),
                    name_span,
                ));
            }
            None => return Err(self.unknown_word(name, name_span)),
        };
        let mut path = Vec::new();
        let mut rest = &indices[..];
        loop {
            let n = array.dims.len();
            if rest.len() < n {
                let last = rest.last().map_or(name_span, |(_, s)| *s);
                return Err(Diagnostic::error(
                    format!(
                        "`{name}` has {} dimension(s), {} subscript(s) given",
                        array.dims.len(),
                        rest.len()
                    ),
                    Span {
                        start: name_span.start,
                        ..last
                    },
                ));
            }
            let mut pos = 0usize;
            for ((i, span), &d) in rest[..n].iter().zip(&array.dims) {
                if *i < 0.0 || *i >= d as f64 {
                    return Err(Diagnostic::error(
                        format!(
                            "array subscript {i} out of range: this dimension of `{name}` runs from 0 to {}",
                            d - 1
                        ),
                        *span,
                    ));
                }
                pos = pos * d + *i as usize;
            }
            path.push(pos);
            rest = &rest[n..];
            let Some((_, span)) = rest.first() else {
                return Ok(path);
            };
            array = match &array.items[pos] {
                Some(Value::Array(inner)) => inner,
                Some(other) => {
                    return Err(Diagnostic::error(
                        format!(
                            "`{name}` has {} dimension(s), {} subscript(s) given (its element is {}, not an array)",
                            array.dims.len(),
                            indices.len(),
                            other.kind_name()
                        ),
                        *span,
                    ));
                }
                None => {
                    return Err(Diagnostic::error(
                        "this array element has not been given a value",
                        *span,
                    ));
                }
            };
        }
    }

    /// `A[i]…` in an expression.
    pub(in crate::eval) fn index_expr(&mut self, expr: &Expr) -> Result<Value> {
        let mut subs = Vec::new();
        let mut base = expr;
        while let ExprKind::Index(inner, index) = &base.kind {
            subs.push(index.as_ref());
            base = inner;
        }
        subs.reverse();
        let ExprKind::Ident(name, name_slot) = &base.kind else {
            return Err(Diagnostic::error(
                "only a declared array can be subscripted",
                base.span,
            ));
        };
        self.element(name, *name_slot, base.span, &subs, expr.span)
    }

    /// The value `name` stands for, from `holder`.
    fn holder_value(&self, name: &str, holder: Holder) -> Option<&Value> {
        match holder {
            Holder::Bound(slot) => self.bound(slot),
            Holder::Declared => self.lang.env.get(name).map(|v| &**v),
        }
    }

    /// A copy of the element `name[subs…]`, `name` bound in `slot`.
    fn element(
        &mut self,
        name: &str,
        name_slot: Slot,
        name_span: Span,
        subs: &[&Expr],
        span: Span,
    ) -> Result<Value> {
        let holder = Holder::Bound(name_slot);
        let path = self.element_path(name, holder, name_span, subs)?;
        match self.holder_value(name, holder) {
            Some(Value::Array(a)) => match slot(a, &path) {
                Some(v) => Ok(v.clone()),
                None => Err(Diagnostic::error(
                    "this array element has not been given a value",
                    span,
                )),
            },
            _ => unreachable!("element_path checked that `{name}` is an array"),
        }
    }

    /// `T` or `A[i]` where an item may stand.
    pub(in crate::eval) fn item_ref(&mut self, node: &Node) -> Result<Value> {
        if node.children.is_empty() {
            return match self.bound(node.slot) {
                Some(v) => self.usable(&node.word, v.clone(), node.span),
                None => Err(self.unknown_word(&node.word, node.span)),
            };
        }
        let subs: Vec<&Expr> = subscripts(&node.children);
        self.element(&node.word, node.slot, node.word_span, &subs, node.span)
    }

    /// `#ifdef (A[i])`: whether the element has been assigned (out of range is an error, as in
    /// POV-Ray).
    pub(in crate::eval) fn element_assigned(&mut self, node: &Node) -> Result<bool> {
        let subs: Vec<&Expr> = subscripts(&node.children);
        let path = self.element_path(&node.word, Holder::Declared, node.word_span, &subs)?;
        let Some(Value::Array(array)) = self.lang.env.get(node.word.as_str()).map(|v| &**v) else {
            unreachable!("element_path checked that the name is an array");
        };
        Ok(slot(array, &path).is_some())
    }

    /// `#undef A[i]`: the element has no value again.
    pub(in crate::eval) fn unassign_element(&mut self, node: &Node) -> Result<()> {
        let subs: Vec<&Expr> = subscripts(&node.children);
        let path = self.element_path(&node.word, Holder::Declared, node.word_span, &subs)?;
        let Some(Value::Array(array)) = self
            .lang
            .env
            .get_mut(node.word.as_str())
            .map(std::sync::Arc::make_mut)
        else {
            unreachable!("element_path checked that the name is an array");
        };
        let (array, pos) = slot_mut(array, &path);
        array.items[pos] = None;
        Ok(())
    }

    /// `#declare A[i]… = value`.
    pub(in crate::eval) fn assign_element(
        &mut self,
        name: &Node,
        subs: &[&Node],
        value: Value,
    ) -> Result<()> {
        let exprs: Vec<&Expr> = subs.iter().filter_map(|s| subscript(s)).collect();
        let path = self.element_path(&name.word, Holder::Declared, name.span, &exprs)?;
        let Some(Value::Array(array)) = self
            .lang
            .env
            .get_mut(name.word.as_str())
            .map(std::sync::Arc::make_mut)
        else {
            unreachable!("element_path checked that the name is an array");
        };
        let (array, pos) = slot_mut(array, &path);
        if let Some(existing) = array.items.iter().flatten().next() {
            let span = Span {
                end: subs.last().map_or(name.span.end, |s| s.span.end),
                ..name.span
            };
            same_kind(existing, &value, span)?;
        }
        array.items[pos] = Some(value);
        Ok(())
    }

    /// `dimensions(A)` and `dimension_size(A, n)`.
    pub(in crate::eval) fn array_dimensions(
        &mut self,
        name: &str,
        args: &[Expr],
        span: Span,
    ) -> Result<f64> {
        let (array, which) = match (name, args) {
            ("dimensions", [array]) => (array, None),
            ("dimension_size", [array, which]) => (array, Some(which)),
            _ => {
                let want = if name == "dimensions" { 1 } else { 2 };
                return Err(Diagnostic::error(
                    format!("`{name}` takes {want} argument(s), found {}", args.len()),
                    span,
                ));
            }
        };
        let dims = match &array.kind {
            ExprKind::Index(..) => match self.index_expr(array)? {
                Value::Array(a) => a.dims.clone(),
                other => {
                    return Err(crate::eval::lang::expr::type_error(
                        "an array", &other, array.span,
                    ));
                }
            },
            ExprKind::Ident(id, name_slot) => match self.bound(*name_slot) {
                Some(Value::Array(a)) => a.dims.clone(),
                Some(other) => {
                    return Err(crate::eval::lang::expr::type_error(
                        "an array", other, array.span,
                    ));
                }
                None => return Err(self.unknown_word(id, array.span)),
            },
            _ => {
                return Err(Diagnostic::error(
                    "expected the name of an array",
                    array.span,
                ));
            }
        };
        let Some(which) = which else {
            return Ok(dims.len() as f64);
        };
        let n = self.float(which)?.trunc();
        if n < 1.0 || n > dims.len() as f64 {
            // POV-Ray's answer here is not consistent (0, or a stale size): an error instead.
            return Err(Diagnostic::error(
                format!("the array has dimensions 1 to {}, not {n}", dims.len()),
                which.span,
            ));
        }
        Ok(dims[n as usize - 1] as f64)
    }
}

/// The element slot `path` (from [`Evaluator::element_path`]) leads to.
fn slot<'a>(array: &'a Array, path: &[usize]) -> &'a Option<Value> {
    let (last, inner) = path.split_last().expect("a path has a position");
    let mut a = array;
    for &p in inner {
        let Some(Value::Array(next)) = &a.items[p] else {
            unreachable!("element_path walked through arrays only");
        };
        a = next;
    }
    &a.items[*last]
}

/// [`slot`], to assign to, with the array holding it.
fn slot_mut<'a>(array: &'a mut Array, path: &[usize]) -> (&'a mut Array, usize) {
    let (last, inner) = path.split_last().expect("a path has a position");
    let mut a = array;
    for &p in inner {
        let Some(Value::Array(next)) = &mut a.items[p] else {
            unreachable!("element_path walked through arrays only");
        };
        a = next;
    }
    (a, *last)
}

/// POV-Ray keeps one type per array: an element of another kind is an error.
fn same_kind(existing: &Value, new: &Value, span: Span) -> Result<()> {
    if std::mem::discriminant(existing) == std::mem::discriminant(new) {
        return Ok(());
    }
    Err(Diagnostic::error(
        format!(
            "this array holds {}s; an element cannot be {}",
            existing
                .kind_name()
                .trim_start_matches("an ")
                .trim_start_matches("a "),
            new.kind_name()
        ),
        span,
    ))
}

/// The index of a subscript (`[i]`).
fn subscript(node: &Node) -> Option<&Expr> {
    match node.view() {
        View::Subscript(index) => Some(index),
        _ => None,
    }
}

/// The indices of an element's subscripts (`A[i][j]`).
fn subscripts(nodes: &[Node]) -> Vec<&Expr> {
    nodes.iter().filter_map(subscript).collect()
}
