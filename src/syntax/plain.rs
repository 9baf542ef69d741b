//! The fast lane for plain statements.
//!
//! Big generated or exported scenes are mostly one shape a statement with literal numbers:
//! `sphere { <1.5, 2, -3>, 0.25 pigment { rgb <0.2, 0.5, 0.9> } }`, `object { Tree translate
//! <4, 0, 7> }`. Such a statement is read here by a hand-written scanner into exactly the tree
//! the grammar's lowering builds (spans included), several times faster than pest's general
//! rules. The lane is narrow on purpose: shapes with literal arguments; `pigment` with one
//! literal colour; `finish` with literal items; `texture` of those; `translate`, `rotate`,
//! `scale` by a literal; plain flags; `object { Name … }`; comments between them (the one lexer's
//! trivia and numbers: `lexer::skip_trivia`, `lexer::number_end`). Anything else — an
//! expression, an identifier, a directive, an unknown word, a syntax error — gives up at once
//! and the statement goes to the grammar, which reads it (or reports it) as always. The unit
//! tests compare the two readings on every form the lane takes, byte offsets included.
//!
//! The directive reader (`eval::lang::reader`) tries the lane where a statement starts; a name in
//! `object { Name … }` is bound there (or, naming a macro, sends the statement to the usual
//! reading).

use super::{BinOp, ColourPart, Expr, ExprKind, Node, NodeKind};
use crate::diag::{FileId, Span};

/// Reads the statement starting after the blanks at byte `pos` of `source`, if it is plain:
/// its tree and the byte just after its closing `}`.
pub fn statement(source: &str, pos: usize, file: FileId) -> Option<(Node, usize)> {
    let mut s = Scanner {
        text: source,
        at: pos,
        file,
    };
    s.skip_blanks();
    let node = s.object()?;
    Some((node, s.at))
}

/// A plain statement read, its declared names given their slots.
#[derive(Debug)]
pub struct Plain {
    /// Its tree, each name's slot the name's place in `names`.
    pub node: Node,
    /// The byte just after its closing `}`.
    pub end: usize,
    /// Where its declared names are written, in the order of their slots.
    pub names: Names,
}

/// Most declared names a statement of the lane holds (one with more goes to the grammar).
const MOST_NAMES: usize = 6;

/// The declared names of a plain statement: where each is written.
#[derive(Clone, Copy, Debug, Default)]
pub struct Names {
    spans: [Span; MOST_NAMES],
    len: usize,
}

impl Names {
    /// Where each name is written, in the order of their slots.
    pub fn spans(&self) -> &[Span] {
        &self.spans[..self.len]
    }

    /// Gives the name at `span` the next slot.
    fn add(&mut self, span: Span) -> Option<super::Slot> {
        let slot = self.spans.get_mut(self.len)?;
        *slot = span;
        self.len += 1;
        Some(super::Slot(self.len as u32 - 1))
    }

    /// Gives every name of `node` its slot.
    fn of_node(&mut self, node: &mut Node) -> Option<()> {
        if node.kind == NodeKind::IdentRef {
            node.slot = self.add(node.word_span)?;
        }
        for e in &mut node.args {
            self.of_expr(e)?;
        }
        for c in &mut node.children {
            self.of_node(c)?;
        }
        Some(())
    }

    fn of_expr(&mut self, e: &mut Expr) -> Option<()> {
        match &mut e.kind {
            ExprKind::Ident(_, slot) => *slot = self.add(e.span)?,
            ExprKind::Binary(_, a, b) => {
                self.of_expr(a)?;
                self.of_expr(b)?;
            }
            ExprKind::Unary(_, a) => self.of_expr(a)?,
            ExprKind::Vector(items) => {
                for item in items {
                    self.of_expr(item)?;
                }
            }
            _ => {}
        }
        Some(())
    }
}

/// The plain statement starting after the blanks at byte `pos` of `source` if it ends by
/// byte `end`, its names given their slots (as [`statement`] reads it).
pub fn read(source: &str, pos: usize, file: FileId, end: usize) -> Option<Plain> {
    let (mut node, after) = statement(source, pos, file)?;
    if after > end {
        return None;
    }
    let mut names = Names::default();
    names.of_node(&mut node)?;
    Some(Plain {
        node,
        end: after,
        names,
    })
}

/// Shapes the lane reads: keyword, node kind, number of arguments.
const SHAPES: [(&str, NodeKind, usize); 8] = [
    ("sphere", NodeKind::Sphere, 2),
    ("box", NodeKind::Box, 2),
    ("cylinder", NodeKind::Cylinder, 3),
    ("cone", NodeKind::Cone, 4),
    ("triangle", NodeKind::Triangle, 3),
    ("smooth_triangle", NodeKind::SmoothTriangle, 6),
    ("torus", NodeKind::Torus, 2),
    ("plane", NodeKind::Plane, 2),
];

/// Finish items taking one literal: keyword and node kind.
const FINISH_ITEMS: [(&str, NodeKind); 9] = [
    ("ambient", NodeKind::Ambient),
    ("emission", NodeKind::Emission),
    ("diffuse", NodeKind::Diffuse),
    ("brilliance", NodeKind::Brilliance),
    ("phong", NodeKind::Phong),
    ("phong_size", NodeKind::PhongSize),
    ("specular", NodeKind::Specular),
    ("roughness", NodeKind::Roughness),
    ("reflection", NodeKind::Reflection),
];

/// Flags the lane reads (without an `on`/`off` value).
const FLAGS: [&str; 6] = [
    "no_shadow",
    "no_image",
    "no_reflection",
    "hollow",
    "double_illuminate",
    "open",
];

/// The words that name a value (the grammar's `value_kw`) but the axes: left to the grammar.
/// (`x`, `y` and `z` are names the lane reads as the grammar does, as values evaluation
/// knows: `plane { y, -1 }`, `rotate 45*y`.)
const VALUE_WORDS: [&str; 23] = [
    "pi",
    "t",
    "u",
    "v",
    "true",
    "false",
    "yes",
    "no",
    "on",
    "off",
    "clock_on",
    "clock_delta",
    "clock",
    "frame_number",
    "initial_frame",
    "final_frame",
    "initial_clock",
    "final_clock",
    "image_width",
    "image_height",
    "version",
    "input_file_name",
    "now",
];

/// `left op right`, spanning both, as the grammar's lowering joins them.
fn binary(op: BinOp, left: Expr, right: Expr) -> Expr {
    let span = Span {
        end: right.span.end,
        ..left.span
    };
    Expr {
        kind: ExprKind::Binary(op, Box::new(left), Box::new(right)),
        span,
    }
}

#[derive(Clone, Copy)]
struct Scanner<'a> {
    text: &'a str,
    at: usize,
    file: FileId,
}

impl<'a> Scanner<'a> {
    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.file, start, end)
    }

    fn peek(&self) -> Option<u8> {
        self.text.as_bytes().get(self.at).copied()
    }

    /// The grammar's implicit whitespace: blanks and comments, as the lexer passes over them
    /// (an unclosed comment stays, for the grammar to report).
    fn skip_blanks(&mut self) {
        let bytes = self.text.as_bytes();
        self.at = super::lexer::skip_trivia(bytes, self.at, bytes.len()).unwrap_or(self.at);
    }

    /// Blanks only, as inside the grammar's `plain_vector` (a vector with a comment in it is
    /// the grammar's).
    fn skip_spaces(&mut self) {
        let bytes = self.text.as_bytes();
        while self.at < bytes.len() && matches!(bytes[self.at], b' ' | b'\t'..=b'\r') {
            self.at += 1;
        }
    }

    fn eat(&mut self, byte: u8) -> Option<()> {
        (self.peek() == Some(byte)).then(|| self.at += 1)
    }

    /// A word (`[A-Za-z_][A-Za-z0-9_]*`) and where it starts.
    fn word(&mut self) -> Option<(&'a str, usize)> {
        let bytes = self.text.as_bytes();
        let start = self.at;
        if !bytes
            .get(start)
            .is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_')
        {
            return None;
        }
        let mut end = start + 1;
        while end < bytes.len() && super::lexer::is_word_byte(bytes[end]) {
            end += 1;
        }
        self.at = end;
        Some((&self.text[start..end], start))
    }

    /// A node for the keyword `word` starting at `start`; span and children filled later.
    /// A node of `kind` whose keyword `word` starts at `start` (the table's own string: no
    /// copy of it is made).
    fn node(&self, kind: NodeKind, word: &'static str, start: usize) -> Node {
        let word_span = self.span(start, start + word.len());
        Node {
            kind,
            span: word_span,
            word: super::Word::fixed(word),
            word_span,
            args: Vec::new(),
            children: Vec::new(),
            slot: super::Slot::NONE,
        }
    }

    /// `keyword { … }` of a shape, or `object { Name … }`.
    fn object(&mut self) -> Option<Node> {
        let (word, start) = self.word()?;
        let mut node = if word == "object" {
            let mut node = self.node(NodeKind::ObjectRef, "object", start);
            self.skip_blanks();
            self.eat(b'{')?;
            self.skip_blanks();
            node.children.push(self.item_ref()?);
            node
        } else {
            let &(word, kind, count) = SHAPES.iter().find(|s| s.0 == word)?;
            let mut node = self.node(kind, word, start);
            self.skip_blanks();
            self.eat(b'{')?;
            self.skip_blanks();
            for i in 0..count {
                if i > 0 && self.eat(b',').is_some() {
                    self.skip_blanks();
                }
                node.args.push(self.value()?);
            }
            node
        };
        self.modifiers(&mut node.children)?;
        self.eat(b'}')?;
        node.span = self.span(start, self.at);
        Some(node)
    }

    /// A declared name in `object { … }` (not a keyword, not a macro call or array element).
    fn item_ref(&mut self) -> Option<Node> {
        let (name, start) = self.word()?;
        self.named(name, start)
    }

    /// The declared name `name` (read, starting at `start`) standing for a whole item, as
    /// `object { Name … }`, `texture { Name … }` and `finish { Name … }` begin.
    fn named(&mut self, name: &str, start: usize) -> Option<Node> {
        if super::is_keyword(name) {
            return None;
        }
        let name_end = self.at;
        self.skip_blanks();
        if !self
            .peek()
            .is_some_and(|b| b == b'}' || b.is_ascii_alphabetic() || b == b'_')
        {
            return None;
        }
        let mut node = self.node(NodeKind::IdentRef, "", start);
        node.word = super::Word::new(name);
        node.word_span = self.span(start, name_end);
        node.span = self.span(start, self.at);
        Some(node)
    }

    /// Object modifiers up to (not including) the closing `}`.
    fn modifiers(&mut self, children: &mut Vec<Node>) -> Option<()> {
        loop {
            self.skip_blanks();
            if self.peek() == Some(b'}') {
                return Some(());
            }
            let (word, start) = self.word()?;
            let child = match word {
                "pigment" => self.pigment(start)?,
                "finish" => self.finish(start)?,
                "texture" => self.texture(start)?,
                "interior" => self.interior(start)?,
                _ => match self.transform(word, start) {
                    Some(node) => node?,
                    None => self.flag(word, start)?,
                },
            };
            children.push(child);
        }
    }

    /// `translate`, `rotate` or `scale` by a literal (`None` if `word` is none of them).
    fn transform(&mut self, word: &str, start: usize) -> Option<Option<Node>> {
        let (kind, word) = match word {
            "translate" => (NodeKind::Translate, "translate"),
            "rotate" => (NodeKind::Rotate, "rotate"),
            "scale" => (NodeKind::Scale, "scale"),
            _ => return None,
        };
        Some(self.with_literal(kind, word, start))
    }

    /// A keyword followed by one literal; the node runs to the blanks after the literal, as
    /// the grammar's does.
    fn with_literal(&mut self, kind: NodeKind, word: &'static str, start: usize) -> Option<Node> {
        let mut node = self.node(kind, word, start);
        self.skip_blanks();
        node.args.push(self.value()?);
        node.span = self.span(start, self.at);
        Some(node)
    }

    fn flag(&mut self, word: &str, start: usize) -> Option<Node> {
        let word = *FLAGS.iter().find(|f| **f == word)?;
        let mut node = self.node(NodeKind::Flag, word, start);
        self.skip_blanks();
        // (`hollow on` and the like are the grammar's.)
        let mut ahead = *self;
        if ahead
            .word()
            .is_some_and(|(next, _)| matches!(next, "on" | "off" | "true" | "false" | "yes" | "no"))
        {
            return None;
        }
        node.span = self.span(start, self.at);
        Some(node)
    }

    /// `pigment { [color] rgb… literal }`.
    fn pigment(&mut self, start: usize) -> Option<Node> {
        let mut node = self.node(NodeKind::Pigment, "pigment", start);
        self.skip_blanks();
        self.eat(b'{')?;
        self.skip_blanks();
        // A declared pigment or colour by name (`pigment { Red }`), or one typed colour.
        let value = match self.peek()? {
            b'A'..=b'Z' | b'_' => self
                .operand()
                .filter(|e| matches!(e.kind, ExprKind::Ident(..)))?,
            _ => self.colour()?,
        };
        node.args.push(value);
        self.eat(b'}')?;
        node.span = self.span(start, self.at);
        Some(node)
    }

    /// `rgb V`, `color rgbf V`, …: one typed colour of a literal, followed by `}`.
    fn colour(&mut self) -> Option<Expr> {
        let start = self.at;
        let (mut kw, _) = self.word()?;
        if kw == "color" || kw == "colour" {
            self.skip_blanks();
            (kw, _) = self.word()?;
        }
        let typed = kw.strip_prefix('s').unwrap_or(kw);
        if !matches!(typed, "rgb" | "rgbf" | "rgbt" | "rgbft") {
            return None;
        }
        self.skip_blanks();
        let value = self.literal()?;
        (self.peek() == Some(b'}')).then_some(())?;
        Some(Expr {
            kind: ExprKind::Colour(vec![ColourPart::Typed(kw.to_string(), value)]),
            span: self.span(start, self.at),
        })
    }

    /// `finish { [Name] item literal … }`.
    fn finish(&mut self, start: usize) -> Option<Node> {
        self.block(
            NodeKind::Finish,
            "finish",
            start,
            |s, word, item_start, first| {
                if first && !super::is_keyword(word) {
                    return s.named(word, item_start);
                }
                if word == "conserve_energy" {
                    return Some(s.node(NodeKind::ConserveEnergy, "conserve_energy", item_start));
                }
                let &(word, kind) = FINISH_ITEMS.iter().find(|f| f.0 == word)?;
                let item = s.with_literal(kind, word, item_start)?;
                // (`diffuse A, B` is the grammar's.)
                (s.peek() != Some(b',')).then_some(item)
            },
        )
    }

    /// `interior { ior/fade_distance/fade_power value … }`.
    fn interior(&mut self, start: usize) -> Option<Node> {
        self.block(
            NodeKind::Interior,
            "interior",
            start,
            |s, word, item_start, _| {
                let (kind, word) = match word {
                    "ior" => (NodeKind::Ior, "ior"),
                    "fade_distance" => (NodeKind::FadeDistance, "fade_distance"),
                    "fade_power" => (NodeKind::FadePower, "fade_power"),
                    _ => return None,
                };
                s.with_literal(kind, word, item_start)
            },
        )
    }

    /// `texture { [Name] pigment/finish/transforms }`.
    fn texture(&mut self, start: usize) -> Option<Node> {
        self.block(
            NodeKind::Texture,
            "texture",
            start,
            |s, word, item_start, first| match word {
                _ if first && !super::is_keyword(word) => s.named(word, item_start),
                "pigment" => s.pigment(item_start),
                "finish" => s.finish(item_start),
                _ => s.transform(word, item_start)?,
            },
        )
    }

    /// `word { item … }`, each item starting with a word that `item` reads (from the word,
    /// where it starts, and whether it is the first item).
    fn block(
        &mut self,
        kind: NodeKind,
        word: &'static str,
        start: usize,
        mut item: impl FnMut(&mut Self, &'a str, usize, bool) -> Option<Node>,
    ) -> Option<Node> {
        let mut node = self.node(kind, word, start);
        self.skip_blanks();
        self.eat(b'{')?;
        loop {
            self.skip_blanks();
            if self.eat(b'}').is_some() {
                break;
            }
            let (word, item_start) = self.word()?;
            let first = node.children.is_empty();
            node.children.push(item(self, word, item_start, first)?);
        }
        node.span = self.span(start, self.at);
        Some(node)
    }

    /// A number or a vector of numbers that no operator follows (the grammar's `literal ~
    /// literal_end`); leaves the scanner after the blanks that follow it.
    fn literal(&mut self) -> Option<Expr> {
        let start = self.at;
        let kind = if self.peek() == Some(b'<') {
            self.vector()?
        } else {
            ExprKind::Number(self.number()?)
        };
        let span = self.span(start, self.at);
        self.skip_blanks();
        // What may follow a literal without making it part of an expression (a subset of the
        // grammar's `literal_end`).
        let next = self.peek()?;
        (next == b',' || next == b'}' || next == b'_' || next.is_ascii_alphanumeric())
            .then_some(Expr { kind, span })
    }

    /// A literal, or a small expression: unsigned numbers and declared names joined by
    /// `+ - * /` (products first, left to right), as the grammar's lowering builds it; a
    /// name is bound where the reader takes the statement.
    fn value(&mut self) -> Option<Expr> {
        let save = *self;
        if let Some(e) = self.literal() {
            return Some(e);
        }
        *self = save;
        let mut sum = self.product()?;
        loop {
            let op = match self.peek() {
                Some(b'+') => BinOp::Add,
                Some(b'-') => BinOp::Sub,
                _ => break,
            };
            self.at += 1;
            self.skip_blanks();
            let right = self.product()?;
            sum = binary(op, sum, right);
        }
        let next = self.peek()?;
        (next == b',' || next == b'}' || next == b'_' || next.is_ascii_alphanumeric())
            .then_some(sum)
    }

    /// Operands joined by `*` and `/`; leaves the scanner after the blanks that follow.
    fn product(&mut self) -> Option<Expr> {
        let mut product = self.operand()?;
        loop {
            let op = match self.peek() {
                Some(b'*') => BinOp::Mul,
                Some(b'/') if self.text.as_bytes().get(self.at + 1) != Some(&b'/') => BinOp::Div,
                _ => return Some(product),
            };
            self.at += 1;
            self.skip_blanks();
            let right = self.operand()?;
            product = binary(op, product, right);
        }
    }

    /// An unsigned number, or a name (not a keyword, not called, indexed or a member's
    /// base); leaves the scanner after the blanks that follow.
    fn operand(&mut self) -> Option<Expr> {
        let start = self.at;
        let kind = match self.peek()? {
            b'0'..=b'9' | b'.' => ExprKind::Number(self.number()?),
            b'a'..=b'z' | b'A'..=b'Z' | b'_' => {
                let (name, _) = self.word()?;
                // (Every value word and keyword starts with a small letter.)
                if name.starts_with(|c: char| c.is_ascii_lowercase())
                    && (VALUE_WORDS.contains(&name) || super::is_keyword(name))
                {
                    return None;
                }
                ExprKind::Ident(name.to_string(), super::Slot::NONE)
            }
            _ => return None,
        };
        let span = self.span(start, self.at);
        self.skip_blanks();
        if matches!(self.peek(), Some(b'(' | b'[' | b'.')) {
            return None;
        }
        Some(Expr { kind, span })
    }

    /// `<n, n, …>` of 2 to 5 plain numbers (commas optional before an unsigned number).
    fn vector(&mut self) -> Option<ExprKind> {
        self.eat(b'<')?;
        let mut c = [0.0; 5];
        let mut n = 0;
        loop {
            self.skip_spaces();
            *c.get_mut(n)? = self.number()?;
            n += 1;
            let before = self.at;
            self.skip_spaces();
            match self.peek()? {
                b'>' => {
                    self.at += 1;
                    break;
                }
                b',' => self.at += 1,
                b'0'..=b'9' | b'.' if self.at > before => {}
                _ => return None,
            }
        }
        (n >= 2).then_some(ExprKind::PlainVector(c, n as u8))
    }

    /// The grammar's `plain_number`: a sign, then the lexer's number, read as the lowering
    /// reads it.
    fn number(&mut self) -> Option<f64> {
        let bytes = self.text.as_bytes();
        let start = self.at;
        let mut i = start;
        if matches!(bytes.get(i), Some(b'+' | b'-')) {
            i += 1;
        }
        let digit = |i: usize| bytes.get(i).is_some_and(u8::is_ascii_digit);
        if !(digit(i) || bytes.get(i) == Some(&b'.') && digit(i + 1)) {
            return None;
        }
        self.at = super::lexer::number_end(bytes, i, bytes.len());
        Some(super::lexer::number_value(&self.text[start..self.at]))
    }
}

#[cfg(test)]
mod tests {
    use super::super::lexer::{Lexer, TokenKind};
    use super::super::{Unit, parse_statement};
    use super::*;

    /// The grammar's reading of the statement at the start of `text`, cut where the directive
    /// reader cuts it (a word and its `{ … }` block): tree and end.
    fn by_grammar(text: &str) -> Option<(String, usize)> {
        let mut lexer = Lexer::new(text, 0..text.len());
        let first = lexer.next().ok()??;
        let mut end = first.end as usize;
        let mut depth = 0;
        while let Ok(Some(t)) = lexer.next() {
            if t.kind == TokenKind::Directive {
                return None;
            }
            end = t.end as usize;
            match t.text(text) {
                "{" => depth += 1,
                "}" => depth -= 1,
                _ => {}
            }
            if depth == 0 {
                break;
            }
        }
        let start = first.start as usize;
        let unit = Unit::from_file_text(&text[start..end], FileId(0), start);
        match parse_statement(&unit) {
            Ok(node) => Some((format!("{node:?}"), end)),
            Err(_) => None,
        }
    }

    /// The lane's reading, checked against the grammar's whenever the lane takes the text.
    fn by_lane(text: &str) -> Option<(String, usize)> {
        let (node, end) = statement(text, 0, FileId(0))?;
        let lane = (format!("{node:?}"), end);
        assert_eq!(
            Some(&lane),
            by_grammar(text).as_ref(),
            "the two readings of {text:?} differ"
        );
        Some(lane)
    }

    const TAKEN: &[&str] = &[
        "sphere { <1.5, -2, 3e2>, 0.25 }",
        "sphere{<0,0,0>,1}",
        "  sphere {\n\t< 1 , 2 , 3 >\n,\r\n.5\n}  ",
        "sphere { <1 2 3> 1 }",
        "sphere { <1 .5 3>, +1E-2 }",
        "box { <-1,-1,-1>, <1,1,1> }",
        "cylinder { <0,0,0>, <0,1,0>, .5 open }",
        "cone { <0,0,0>, 1, <0,1,0>, 0 }",
        "triangle { <0,0,0>, <1,0,0>, <0,1,0> }",
        "smooth_triangle { <0,0,0>, <0,0,1>, <1,0,0>, <0,0,1>, <0,1,0>, <0,0,1> }",
        "torus { 1, 0.25 rotate <90, 0, 0> }",
        "plane { <0, 1, 0>, -1 hollow }",
        "sphere { <0,0,0>, 1 pigment { rgb <0.2, 0.5, 0.9> } }",
        "sphere { <0,0,0>, 1 pigment{color rgbf <1,0,0,0.5>} }",
        "sphere { <0,0,0>, 1 pigment { colour srgb 0.5 } no_shadow }",
        "sphere { <0,0,0>, 1 pigment { rgbft <1,1,1,0,0.5>}}",
        "sphere { <0,0,0>, 1 finish { phong 0.5 phong_size 40 ambient 0.1 diffuse 0.7 conserve_energy reflection 0.2 } }",
        "sphere { <0,0,0>, 1 finish { } }",
        "sphere { <0,0,0>, 1 texture { pigment { rgb 1 } finish { specular 0.3 roughness 0.01 } scale 2 } }",
        "sphere { <0,0,0>, 1 translate <1,2,3> scale 2 no_image no_reflection double_illuminate }",
        "sphere { <0,0,0>, 1 finish { emission 1 brilliance 2 } }",
        "object { Tree }",
        "object {Tree translate <1,0,0>}",
        "object { Tree pigment { rgb <1,0,0> } }",
        "object { _t2 scale 3 }",
        "sphere { <0,0,0>, 1 }\nsphere { <1,1,1>, 2 }",
        // Comments, as the lexer passes over them.
        "sphere { /* a /* nested */ c */ <0,0,0>, 1 // radius\n pigment { rgb 1 } }",
        "sphere { <0,0,0>, /* r */ 1 finish { phong /* p */ 0.5 } }",
        "/* c */ sphere { <0,0,0>, 1 }",
        "sphere { <0,0,0>, 1 // c\n }",
        // Small expressions of numbers and names.
        "sphere { <0,0,0>, 0.5*2 }",
        "sphere { <0,0,0>, R }",
        "sphere { <0,0,0>, A + B*2 - C/4 }",
        "sphere { <0,0,0>, 1 finish { phong Gloss*2 specular 0.1 } interior { ior 1.5 } }",
        "sphere { <0,0,0>, 1 interior { ior N fade_distance 2 fade_power 1001 } translate D*3 }",
        "cylinder { <0,0,0>, <0,1,0>, R/2/2 open }",
        "sphere { <0,0,0>, R // c\n *2 }",
        // The axes.
        "plane { y, -1 }",
        "plane { z 5 pigment { rgb 1 } }",
        "sphere { <0,0,0>, 1 translate x rotate 45*y scale z*2 + 1 }",
        "object { Tree translate x*3 + z*Step }",
        // Declared pigments, textures and finishes.
        "sphere { <0,0,0>, 1 pigment { Red } }",
        "sphere { <0,0,0>, 1 texture { pigment { P_1 } finish { F } } }",
        "sphere { <0,0,0>, 1 texture { T } }",
        "sphere { <0,0,0>, 1 texture { Bark scale 2 } finish { F } }",
        "sphere { <0,0,0>, 1 texture { T finish { Shiny phong 0.5 } } }",
        "object { Tree texture { _wood translate <1,0,0> } }",
        // A dangling exponent counts for nothing (POV-Ray reads `1E` as 1).
        "sphere { <0,0,0> 1E }",
    ];

    /// Statements the lane leaves to the grammar (which reads them differently, or needs
    /// what the lane does not have).
    const LEFT: &[&str] = &[
        "sphere { <1 -2 3>, 1 }",
        "sphere { <0,0,0> -1 }",
        "sphere { <1 .5 3> +1E-2 }",
        "sphere { <1,2,3>.x, 1 }",
        "sphere { <0,0,0>, R.x }",
        "sphere { <0,0,0>, F(2) }",
        "sphere { <0,0,0>, A[1] }",
        "sphere { <0,0,0>, 2*-R }",
        "sphere { <0,0,0>, -R*2 }",
        "sphere { <0,0,0>, R*pi }",
        "sphere { <0,0,0>, (R) }",
        "sphere { <0,0,0>, 1 interior { ior 1.5 caustics 1 } }",
        "sphere { <0,0,0>, 1 finish { phong R*<1,1,1> } }",
        "sphere { <0,0,0>, 1 pigment { rgb <1,0,0> filter 0.5 } }",
        "sphere { <0,0,0>, 1 texture { pigment { rgb 1 } T } }",
        "sphere { <0,0,0>, 1 finish { phong 1 F } }",
        "sphere { <0,0,0>, 1 texture { T U } }",
        "sphere { <0,0,0>, 1 pigment { Red*0.5 } }",
        "sphere { <0,0,0>, 1 pigment { Red filter 0.5 } }",
        "sphere { <0,0,0>, 1 pigment { Red scale 2 } }",
        "sphere { <0,0,0>, 1 pigment { P[2] } }",
        "sphere { <0,0,0>, 1 pigment { red } }",
        "sphere { <0,0,0>, 1 texture { T[1] } }",
        "sphere { <0,0,0>, 1 texture { M() } }",
        "sphere { <0,0,0>, 1 pigment { color <1,0,0> } }",
        "sphere { <0,0,0>, 1 finish { diffuse 0.6, 0.3 } }",
        "sphere { <0,0,0>, 1 finish { phong albedo 0.6 } }",
        "sphere { <0,0,0>, 1 hollow on }",
        "sphere { <0,0,0>, 1 rotate 45*t }",
        "sphere { <0,0,0>, 1 #if (1) #end }",
        "sphere { <0,0,0>, 1 bogus 3 }",
        "object { Tree(1) }",
        "object { A[1] }",
        "object { sphere { <0,0,0>, 1 } }",
        "object { pigment }",
        "box { <0,0,0> <1,1,1> }",
        "sphere { <1>, 1 }",
        "sphere { <1,2,3,4,5,6>, 1 }",
        "disc { <0,0,0>, y, 1 }",
        "#declare A = 1;",
        "sphere { <0,0,0>, 1 ",
        "",
    ];

    #[test]
    fn the_lane_reads_plain_statements_as_the_grammar_does() {
        for text in TAKEN {
            assert!(by_lane(text).is_some(), "the lane should take {text:?}");
        }
        for text in LEFT {
            assert!(by_lane(text).is_none(), "the lane should leave {text:?}");
        }
    }

    /// Statements near the plain ones (a token dropped, doubled or replaced, blanks moved):
    /// whatever the lane takes it reads as the grammar does.
    #[test]
    fn near_misses_are_read_as_the_grammar_does_or_left_to_it() {
        const TOKENS: &[&str] = &[
            "sphere",
            "box",
            "cone",
            "object",
            "Tree",
            "{",
            "}",
            "<",
            ">",
            ",",
            "1",
            "-2.5",
            ".5",
            "3e2",
            "1e",
            "+4.",
            "pigment",
            "rgb",
            "color",
            "rgbt",
            "finish",
            "phong",
            "diffuse",
            "translate",
            "no_shadow",
            "on",
            "(",
            "*",
            "-",
            ".",
            "/",
            " ",
            "\n",
            "texture",
            "scale",
            "open",
            "conserve_energy",
            "x",
            "#",
            ";",
            "[",
        ];
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = |n: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % n as u64) as usize
        };
        let (mut taken, mut cases) = (0, 0);
        for text in TAKEN {
            // Tokens split at blanks and punctuation, kept with their separators.
            let mut tokens: Vec<String> = Vec::new();
            for piece in text.split_inclusive(|c: char| " {}<>,\n".contains(c)) {
                let (body, sep) = piece.split_at(piece.len() - 1);
                if !body.is_empty() {
                    tokens.push(body.to_string());
                }
                tokens.push(sep.to_string());
            }
            for _ in 0..400 {
                let mut t = tokens.clone();
                for _ in 0..1 + next(2) {
                    let i = next(t.len());
                    match next(4) {
                        0 => {
                            t.remove(i);
                        }
                        1 => t.insert(i, t[i].clone()),
                        2 => t[i] = TOKENS[next(TOKENS.len())].to_string(),
                        _ => t.insert(i, TOKENS[next(TOKENS.len())].to_string()),
                    }
                    if t.is_empty() {
                        break;
                    }
                }
                cases += 1;
                taken += usize::from(by_lane(&t.concat()).is_some());
            }
        }
        // Some variants stay plain (a blank moved, a number replaced): the comparison above
        // then ran on them.
        assert!(
            taken > cases / 20,
            "only {taken} of {cases} variants were taken"
        );
    }

    /// The declared names of a statement get slots in the order they are listed, and a
    /// statement with more names than the lane keeps is left to the grammar.
    #[test]
    fn names_get_their_slots_in_the_order_listed() {
        let text = "sphere { <1,2,3>, R*2 pigment { rgb <1,0,0> } \
                    finish { phong G*1 specular S } }";
        let plain = read(text, 0, FileId(0), text.len()).expect("a plain statement");
        let names: Vec<&str> = plain
            .names
            .spans()
            .iter()
            .map(|s| &text[s.start as usize..s.end as usize])
            .collect();
        assert_eq!(names, ["R", "G", "S"]);
        let tree = format!("{:?}", plain.node);
        for (i, name) in names.iter().enumerate() {
            assert!(tree.contains(&format!("Ident(\"{name}\", #{i})")), "{tree}");
        }
        let object = "object { Thing translate <1, 0, 0> }";
        let plain = read(object, 0, FileId(0), object.len()).expect("a plain statement");
        assert_eq!(plain.names.spans().len(), 1);
        let many = "sphere { <1,2,3>, A+B+C+D+E+F+G }";
        assert!(statement(many, 0, FileId(0)).is_some());
        assert!(read(many, 0, FileId(0), many.len()).is_none());
        assert!(
            read(text, 0, FileId(0), text.len() - 1).is_none(),
            "past the end"
        );
    }
}
