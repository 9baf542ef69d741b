//! Directives that steer evaluation: `#declare`/`#local`/`#undef`, `#if`/`#ifdef`/`#while`/
//! `#for`/`#switch`, `#macro` and macro calls, `#include`, `#debug`/`#warning`/`#error`.
//!
//! Every block of the scene (the file, an object's modifiers, a finish …) is run through
//! [`Evaluator::each_item`], which executes these directives in order and hands every other
//! item to the block's own handler. Loops, macro recursion and include depth are bounded.

use super::{
    Evaluator, Result, Value,
    expr::{STRING_FUNCTIONS, check_arity, type_error},
};
use crate::diag::{Diagnostic, Span};
use crate::syntax::{self, ExprKind, Node, NodeKind};
use std::sync::Arc;

/// Longest string a string function may make (a string doubled in a loop stops here).
pub const MAX_STRING_BYTES: usize = 1 << 20;
/// Widest field and most decimals `str`/`vstr` write.
const MAX_FORMAT_WIDTH: f64 = 1000.0;
/// Evaluation steps a macro call costs besides the statements its body runs (measured: a call
/// of a one-line expression macro takes 0.7 µs, a loop pass with two `#declare`s 0.5 µs).
const MACRO_CALL_STEPS: u64 = 4;
/// Bytes of a macro's body that cost one step when the body is parsed (once, at its first call).
const MACRO_PARSE_BYTES_PER_STEP: u64 = 16;
/// The key of a macro body's entry in the cache of parsed bodies.
fn macro_key(body: Span) -> (u32, u32) {
    (body.file.0, body.start)
}

/// Deepest nesting of macro calls.
pub const MAX_MACRO_DEPTH: usize = 200;
/// Deepest nesting of include files.
pub const MAX_INCLUDE_DEPTH: usize = 64;

/// The items a macro called as a value may give (besides objects and colours).
const VALUE_ITEMS: &[NodeKind] = &[
    NodeKind::Pigment,
    NodeKind::Normal,
    NodeKind::Finish,
    NodeKind::Texture,
    NodeKind::Interior,
    NodeKind::Material,
    NodeKind::ColourMap,
    NodeKind::PigmentMap,
    NodeKind::TextureMap,
    NodeKind::NormalMap,
    NodeKind::SlopeMap,
    NodeKind::Transform,
    NodeKind::SkySphere,
    NodeKind::Fog,
    NodeKind::Camera,
];

/// A declared macro: its parameters and where its body's text lies.
#[derive(Clone, Debug)]
pub struct Macro {
    params: Vec<String>,
    body: Span,
    name_span: Span,
}

/// A macro body's trees, each made the first time the body is read that way.
#[derive(Default)]
pub(super) struct MacroParse {
    items: Option<std::result::Result<Arc<Vec<Node>>, Diagnostic>>,
    expr: Option<std::result::Result<Arc<syntax::FragmentExpr>, Diagnostic>>,
}

/// One macro call in progress: the variables its parameters and `#local`s shadow (restored
/// when it returns) and its by-reference arguments (parameter, caller's variable).
#[derive(Default)]
pub(super) struct Frame {
    saved: Vec<(String, Option<Value>)>,
    by_reference: Vec<(String, String)>,
}

/// A block item handler.
pub(super) type Handler<'h, 'a> = dyn FnMut(&mut Evaluator<'a>, &Node) -> Result<()> + 'h;

impl<'a> Evaluator<'a> {
    /// Runs `items` in order: directives are executed here, every other item goes to `f`.
    pub(super) fn each_item(&mut self, items: &[Node], f: &mut Handler<'_, 'a>) -> Result<()> {
        for item in items {
            self.one_item(item, f)?;
        }
        Ok(())
    }

    /// Runs a file's statements as they are parsed, like [`Evaluator::each_item`].
    pub(super) fn each_statement(
        &mut self,
        statements: syntax::Statements,
        f: &mut Handler<'_, 'a>,
    ) -> Result<()> {
        let mut statements = statements;
        loop {
            let Some(statement) = statements.next() else {
                return Ok(());
            };
            let (failed, at) = match statement {
                Ok(statement) => match self.directive_in_value(&statement) {
                    None => {
                        let done = self.one_item(&statement, f);
                        // (A statement parsed ahead is freed by the thread that parsed it.)
                        statements.spent(statement);
                        done?;
                        continue;
                    }
                    // A statement read with a directive where a value is.
                    Some(_) => {
                        let at = statement.span.start as usize;
                        (
                            super::spliced::directive_in_value_error(statement.span.file, at),
                            at,
                        )
                    }
                },
                // What the grammar cannot read may be directives working on tokens.
                Err(failed) => (failed, statements.position()),
            };
            // From here the file is read as POV-Ray's token reader reads it, up to where the
            // grammar can read it whole again.
            let file = statements.file();
            drop(statements);
            let text = self.sources.file(file).text.clone();
            match self.run_spliced(file, at..text.len(), false, failed, f, true)? {
                None => return Ok(()),
                Some(resume) => {
                    let helpers = self.options.parse_helpers();
                    statements = syntax::statements_from(text, file, helpers, resume)?;
                }
            }
        }
    }

    pub(super) fn one_item(&mut self, item: &Node, f: &mut Handler<'_, 'a>) -> Result<()> {
        self.charge(1, "statement", item.word_span)?;
        match item.kind {
            NodeKind::Version => {
                self.version = Some(self.float(&item.args[0])?);
                if item
                    .children
                    .iter()
                    .any(|c| c.kind == NodeKind::MissingSemicolon)
                {
                    self.warn(Diagnostic::warning(
                        "`#version` wants a `;` after its number (POV-Ray warns too)",
                        item.args[0].span,
                    ));
                }
            }
            NodeKind::Declare | NodeKind::Local => self.declare(item)?,
            NodeKind::Undef => {
                self.env.remove(&item.children[0].word);
            }
            NodeKind::If => {
                // #if (c) body [#elseif (c) body]* [#else body] #end
                if self.truth(&item.args[0])? {
                    return self.each_item(&item.children[0].children, f);
                }
                for clause in &item.children[1..] {
                    match clause.kind {
                        NodeKind::ElseIf if self.truth(&clause.args[0])? => {
                            return self.each_item(&clause.children[0].children, f);
                        }
                        NodeKind::Else => return self.each_item(&clause.children[0].children, f),
                        _ => {}
                    }
                }
            }
            NodeKind::IfDef => {
                if self.ifdef_holds(item)? {
                    return self.each_item(&item.children[1].children, f);
                }
                if let Some(clause) = item.children.get(2) {
                    return self.each_item(&clause.children[0].children, f);
                }
            }
            NodeKind::While => {
                while self.truth(&item.args[0])? {
                    self.charge(1, "#while", item.word_span)?;
                    self.each_item(&item.children[0].children, f)?;
                }
            }
            NodeKind::For => {
                let body = &item.children[1].children;
                self.for_loop_with(item, &mut |ev| ev.each_item(body, f))?;
            }
            NodeKind::Switch => self.switch(item, f)?,
            NodeKind::Message => {
                let text = self.string(&item.args[0])?;
                match item.word.as_str() {
                    "error" => {
                        return Err(Diagnostic::error(format!("#error: {text}"), item.word_span));
                    }
                    "warning" => self.warn(Diagnostic::warning(text, item.word_span)),
                    _ => self.debug_output.push_str(&text),
                }
            }
            NodeKind::MacroDef => {
                let name = item.children[0].word.clone();
                let params = item.children[1..item.children.len() - 1]
                    .iter()
                    .map(|p| p.word.clone())
                    .collect();
                let body = item.children[item.children.len() - 1].span;
                self.macros.insert(
                    name,
                    Macro {
                        params,
                        body,
                        name_span: item.children[0].span,
                    },
                );
            }
            NodeKind::MacroCall => {
                let name = &item.children[0];
                let body = self.begin_macro(&name.word, name.span, &item.args)?;
                let result = self.run_body(body, f);
                self.end_macro(item, result)?;
            }
            NodeKind::Include => self.include(item, f)?,
            NodeKind::FileOpen | NodeKind::FileClose | NodeKind::FileRead | NodeKind::FileWrite => {
                self.file_directive(item)?;
            }
            NodeKind::UnknownDirective => {
                let span = Span {
                    start: item.span.start,
                    ..item.word_span
                };
                return Err(match super::keywords::reason(&item.word) {
                    Some(reason) => {
                        Diagnostic::error(format!("unsupported: `#{}` ({reason})", item.word), span)
                    }
                    None => Diagnostic::error(format!("unknown directive `#{}`", item.word), span),
                });
            }
            _ => f(self, item)?,
        }
        Ok(())
    }

    /// `#declare Name = value;` / `#local Name = value;`.
    fn declare(&mut self, node: &Node) -> Result<()> {
        let deprecation = node
            .children
            .first()
            .filter(|c| c.kind == NodeKind::Deprecation);
        let children = &node.children[usize::from(deprecation.is_some())..];
        let (children, missing) = match children.split_last() {
            // (Messages point at the value the `;` should follow.)
            Some((last, rest)) if last.kind == NodeKind::MissingSemicolon => {
                (rest, node.args.first().map(|e| e.span))
            }
            _ => (children, None),
        };
        let name = children[0].word.clone();
        let subs: Vec<&Node> = children
            .iter()
            .filter(|c| c.kind == NodeKind::Subscript)
            .collect();
        let mut at = 1 + subs.len();
        if let Some(leading) = children
            .get(at)
            .filter(|c| c.kind == NodeKind::LeadingDirectives)
        {
            self.each_item(&leading.children, &mut |ev, item| {
                Err(ev.unknown_item(item, "a declaration"))
            })?;
            at += 1;
        }
        let value = match children.get(at) {
            Some(item) if item.kind == NodeKind::LayeredTexture => {
                self.layered_texture(item).or_else(unsupported_later)?
            }
            Some(item) if item.kind == NodeKind::Unparsed => {
                Value::Unsupported(Box::new(self.why_unparsed(item)))
            }
            Some(item) if item.kind == NodeKind::Array => self.array_value(item)?,
            Some(item)
                if matches!(item.kind, NodeKind::If | NodeKind::IfDef | NodeKind::Switch) =>
            {
                self.directive_value(item).or_else(unsupported_later)?
            }
            Some(item) if item.kind == NodeKind::Function => self
                .function(item)
                .map(Value::Function)
                .or_else(unsupported_later)?,
            Some(item) if item.kind == NodeKind::IdentRef => {
                self.lookup(item).or_else(unsupported_later)?
            }
            Some(item) => self.item_value(item).or_else(unsupported_later)?,
            None => self.eval(&node.args[0]).or_else(unsupported_later)?,
        };
        if !subs.is_empty() {
            if let Value::Unsupported(d) = value {
                return Err(*d);
            }
            return self.assign_element(&children[0], &subs, value);
        }
        // A float, vector or colour without its `;`: accepted with a warning before version
        // 3.5, refused after, as POV-Ray does.
        if let Some(at) = missing
            && matches!(value, Value::Float(_) | Value::Vector(_) | Value::Colour(_))
        {
            if self.version.is_some_and(|v| v < 3.5 - 1e-9) {
                self.warn(Diagnostic::warning(
                    "a declared float, vector or colour wants a `;` after it (POV-Ray warns before version 3.5)",
                    at,
                ));
            } else {
                return Err(Diagnostic::error(
                    "expected `;`: a declared float, vector or colour ends with one from version 3.5 on (as in POV-Ray; before it, a warning)",
                    at,
                ));
            }
        }
        if node.kind == NodeKind::Local {
            self.shadow(&name);
        }
        match deprecation {
            Some(d) => {
                let message = self.string(&d.args[0])?;
                self.deprecated.insert(name.clone(), message);
            }
            None => {
                self.deprecated.remove(&name);
            }
        }
        self.env.insert(name, value);
        Ok(())
    }

    /// Why a declared value could not be read: an unsupported construct named by its first
    /// word, or the grammar's error.
    fn why_unparsed(&self, item: &Node) -> Diagnostic {
        let word: String = item
            .word
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let word_span = Span {
            end: item.span.start + word.len().max(1) as u32,
            ..item.span
        };
        if let Some(reason) = super::keywords::reason(&word) {
            return Diagnostic::error(format!("unsupported: `{word}` ({reason})"), word_span);
        }
        let text = &self.sources.file(item.span.file).text;
        syntax::explain_value(text, item.span.file, item.span.start as usize).unwrap_or_else(|| {
            Diagnostic::error(
                "this declaration is outside the language trace reads",
                word_span,
            )
        })
    }

    /// Records the current value of `name` in the innermost macro frame (once), so that it is
    /// restored when the macro returns.
    fn shadow(&mut self, name: &str) {
        if let Some(frame) = self.frames.last_mut() {
            if !frame.saved.iter().any(|(n, _)| n == name) {
                frame
                    .saved
                    .push((name.to_string(), self.env.get(name).cloned()));
            }
        }
    }

    /// Whether `#ifdef (Name)` (or `#ifndef`, or an array element's) takes its first branch.
    pub(super) fn ifdef_holds(&mut self, item: &Node) -> Result<bool> {
        let name = &item.children[0];
        let defined = if name.children.is_empty() {
            self.env.contains_key(&name.word)
        } else {
            self.element_assigned(name)?
        };
        Ok(defined == (item.word == "ifdef"))
    }

    /// `#for (I, start, end [, step]) body #end`: inclusive, with POV-Ray's 1e-10 slack;
    /// `pass` runs the body.
    pub(super) fn for_loop_with(
        &mut self,
        item: &Node,
        pass: &mut dyn FnMut(&mut Evaluator<'a>) -> Result<()>,
    ) -> Result<()> {
        let name = item.children[0].word.clone();
        let start = self.float(&item.args[0])?;
        let end = self.float(&item.args[1])?;
        let step = match item.args.get(2) {
            Some(e) => self.float(e)?,
            None => 1.0,
        };
        if step == 0.0 {
            return Err(Diagnostic::error(
                "#for step must not be zero",
                item.args[2].span,
            ));
        }
        let mut i = start;
        while (step > 0.0 && i <= end + 1e-10) || (step < 0.0 && i >= end - 1e-10) {
            self.charge(1, "#for", item.word_span)?;
            self.env.insert(name.clone(), Value::Float(i));
            pass(self)?;
            // The body may change the counter, as in POV-Ray.
            i = match self.env.get(&name) {
                Some(Value::Float(v)) => *v,
                _ => i,
            } + step;
        }
        Ok(())
    }

    /// `#switch (v) #case (a) … #break #range (lo, hi) … #else … #end`: the first matching
    /// clause runs, and falls through into the next ones until a `#break`.
    fn switch(&mut self, item: &Node, f: &mut Handler<'_, 'a>) -> Result<()> {
        let v = self.float(&item.args[0])?;
        let mut running = false;
        for clause in &item.children {
            match clause.kind {
                NodeKind::SwitchClause => {
                    let head = &clause.children[0];
                    if !running {
                        running = match head.kind {
                            NodeKind::CaseHead => (self.float(&head.args[0])? - v).abs() <= 1e-10,
                            _ => {
                                let (lo, hi) =
                                    (self.float(&head.args[0])?, self.float(&head.args[1])?);
                                lo <= v && v <= hi
                            }
                        };
                    }
                    if running {
                        self.each_item(&clause.children[1].children, f)?;
                        if clause.word == "break" {
                            return Ok(());
                        }
                    }
                }
                _ => return self.each_item(&clause.children[0].children, f),
            }
        }
        Ok(())
    }

    /// A string value: a literal, `concat(…)`, `str(v, w, p)`, or a declared string.
    pub(super) fn string(&mut self, e: &syntax::Expr) -> Result<String> {
        match &e.kind {
            ExprKind::Str(s) => Ok(super::files::unescape(s)),
            ExprKind::Call(name, _, args) if STRING_FUNCTIONS.contains(&name.as_str()) => {
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
        if name == "datetime" {
            if args.is_empty() || args.len() > 2 {
                check_arity(name, 2, args.len(), span)?;
            }
            let days = self.float(&args[0])?;
            let format = match args.get(1) {
                Some(f) => {
                    let f = self.string(f)?;
                    if f.is_empty() {
                        return Err(Diagnostic::error("empty format string", args[1].span));
                    }
                    f
                }
                None => "%Y-%m-%d %H:%M:%SZ".to_string(),
            };
            return Ok(super::datetime::format(days, &format));
        }
        let arity = match name {
            "concat" => args.len().max(1),
            "chr" | "strupr" | "strlwr" => 1,
            "str" | "substr" => 3,
            _ => 5, // vstr
        };
        check_arity(name, arity, args.len(), span)?;
        Ok(match name {
            "concat" => {
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
                let code = self.float(&args[0])? as u32;
                char::from_u32(code).map(String::from).unwrap_or_default()
            }
            "substr" => {
                let text = self.string(&args[0])?;
                let (start, len) = (self.float(&args[1])?, self.float(&args[2])?);
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
            "strupr" => self.string(&args[0])?.to_uppercase(),
            "strlwr" => self.string(&args[0])?.to_lowercase(),
            "str" => {
                let v = self.float(&args[0])?;
                let (width, precision) = (self.float(&args[1])?, self.float(&args[2])?);
                format_float(v, width, precision, span)?
            }
            _ => {
                let n = self.float(&args[0])?.clamp(1.0, 5.0) as usize;
                let v = self.eval(&args[1])?;
                let Some((components, _)) = v.components() else {
                    return Err(type_error("a vector", &v, args[1].span));
                };
                let separator = self.string(&args[2])?;
                let (width, precision) = (self.float(&args[3])?, self.float(&args[4])?);
                let mut parts = Vec::with_capacity(n);
                // Missing components (and all but the first of a float) are zeros.
                for c in &components[..n] {
                    parts.push(format_float(*c, width, precision, span)?);
                }
                parts.join(&separator)
            }
        })
    }

    /// The single object a macro call expands to (`object { Macro(…) modifiers }`).
    pub(super) fn macro_object(&mut self, call: &Node) -> Result<super::ObjectValue> {
        let name = &call.children[0];
        let body = self.begin_macro(&name.word, name.span, &call.args)?;
        let mut object = None;
        let result = self.run_body(body, &mut |ev, n| {
            // An unsupported construct the macro leaves (`difference { … }`): named.
            if n.kind == NodeKind::Unknown && super::keywords::reason(&n.word).is_some() {
                return Err(ev.unknown_word(&n.word, n.word_span));
            }
            if object.is_some() || !super::object::is_object(n.kind) {
                return Err(Diagnostic::error(
                    "expected the macro to give exactly one object",
                    n.word_span,
                ));
            }
            object = Some(ev.object(n)?);
            Ok(())
        });
        self.end_macro(call, result)?;
        object.ok_or_else(|| Diagnostic::error("the macro gives no object", call.span))
    }

    /// Runs a macro's body as items (read once by the grammar, or, if the grammar cannot read
    /// it whole, as POV-Ray's token reader reads it, at every call).
    fn run_body(&mut self, body: Span, f: &mut Handler<'_, 'a>) -> Result<()> {
        match self.parsed_items(body) {
            Ok(nodes) => self.each_item(&nodes, f),
            Err(failed) => {
                let region = body.start as usize..body.end as usize;
                self.run_spliced(body.file, region, true, failed, f, false)
                    .map(|_| ())
            }
        }
    }

    /// Evaluates a macro called inside an expression: its body is one expression.
    pub(super) fn macro_value(
        &mut self,
        name: &str,
        name_span: Span,
        args: &[syntax::Expr],
        call_span: Span,
    ) -> Result<Value> {
        let body = self.begin_macro(name, name_span, args)?;
        let only_directives = |n: &Node| {
            Diagnostic::error(
                "a macro used as a value may hold only directives besides its value",
                n.word_span,
            )
        };
        let result = match self.parsed_expr(body) {
            Ok(fragment) => {
                let mut directives = |_: &mut Evaluator<'a>, n: &Node| Err(only_directives(n));
                self.each_item(&fragment.before, &mut directives)
                    .and_then(|()| {
                        let value = self.eval(&fragment.expr)?;
                        self.each_item(&fragment.after, &mut directives)?;
                        Ok(value)
                    })
            }
            // The value may stand inside the directives: `#if (A) rgb 1 #else rgb 0 #end`
            // (a colour there, as POV-Ray reads the tokens the directives leave).
            // Or the value is an item: `#declare O = MakeObject(1)` with an object in the
            // macro, a pigment, a function … (POV-Ray's usual way of making things).
            Err(not_an_expression) => {
                let mut value = None;
                let mut one_value = |ev: &mut Evaluator<'a>, n: &Node| {
                    if value.is_some() {
                        return Err(only_directives(n));
                    }
                    match ev.item_as_value(n)? {
                        Some(v) => value = Some(v),
                        None => return Err(only_directives(n)),
                    }
                    Ok(())
                };
                let run = match self.parsed_items(body) {
                    Ok(items) => self.each_item(&items, &mut one_value),
                    Err(failed) => {
                        let region = body.start as usize..body.end as usize;
                        self.run_spliced(body.file, region, true, failed, &mut one_value, false)
                            .map(|_| ())
                    }
                };
                match run {
                    Ok(()) => value.ok_or(not_an_expression),
                    // (Neither an expression nor items: the expression's error says more.)
                    Err(d) if d.message.starts_with("syntax error") => Err(not_an_expression),
                    Err(d) => Err(d),
                }
            }
        };
        let result = result.map_err(|d| {
            d.with_note(format!(
                "in macro {name}, called at {}",
                self.location(call_span)
            ))
        });
        self.return_from_macro();
        result
    }

    /// The value an item left by a directive or a macro stands for, where a value is wanted
    /// (`None` if it is no value): an expression, a colour, a declared name, an object, a
    /// pigment or another declarable item, a function.
    fn item_as_value(&mut self, n: &Node) -> Result<Option<Value>> {
        Ok(Some(match n.kind {
            NodeKind::ColourItem | NodeKind::Value => self.eval(&n.args[0])?,
            // A declared value alone (`#if (Ok) Q; #else <0, 0, 0>; #end`).
            NodeKind::IdentRef | NodeKind::Unknown if self.env.contains_key(&n.word) => {
                self.lookup(n)?
            }
            // (`function { … }` reads as a function pattern among items.)
            NodeKind::Pattern
                if n.children
                    .first()
                    .is_some_and(|c| c.kind == NodeKind::Function) =>
            {
                Value::Function(self.function(&n.children[0])?)
            }
            NodeKind::LayeredTexture => self.layered_texture(n)?,
            _ if super::object::is_object(n.kind) || VALUE_ITEMS.contains(&n.kind) => {
                self.item_value(n)?
            }
            _ => return Ok(None),
        }))
    }

    /// `#declare X = #if (c) A #else B #end`: the one value the directive's taken branch
    /// gives, as POV-Ray reads the tokens the directive leaves.
    fn directive_value(&mut self, directive: &Node) -> Result<Value> {
        let mut value = None;
        self.each_item(std::slice::from_ref(directive), &mut |ev, n| {
            let v = ev.item_as_value(n)?;
            match (v, &value) {
                (Some(v), None) => value = Some(v),
                (Some(_), Some(_)) => {
                    return Err(Diagnostic::error(
                        "a declaration takes one value",
                        n.word_span,
                    ));
                }
                (None, _) => return Err(ev.unknown_item(n, "a declaration")),
            }
            Ok(())
        })?;
        value.ok_or_else(|| {
            Diagnostic::error(
                "this directive gives the declaration no value",
                directive.word_span,
            )
        })
    }

    /// Counts `cost` steps against the scene's evaluation budget
    /// ([`LoadOptions::max_steps`](super::LoadOptions)), shared by everything the scene runs:
    /// a statement or block item is one step, a loop pass one, a macro call
    /// [`MACRO_CALL_STEPS`], plus one per [`MACRO_PARSE_BYTES_PER_STEP`] bytes of its body at
    /// the call that parses it (the first). Nested loops cannot run for hours.
    pub(super) fn charge(&mut self, cost: u64, what: &str, span: Span) -> Result<()> {
        self.steps = self.steps.saturating_add(cost);
        if self.steps <= self.options.max_steps {
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

    /// Binds a macro's parameters in a new frame and returns its body text.
    fn begin_macro(&mut self, name: &str, span: Span, args: &[syntax::Expr]) -> Result<Span> {
        let Some(m) = self.macros.get(name).cloned() else {
            return Err(self.unknown_word(name, span));
        };
        let split;
        let args = match self.split_after_macro_items(args, m.params.len()) {
            Some(s) => {
                split = s;
                &split[..]
            }
            None => args,
        };
        if args.len() != m.params.len() {
            return Err(Diagnostic::error(
                format!(
                    "macro `{name}` takes {} argument(s), found {}",
                    m.params.len(),
                    args.len()
                ),
                span,
            )
            .with_note(format!(
                "`{name}` is declared at {}",
                self.location(m.name_span)
            )));
        }
        let parsed = self.macro_parses.contains_key(&macro_key(m.body));
        let body_bytes = u64::from(m.body.end.saturating_sub(m.body.start));
        let parse = if parsed {
            0
        } else {
            body_bytes / MACRO_PARSE_BYTES_PER_STEP
        };
        self.charge(MACRO_CALL_STEPS + parse, "macro call", span)?;
        if self.frames.len() >= MAX_MACRO_DEPTH {
            return Err(Diagnostic::error(
                format!("macros nested more than {MAX_MACRO_DEPTH} deep (endless recursion?)"),
                span,
            ));
        }
        let mut values = Vec::with_capacity(args.len());
        for a in args {
            values.push(self.eval(a)?);
        }
        // Arguments that are plain identifiers are passed by reference: their final value is
        // copied back when the macro returns.
        let by_reference = args
            .iter()
            .zip(&m.params)
            .filter_map(|(a, p)| match &a.kind {
                ExprKind::Ident(n) if self.env.contains_key(n) => Some((p.clone(), n.clone())),
                _ => None,
            })
            .collect();
        self.frames.push(Frame {
            saved: Vec::new(),
            by_reference,
        });
        for (param, value) in m.params.iter().zip(values) {
            self.shadow(param);
            self.env.insert(param.clone(), value);
        }
        Ok(m.body)
    }

    /// A macro body parsed as items, parsed at its first call only (the body's text never
    /// changes, so neither does its tree).
    /// (A body read with a directive where a value is counts as unread: it is read as POV-Ray's
    /// token reader reads it.)
    fn parsed_items(&mut self, body: Span) -> std::result::Result<Arc<Vec<Node>>, Diagnostic> {
        self.parsed_once(
            body,
            |p| &mut p.items,
            |text, file, offset| {
                let items = syntax::parse_fragment_items(text, file, offset)?;
                for item in &items {
                    if let Some(at) = syntax::tokens::directive_after_unknown(item, text, offset) {
                        return Err(super::spliced::directive_in_value_error(file, offset + at));
                    }
                }
                Ok(items)
            },
        )
    }

    /// A macro body parsed as a value (directives around one expression), parsed once.
    fn parsed_expr(
        &mut self,
        body: Span,
    ) -> std::result::Result<Arc<syntax::FragmentExpr>, Diagnostic> {
        self.parsed_once(body, |p| &mut p.expr, syntax::parse_fragment_expr)
    }

    /// The tree `parse` makes of macro body `body`, kept in the `slot` of its cache entry.
    fn parsed_once<T>(
        &mut self,
        body: Span,
        slot: impl Fn(&mut MacroParse) -> &mut Option<std::result::Result<Arc<T>, Diagnostic>>,
        parse: impl FnOnce(&str, crate::diag::FileId, usize) -> std::result::Result<T, Diagnostic>,
    ) -> std::result::Result<Arc<T>, Diagnostic> {
        let key = macro_key(body);
        if let Some(found) = self
            .macro_parses
            .get_mut(&key)
            .and_then(|p| slot(p).clone())
        {
            return found;
        }
        let text = &self.sources.file(body.file).text[body.start as usize..body.end as usize];
        let parsed = parse(text, body.file, body.start as usize).map(Arc::new);
        *slot(self.macro_parses.entry(key).or_default()) = Some(parsed.clone());
        parsed
    }

    /// `Align(Center(Thing) -y, 0)`: with fewer arguments than the macro's parameters, an
    /// argument `M(…) - e` (or `+ e`) whose left side is a call of a macro giving an item (an
    /// object, a texture …) is two arguments, `M(…)` and `-e`, as POV-Ray reads the tokens:
    /// the item ends at its `}` and the sign starts the next argument. `None` when no such
    /// split gives `want` arguments.
    fn split_after_macro_items(
        &mut self,
        args: &[syntax::Expr],
        want: usize,
    ) -> Option<Vec<syntax::Expr>> {
        if args.len() >= want {
            return None;
        }
        let mut out = Vec::with_capacity(want);
        for a in args {
            if let ExprKind::Binary(op @ (syntax::BinOp::Sub | syntax::BinOp::Add), left, right) =
                &a.kind
            {
                if matches!(&left.kind, ExprKind::Call(n, ..) if self.macros.contains_key(n)) {
                    out.push((**left).clone());
                    let sign = if *op == syntax::BinOp::Sub {
                        syntax::UnOp::Neg
                    } else {
                        syntax::UnOp::Plus
                    };
                    out.push(syntax::Expr {
                        kind: ExprKind::Unary(sign, right.clone()),
                        span: right.span,
                    });
                    continue;
                }
            }
            out.push(a.clone());
        }
        (out.len() == want).then_some(out)
    }

    /// Ends an item-level macro call: restores shadowed variables, copies back by-reference
    /// arguments, and notes the call site on an error.
    fn end_macro(&mut self, call: &Node, result: Result<()>) -> Result<()> {
        self.return_from_macro();
        result.map_err(|d| {
            d.with_note(format!(
                "in macro {}, called at {}",
                call.children[0].word,
                self.location(call.span)
            ))
        })
    }

    /// Leaves the innermost macro (or include file): copies by-reference arguments back,
    /// restores shadowed variables.
    fn return_from_macro(&mut self) {
        let frame = self.frames.pop().expect("a macro frame");
        let back: Vec<(String, Value)> = frame
            .by_reference
            .iter()
            .filter_map(|(param, caller)| self.env.get(param).map(|v| (caller.clone(), v.clone())))
            .collect();
        for (name, old) in frame.saved.into_iter().rev() {
            match old {
                Some(v) => self.env.insert(name, v),
                None => self.env.remove(&name),
            };
        }
        for (caller, v) in back {
            self.env.insert(caller, v);
        }
    }

    /// `#include "file"`: read from the scene's folder or the include paths, evaluated here.
    fn include(&mut self, item: &Node, f: &mut Handler<'_, 'a>) -> Result<()> {
        let name = self.string(&item.args[0])?;
        if self.include_depth >= MAX_INCLUDE_DEPTH {
            return Err(Diagnostic::error(
                format!("includes nested more than {MAX_INCLUDE_DEPTH} deep"),
                item.args[0].span,
            ));
        }
        let path = self.find_file(&name, "include file", item.args[0].span)?;
        let text = crate::diag::read_source(&path).map_err(|e| {
            Diagnostic::error(
                format!("cannot read {}: {e}", path.display()),
                item.args[0].span,
            )
        })?;
        let text = syntax::lexical::rewrite(&text).unwrap_or(text);
        let file = self.sources.add(&path, text);
        let helpers = self.options.parse_helpers();
        let statements = syntax::statements(self.sources.file(file).text.clone(), file, helpers)
            .map_err(|d| d.with_note(format!("included from {}", self.location(item.span))))?;
        // An include file is a scope for its #local declarations, like a macro.
        self.include_depth += 1;
        self.frames.push(Frame::default());
        let result = self.each_statement(statements, f);
        self.return_from_macro();
        self.include_depth -= 1;
        result.map_err(|d| d.with_note(format!("included from {}", self.location(item.span))))
    }

    /// `file:line:col` of a span.
    pub(super) fn location(&self, span: Span) -> String {
        self.sources.location(span)
    }
}

/// A declaration that failed because it uses something outside the subset is kept, to be
/// reported only if the scene uses it (standard include files declare many such things).
impl Evaluator<'_> {
    /// `texture {…} texture {…} …`: each texture layered over the ones before it.
    fn layered_texture(&mut self, item: &Node) -> Result<Value> {
        let mut layered: Option<crate::ir::Texture> = None;
        for t in item.children.iter().filter(|c| c.kind == NodeKind::Texture) {
            let t = self.texture(t)?;
            layered = Some(match layered {
                Some(below) => super::material::layer(t, below),
                None => t,
            });
        }
        Ok(Value::Texture(
            layered.expect("a layered texture has textures"),
        ))
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
