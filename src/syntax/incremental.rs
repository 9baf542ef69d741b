//! Big containers read one item at a time.
//!
//! A loop inside a union's braces (`union { #for (I, 0, 49999) sphere {…} #end }`) or a
//! mesh2's list hands the grammar one unit holding every item the loop made. Read whole, such
//! a unit costs the parser as much per item as a statement of its own, and a long enough one
//! hits the parser's work limit. So a big unit whose statement is a container (a union, light
//! group or composite, a mesh, a mesh2 and its lists) is read here instead: its head and
//! braces by the lexer, each item by a grammar rule that matches the item as a prefix of the
//! text from where it starts (`union_item`, `list_item` … in the grammar), the same
//! alternatives, in the same order, as the container's own rule tries at that place. The
//! node built is the one the whole parse builds (a test checks this on generated units).
//!
//! Items a loop made again are parsed once: an item whose text comes from the same places of
//! the same files as one parsed before (and which the same token follows) is that item's node
//! again, its words' slots moved to the new item's words.
//!
//! Anything unexpected (a syntax error, items out of the container's order) gives up, and
//! the unit is read whole, which reports the error as usual.

use super::grammar::{Rule, SceneParser};
use super::lexer::{Lexer, Token, TokenKind};
use super::unit::Unit;
use super::{ColourPart, Expr, ExprKind, Lower, Node, NodeKind, Slot};
use crate::diag::{FileId, Span};
use pest::Parser;
use std::collections::HashMap;
use std::sync::Arc;

/// Units shorter than this are read whole.
const BIG: usize = 16 * 1024;

/// The statement (or declared value) of a big unit, if it is a container read item by item.
pub(super) fn statement(unit: &Unit) -> Option<Node> {
    if unit.text.len() < BIG {
        return None;
    }
    read(unit)
}

/// The unit's statement read item by item (whatever its size), if it is a container.
pub(super) fn read(unit: &Unit) -> Option<Node> {
    let mut reader = Reader {
        unit,
        lower: Lower::of_unit(unit),
        cache: HashMap::new(),
    };
    let first = reader.token(0)?;
    let (node, end) = reader.container(first)?;
    // The container must be the whole unit.
    match reader.token(end) {
        None => Some(node),
        Some(_) => None,
    }
}

/// Where one byte range of an item's text comes from (see [`Reader::key`]).
#[derive(Clone, PartialEq, Eq)]
struct PieceKey {
    /// Its start and length in the item.
    at: u32,
    len: u32,
    file: FileId,
    /// Where it starts in the file, and where its whole piece ends there.
    start: u32,
    source_end: u32,
    stand_in: bool,
}

/// An item parsed before: the node or expression, and what must match to use it again.
struct Cached {
    len: usize,
    key: Vec<PieceKey>,
    /// The text of the token after the item.
    next: String,
    /// The unit's index of the item's first word.
    first_word: usize,
    item: Item,
}

#[derive(Clone)]
enum Item {
    Node(Node),
    /// A union's member: shared by the members read again from it (see [`again`]).
    Member(Arc<Expr>),
    /// (Shared: a list's entries read again are [`ExprKind::Shifted`] to it.)
    Expr(Arc<Expr>),
}

struct Reader<'u> {
    unit: &'u Unit,
    lower: Lower<'u>,
    /// Items parsed, by the file and place their first byte comes from.
    cache: HashMap<(FileId, u32), Vec<Cached>>,
}

/// Containers whose items are read one at a time.
#[derive(Clone, Copy, PartialEq)]
enum Container {
    Union,
    Mesh,
    Mesh2,
}

/// A mesh2's lists, in the order they must come.
const MESH2_LISTS: [&str; 7] = [
    "vertex_vectors",
    "normal_vectors",
    "uv_vectors",
    "texture_list",
    "face_indices",
    "normal_indices",
    "uv_indices",
];

impl<'u> Reader<'u> {
    /// The first token at or after byte `at`.
    fn token(&self, at: usize) -> Option<Token> {
        let text = &self.unit.text;
        Lexer::new(text, at.min(text.len())..text.len())
            .next()
            .ok()
            .flatten()
    }

    fn text(&self, t: Token) -> &'u str {
        t.text(&self.unit.text)
    }

    fn is(&self, t: Token, s: &str) -> bool {
        self.text(t) == s
    }

    /// A node with `word` as its keyword, spanning `start..end` of the unit's text.
    fn head(&self, kind: NodeKind, word: Token) -> Node {
        Node {
            kind,
            span: Span::default(),
            word: super::Word::new(self.text(word)),
            word_span: self.unit.span(word.start as usize, word.end as usize),
            args: Vec::new(),
            children: Vec::new(),
            slot: self.unit.slot(word.start as usize),
        }
    }

    /// The container starting with keyword `word`, and where it ends.
    fn container(&mut self, word: Token) -> Option<(Node, usize)> {
        if word.kind != TokenKind::Word {
            return None;
        }
        let (kind, container) = match self.text(word) {
            "union" | "light_group" | "composite" => (NodeKind::Union, Container::Union),
            "mesh" => (NodeKind::Mesh, Container::Mesh),
            "mesh2" => (NodeKind::Mesh2, Container::Mesh2),
            _ => return None,
        };
        let open = self.token(word.end as usize)?;
        if !self.is(open, "{") {
            return None;
        }
        let mut node = self.head(kind, word);
        let mut at = open.end as usize;
        // How far through its order the container is: for a mesh, 0 triangles, 1 after
        // `inside_vector`, 2 modifiers; for a mesh2, the index in MESH2_LISTS after the last
        // list read, 7 after `inside_vector`, 8 modifiers.
        let mut phase = 0;
        loop {
            let t = self.token(at)?;
            if self.is(t, "}") {
                if container == Container::Mesh2 && phase < 5 {
                    // (Without its vertices and faces: the whole parse says what is missing.)
                    return None;
                }
                node.span = self.unit.span(word.start as usize, t.end as usize);
                return Some((node, t.end as usize));
            }
            let w = self.text(t);
            let (child, end) = match container {
                Container::Union => {
                    if matches!(w, "union" | "light_group" | "composite" | "mesh" | "mesh2") {
                        self.container(t)?
                    } else {
                        self.node(Rule::union_item, t)?
                    }
                }
                Container::Mesh => {
                    let rule = match w {
                        "triangle" | "smooth_triangle" if phase == 0 => Rule::triangle_item,
                        "inside_vector" if phase == 0 => {
                            phase = 1;
                            Rule::inside_item
                        }
                        _ => {
                            phase = 2;
                            Rule::modifier_item
                        }
                    };
                    self.node(rule, t)?
                }
                Container::Mesh2 => {
                    let list = MESH2_LISTS.iter().position(|l| *l == w);
                    match list {
                        Some(i) if i >= phase && phase < 7 => {
                            // The lists it skips must be optional ones.
                            if (phase..i).any(|j| j == 0 || j == 4) {
                                return None;
                            }
                            phase = i + 1;
                            self.list(t)?
                        }
                        Some(_) => return None,
                        None if phase < 5 => return None,
                        None if w == "inside_vector" && phase < 8 => {
                            phase = 8;
                            self.node(Rule::inside_item, t)?
                        }
                        None => {
                            phase = 9;
                            self.node(Rule::modifier_item, t)?
                        }
                    }
                }
            };
            node.children.push(child);
            at = end;
        }
    }

    /// A mesh2's list starting with keyword `word`: its entries one by one (a texture list,
    /// or a body the fast lane read, whole).
    fn list(&mut self, word: Token) -> Option<(Node, usize)> {
        let kind = match self.text(word) {
            "vertex_vectors" => NodeKind::VertexVectors,
            "normal_vectors" => NodeKind::NormalVectors,
            "uv_vectors" => NodeKind::UvVectors,
            "face_indices" => NodeKind::FaceIndices,
            "normal_indices" => NodeKind::NormalIndices,
            "uv_indices" => NodeKind::UvIndices,
            _ => return self.node(Rule::mesh2_part, word),
        };
        let open = self.token(word.end as usize)?;
        if !self.is(open, "{") {
            return None;
        }
        let first = self.token(open.end as usize)?;
        if self.unit.text.as_bytes()[first.start as usize] == super::bulk::MARKER.as_bytes()[0] {
            return self.node(Rule::mesh2_part, word);
        }
        let mut node = self.head(kind, word);
        let (count, mut at) = self.expr(Rule::count_item, first)?;
        node.args.push(count);
        loop {
            let mut t = self.token(at)?;
            if self.is(t, ",") {
                t = self.token(t.end as usize)?;
            }
            if self.is(t, "}") {
                node.span = self.unit.span(word.start as usize, t.end as usize);
                return Some((node, t.end as usize));
            }
            let (entry, end) = self.expr(Rule::list_item, t)?;
            node.args.push(entry);
            at = end;
        }
    }

    /// The node that `rule` reads from token `t` on, and where it ends.
    fn node(&mut self, rule: Rule, t: Token) -> Option<(Node, usize)> {
        match self.item(rule, t)? {
            (Item::Node(n), end) => Some((n, end)),
            (Item::Expr(_) | Item::Member(_), _) => None,
        }
    }

    /// The expression that `rule` reads from token `t` on, and where it ends.
    fn expr(&mut self, rule: Rule, t: Token) -> Option<(Expr, usize)> {
        match self.item(rule, t)? {
            (Item::Expr(e), end) => Some((Arc::unwrap_or_clone(e), end)),
            (Item::Node(_) | Item::Member(_), _) => None,
        }
    }

    /// What `rule` reads from token `t` on: parsed before, or parsed now.
    fn item(&mut self, rule: Rule, t: Token) -> Option<(Item, usize)> {
        let at = t.start as usize;
        let source = self.unit.source(at);
        let first_word = self.first_word(at);
        if let Some(known) = self.cache.get(&source) {
            for c in known {
                let end = at + c.len;
                if end <= self.unit.text.len()
                    && self.next_text(end) == c.next
                    && self.key(at, end).as_ref() == Some(&c.key)
                {
                    let shift = first_word as i64 - c.first_word as i64;
                    let item = match &c.item {
                        // (Later items have later words: the shift is not negative.)
                        Item::Member(e) => Item::Node(again(e, shift as u32)),
                        Item::Node(n) => {
                            let mut n = n.clone();
                            shift_node(&mut n, shift);
                            Item::Node(n)
                        }
                        // (Later items have later words: the shift is not negative.)
                        Item::Expr(e) => Item::Expr(Arc::new(Expr {
                            span: e.span,
                            kind: ExprKind::Shifted(Arc::clone(e), shift as u32),
                        })),
                    };
                    return Some((item, end));
                }
            }
        }
        let mut pairs = SceneParser::parse(rule, &self.unit.text[at..]).ok()?;
        let pair = pairs.next()?.into_inner().next()?;
        let end = at + pair.as_span().end();
        self.lower.offset = at;
        let item = if super::is_expr(pair.as_rule()) {
            Item::Expr(Arc::new(self.lower.expr(pair)))
        } else if rule == Rule::union_item {
            let node = self.lower.node(pair);
            Item::Member(Arc::new(Expr {
                span: node.span,
                kind: ExprKind::Item(Box::new(node)),
            }))
        } else {
            Item::Node(self.lower.node(pair))
        };
        if let Some(key) = self.key(at, end) {
            let next = self.next_text(end).to_string();
            let known = self.cache.entry(source).or_default();
            // (A few shapes of one place are kept: a loop's body read in a few ways.)
            if known.len() < 4 {
                known.push(Cached {
                    len: end - at,
                    key,
                    next,
                    first_word,
                    item: item.clone(),
                });
            }
        }
        let item = match item {
            Item::Member(e) => Item::Node(again(&e, 0)),
            other => other,
        };
        Some((item, end))
    }

    /// The text of the first token at or after `at` (empty at the end).
    fn next_text(&self, at: usize) -> &'u str {
        self.token(at).map_or("", |t| self.text(t))
    }

    /// The unit's index of the first word at or after byte `at`.
    fn first_word(&self, at: usize) -> usize {
        self.unit.words.partition_point(|&w| (w as usize) < at)
    }

    /// Where bytes `start..end` come from, piece by piece, relative to `start`: two items
    /// with equal keys have the same text and the same spans. `None` for one holding a list
    /// the fast lane read (its node owns that list).
    fn key(&self, start: usize, end: usize) -> Option<Vec<PieceKey>> {
        let lists = &self.unit.lists;
        let first_list = lists.partition_point(|(at, _)| (*at as usize) < start);
        if lists
            .get(first_list)
            .is_some_and(|(at, _)| (*at as usize) < end)
        {
            return None;
        }
        let mut key = Vec::new();
        for p in &self.unit.pieces[self.unit.piece_at(start)..] {
            let (p_start, p_end) = (p.at as usize, (p.at + p.len) as usize);
            if p_start >= end {
                break;
            }
            let (s, e) = (p_start.max(start), p_end.min(end));
            if s >= e {
                continue;
            }
            let stand_in = p.len != p.src_len;
            key.push(PieceKey {
                at: (s - start) as u32,
                len: (e - s) as u32,
                file: p.file,
                start: if stand_in {
                    p.start
                } else {
                    p.start + (s - p_start) as u32
                },
                source_end: p.start + p.src_len,
                stand_in,
            });
        }
        Some(key)
    }
}

/// A union's member read again, `by` words after the one `shared` was read from: the node is
/// shared, not copied (a union a loop filled holds many), and evaluation moves its slots.
fn again(shared: &Arc<Expr>, by: u32) -> Node {
    Node {
        kind: NodeKind::Again,
        span: shared.span,
        word: super::Word::default(),
        word_span: shared.span,
        args: vec![Expr {
            span: shared.span,
            kind: ExprKind::Shifted(Arc::clone(shared), by),
        }],
        children: Vec::new(),
        slot: Slot::NONE,
    }
}

fn shift(slot: &mut Slot, by: i64) {
    if *slot != Slot::NONE {
        slot.0 = (slot.0 as i64 + by) as u32;
    }
}

/// Moves every slot of `node` by `by` words.
fn shift_node(node: &mut Node, by: i64) {
    shift(&mut node.slot, by);
    for e in &mut node.args {
        shift_expr(e, by);
    }
    for c in &mut node.children {
        shift_node(c, by);
    }
}

fn shift_expr(e: &mut Expr, by: i64) {
    match &mut e.kind {
        ExprKind::Number(_) | ExprKind::Str(_) | ExprKind::Bulk(_) | ExprKind::PlainVector(..) => {}
        ExprKind::Ident(_, slot) => shift(slot, by),
        ExprKind::Call(_, _, slot, args) => {
            shift(slot, by);
            args.iter_mut().for_each(|a| shift_expr(a, by));
        }
        ExprKind::Vector(items) => items.iter_mut().for_each(|a| shift_expr(a, by)),
        ExprKind::Unary(_, a) => shift_expr(a, by),
        ExprKind::Binary(_, a, b) | ExprKind::Index(a, b) => {
            shift_expr(a, by);
            shift_expr(b, by);
        }
        ExprKind::Ternary(a, b, c) => {
            shift_expr(a, by);
            shift_expr(b, by);
            shift_expr(c, by);
        }
        ExprKind::Member(a, _, _) => shift_expr(a, by),
        ExprKind::Colour(parts) => {
            for p in parts {
                match p {
                    ColourPart::Base(a) | ColourPart::Typed(_, a) | ColourPart::Channel(_, a) => {
                        shift_expr(a, by)
                    }
                }
            }
        }
        ExprKind::Item(n) => shift_node(n, by),
        ExprKind::Shifted(_, s) => *s = (*s as i64 + by) as u32,
    }
}

/// `node` with its shared entries copied, their slots moved (as a whole parse reads them).
#[cfg(test)]
pub(super) fn unshare(node: &mut Node) {
    if let Some((inner, by)) = node.again() {
        let mut copy = inner.clone();
        shift_node(&mut copy, i64::from(by));
        *node = copy;
    }
    for e in &mut node.args {
        if let ExprKind::Shifted(inner, by) = &e.kind {
            let mut copy = (**inner).clone();
            shift_expr(&mut copy, i64::from(*by));
            *e = copy;
        }
    }
    node.children.iter_mut().for_each(unshare);
}
