//! The one lexer of POV-Ray's scene language: words, numbers, strings, directives and
//! punctuation, with blanks and comments (block comments nest, as in POV-Ray) passed over.
//!
//! Everything that reads scene text token by token uses it: the directive reader (which runs
//! `#if`, `#while`, macros and includes before the grammar sees the text), the fast lanes
//! (plain statements, mesh2 lists) and the nesting bound. Text is UTF-8 (a file that is not is
//! read as Latin-1 when loaded, see `diag::read_source`); any character the language has no
//! use for outside strings and comments is a [`TokenKind::Unknown`] token, for the grammar to
//! report where it stands.

/// What a token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TokenKind {
    /// A word: a keyword or an identifier (`[A-Za-z_][A-Za-z0-9_]*`).
    Word,
    /// A number: `1`, `1.5`, `.5`, `2.`, `1e-3`.
    Number,
    /// A string literal with its quotes (backslash escapes kept as written).
    Str,
    /// `#word` (blanks may stand between `#` and the word): a directive.
    Directive,
    /// A `#` that no word follows, which POV-Ray passes over.
    Hash,
    /// One of `{ } ( ) [ ] < > , ; + - * / = ! & | ? : .`, or `<=`, `>=`, `!=`.
    Punct,
    /// Any other character outside strings and comments.
    Unknown,
}

/// A token: its kind and its byte range in the text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token {
    /// What it is.
    pub kind: TokenKind,
    /// First byte.
    pub start: u32,
    /// One past the last byte.
    pub end: u32,
}

impl Token {
    /// The token's text.
    pub fn text<'t>(&self, text: &'t str) -> &'t str {
        &text[self.start as usize..self.end as usize]
    }

    /// A directive's word (`#  while` → `while`); the text itself for other tokens.
    pub fn word<'t>(&self, text: &'t str) -> &'t str {
        let t = self.text(text);
        match self.kind {
            TokenKind::Directive => t[1..].trim_start_matches([' ', '\t']),
            _ => t,
        }
    }
}

/// What the lexer cannot read: a string or block comment without its end.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LexError {
    /// What is wrong.
    pub message: &'static str,
    /// Where the unfinished string or comment starts.
    pub at: usize,
}

/// Deepest nesting of block comments (each level is one more `*/` to find); the same bound
/// as the grammar's nesting (`MAX_NESTING`).
pub const MAX_COMMENT_NESTING: usize = 1000;

/// Reads the tokens of `text[pos..end]`, one at a time.
#[derive(Clone, Debug)]
pub struct Lexer<'t> {
    text: &'t str,
    pos: usize,
    end: usize,
}

impl<'t> Lexer<'t> {
    /// A lexer over `text[range]`.
    pub fn new(text: &'t str, range: std::ops::Range<usize>) -> Lexer<'t> {
        Lexer {
            text,
            pos: range.start,
            end: range.end.min(text.len()),
        }
    }

    /// Where the next token (or its leading blanks) starts.
    pub fn position(&self) -> usize {
        self.pos
    }

    /// Passes over blanks and comments; `Err` for a block comment without its end.
    pub fn skip_trivia(&mut self) -> Result<(), LexError> {
        self.pos = skip_trivia(self.text.as_bytes(), self.pos, self.end)?;
        Ok(())
    }

    /// The next token, `None` at the end of the range.
    // (Not `Iterator`: the lexer is also asked where it stands and moved between tokens.)
    #[allow(clippy::should_implement_trait)]
    pub fn next(&mut self) -> Result<Option<Token>, LexError> {
        self.skip_trivia()?;
        let b = self.text.as_bytes();
        let start = self.pos;
        if start >= self.end {
            return Ok(None);
        }
        let c = b[start];
        let (kind, end) = match CLASS[c as usize] {
            WORD => (TokenKind::Word, word_end(b, start, self.end)),
            DIGIT => (TokenKind::Number, number_end(b, start, self.end)),
            DOT if start + 1 < self.end && b[start + 1].is_ascii_digit() => {
                (TokenKind::Number, number_end(b, start, self.end))
            }
            QUOTE => (TokenKind::Str, string_end(b, start, self.end)?),
            HASH => {
                let mut i = start + 1;
                while i < self.end && matches!(b[i], b' ' | b'\t') {
                    i += 1;
                }
                if i < self.end && CLASS[b[i] as usize] == WORD {
                    (TokenKind::Directive, word_end(b, i, self.end))
                } else {
                    (TokenKind::Hash, start + 1)
                }
            }
            PAIRED => {
                let two = start + 1 < self.end && b[start + 1] == b'=';
                (TokenKind::Punct, start + 1 + usize::from(two))
            }
            PUNCT | DOT => (TokenKind::Punct, start + 1),
            _ => {
                let len = self.text[start..].chars().next().map_or(1, char::len_utf8);
                (TokenKind::Unknown, start + len)
            }
        };
        self.pos = end;
        Ok(Some(Token {
            kind,
            start: start as u32,
            end: end as u32,
        }))
    }
}

// Character classes, one table lookup a byte.
const OTHER: u8 = 0;
const WORD: u8 = 1;
const DIGIT: u8 = 2;
const DOT: u8 = 3;
const QUOTE: u8 = 4;
const HASH: u8 = 5;
/// `<`, `>`, `!`: may take a `=` after them.
const PAIRED: u8 = 6;
const PUNCT: u8 = 7;
const BLANK: u8 = 8;

const CLASS: [u8; 256] = {
    let mut t = [OTHER; 256];
    let mut c = 0;
    while c < 256 {
        let b = c as u8;
        t[c] = if b.is_ascii_alphabetic() || b == b'_' {
            WORD
        } else if b.is_ascii_digit() {
            DIGIT
        } else {
            match b {
                b'.' => DOT,
                b'"' => QUOTE,
                b'#' => HASH,
                b'<' | b'>' | b'!' => PAIRED,
                b'{' | b'}' | b'(' | b')' | b'[' | b']' | b',' | b';' | b'+' | b'-' | b'*'
                | b'/' | b'=' | b'&' | b'|' | b'?' | b':' => PUNCT,
                // (NUL and Ctrl-Z are blanks too, as in POV-Ray.)
                b' ' | b'\t' | b'\n' | 0x0b | 0x0c | b'\r' | 0 | 0x1a => BLANK,
                _ => OTHER,
            }
        };
        c += 1;
    }
    t
};

/// Whether `b` can continue a word.
pub fn is_word_byte(b: u8) -> bool {
    matches!(CLASS[b as usize], WORD | DIGIT)
}

/// Just after the word starting at `b[i]`.
fn word_end(b: &[u8], mut i: usize, end: usize) -> usize {
    while i < end && is_word_byte(b[i]) {
        i += 1;
    }
    i
}

/// Just after the number starting at `b[i]` (digits, a point, digits, an exponent).
pub fn number_end(b: &[u8], mut i: usize, end: usize) -> usize {
    while i < end && b[i].is_ascii_digit() {
        i += 1;
    }
    if i < end && b[i] == b'.' {
        i += 1;
        while i < end && b[i].is_ascii_digit() {
            i += 1;
        }
    }
    // (An exponent without digits is part of the number and counts for nothing: POV-Ray
    // reads `1e` and `1e+` as 1.)
    if i < end && (b[i] == b'e' || b[i] == b'E') {
        i += 1;
        if i < end && (b[i] == b'+' || b[i] == b'-') {
            i += 1;
        }
        while i < end && b[i].is_ascii_digit() {
            i += 1;
        }
    }
    i
}

/// The value of a number token's text (a dangling exponent, `1e`, counts for nothing).
pub fn number_value(text: &str) -> f64 {
    if let Some(v) = short_decimal(text.as_bytes()) {
        return v;
    }
    let t = text.strip_suffix(['+', '-']).unwrap_or(text);
    let t = t.strip_suffix(['e', 'E']).unwrap_or(text);
    t.parse().unwrap_or(f64::NAN)
}

/// Exact powers of ten as doubles (10^22 is the largest a double holds exactly).
const POWERS_OF_TEN: [f64; 16] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
];

/// The value of a plain decimal (`12`, `0.431`, `.5`, `7.`) of at most 15 digits, the bulk of
/// what scene files hold, without the general parser: its digits as an integer (below 10^15,
/// so exact) divided by an exact power of ten, one correctly rounded operation, hence the
/// same double as `str::parse` gives. `None` for anything else (an exponent, more digits).
fn short_decimal(b: &[u8]) -> Option<f64> {
    let (mut mantissa, mut digits, mut point) = (0u64, 0usize, None);
    for (i, &c) in b.iter().enumerate() {
        match c {
            b'0'..=b'9' => {
                mantissa = mantissa * 10 + u64::from(c - b'0');
                digits += 1;
            }
            b'.' if point.is_none() => point = Some(i),
            _ => return None,
        }
    }
    if digits == 0 || digits > 15 {
        return None;
    }
    let fraction = point.map_or(0, |p| b.len() - p - 1);
    Some(mantissa as f64 / POWERS_OF_TEN[fraction])
}

/// Just after the string starting at `b[i]` (`"`): a backslash escapes the byte after it.
fn string_end(b: &[u8], start: usize, end: usize) -> Result<usize, LexError> {
    let mut i = start + 1;
    while i < end {
        match b[i] {
            b'"' => return Ok(i + 1),
            b'\\' => i += 2,
            _ => i += 1,
        }
    }
    Err(LexError {
        message: "this string has no closing `\"`",
        at: start,
    })
}

/// The first byte at or after `pos` (before `end`) that is neither a blank nor in a comment
/// (`//` to the line's end, `/* */` nested). A byte-order mark counts as a blank.
pub fn skip_trivia(b: &[u8], mut pos: usize, end: usize) -> Result<usize, LexError> {
    while pos < end {
        match b[pos] {
            c if CLASS[c as usize] == BLANK => pos += 1,
            b'/' if pos + 1 < end && b[pos + 1] == b'/' => {
                pos = b[pos..end]
                    .iter()
                    .position(|&c| c == b'\n')
                    .map_or(end, |n| pos + n);
            }
            b'/' if pos + 1 < end && b[pos + 1] == b'*' => pos = block_comment_end(b, pos, end)?,
            0xef if b[pos..end].starts_with("\u{feff}".as_bytes()) => pos += 3,
            _ => break,
        }
    }
    Ok(pos)
}

/// Just after the block comment starting at `b[start]` (`/*`), nested comments included.
pub fn block_comment_end(b: &[u8], start: usize, end: usize) -> Result<usize, LexError> {
    let mut depth = 0usize;
    let mut i = start;
    while i + 1 < end {
        if b[i] == b'/' && b[i + 1] == b'*' {
            depth += 1;
            if depth > MAX_COMMENT_NESTING {
                return Err(LexError {
                    message: "comments nested more than 1000 levels deep",
                    at: i,
                });
            }
            i += 2;
        } else if b[i] == b'*' && b[i + 1] == b'/' {
            depth -= 1;
            i += 2;
            if depth == 0 {
                return Ok(i);
            }
        } else {
            i += 1;
        }
    }
    Err(LexError {
        message: "this comment has no closing `*/`",
        at: start,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tokens(text: &str) -> Vec<(TokenKind, &str)> {
        let mut lexer = Lexer::new(text, 0..text.len());
        let mut out = Vec::new();
        while let Some(t) = lexer.next().unwrap() {
            out.push((t.kind, t.text(text)));
        }
        out
    }

    #[test]
    fn words_numbers_strings_and_punctuation() {
        use TokenKind::*;
        assert_eq!(
            tokens("sphere { <1, -2.5e3, .5> 2. \"a\\\"b\" } x<=y != z"),
            [
                (Word, "sphere"),
                (Punct, "{"),
                (Punct, "<"),
                (Number, "1"),
                (Punct, ","),
                (Punct, "-"),
                (Number, "2.5e3"),
                (Punct, ","),
                (Number, ".5"),
                (Punct, ">"),
                (Number, "2."),
                (Str, "\"a\\\"b\""),
                (Punct, "}"),
                (Word, "x"),
                (Punct, "<="),
                (Word, "y"),
                (Punct, "!="),
                (Word, "z"),
            ]
        );
        // A dangling exponent belongs to the number (POV-Ray reads `1e` as 1); `2x` is a
        // number and a word.
        assert_eq!(
            tokens("1e 2x 3e+"),
            [(Number, "1e"), (Number, "2"), (Word, "x"), (Number, "3e+")]
        );
        assert_eq!(number_value("1e"), 1.0);
        assert_eq!(number_value("3e+"), 3.0);
        assert_eq!(number_value("2.5e-1"), 0.25);
    }

    #[test]
    fn directives_lone_hashes_and_unknown_characters() {
        use TokenKind::*;
        let t = tokens("#declare A=1; # \t while #\n #1 @ é");
        assert_eq!(
            t,
            [
                (Directive, "#declare"),
                (Word, "A"),
                (Punct, "="),
                (Number, "1"),
                (Punct, ";"),
                (Directive, "# \t while"),
                (Hash, "#"),
                (Hash, "#"),
                (Number, "1"),
                (Unknown, "@"),
                (Unknown, "é"),
            ]
        );
        let text = "# \t while";
        let mut l = Lexer::new(text, 0..text.len());
        assert_eq!(l.next().unwrap().unwrap().word(text), "while");
    }

    #[test]
    fn comments_nest_and_are_passed_over() {
        use TokenKind::*;
        assert_eq!(
            tokens("a /* b /* c */ d */ e // f\n g \u{feff}h"),
            [(Word, "a"), (Word, "e"), (Word, "g"), (Word, "h")]
        );
        // Comment markers inside strings are text.
        assert_eq!(tokens("\"/* // #if\""), [(Str, "\"/* // #if\"")]);
    }

    #[test]
    fn unfinished_strings_and_comments_are_errors_at_their_start() {
        let text = "a \"bc";
        let mut l = Lexer::new(text, 0..text.len());
        l.next().unwrap();
        assert_eq!(l.next().unwrap_err().at, 2);
        let text = "a /* /* */";
        let mut l = Lexer::new(text, 0..text.len());
        l.next().unwrap();
        assert_eq!(l.next().unwrap_err().at, 2);
        let deep = "/*".repeat(MAX_COMMENT_NESTING + 1);
        assert_eq!(
            Lexer::new(&deep, 0..deep.len()).next().unwrap_err().message,
            "comments nested more than 1000 levels deep"
        );
    }

    #[test]
    fn a_range_ends_the_tokens() {
        let text = "abc def";
        let mut l = Lexer::new(text, 0..5);
        assert_eq!(l.next().unwrap().unwrap().text(text), "abc");
        // (A word is cut where the range ends.)
        assert_eq!(l.next().unwrap().unwrap().text(text), "d");
        assert_eq!(l.next().unwrap(), None);
    }

    #[test]
    fn short_decimals_read_as_the_general_parser_reads_them() {
        // Every form the shortcut takes, and random ones: the same double, bit for bit.
        let mut random = crate::testing::Xorshift(0x2545_f491_4f6c_dd1d);
        let mut next = move || random.next_u64();
        let mut texts: Vec<String> = ["0", "7.", ".5", "0.431", "123456789012345", "0.1", "0.3"]
            .iter()
            .map(|t| t.to_string())
            .collect();
        for _ in 0..100_000 {
            let digits = 1 + (next() % 15) as usize;
            let mut t: String = (0..digits)
                .map(|_| char::from(b'0' + (next() % 10) as u8))
                .collect();
            let point = (next() % (digits as u64 + 2)) as usize;
            if point <= digits {
                t.insert(point, '.');
            }
            texts.push(t);
        }
        for t in &texts {
            let fast = short_decimal(t.as_bytes()).expect(t);
            assert_eq!(fast.to_bits(), t.parse::<f64>().unwrap().to_bits(), "{t}");
        }
        // Left to the general parser: exponents, 16 digits and more, two points, nothing.
        for t in ["1e5", "1234567890123456", "1.2.3", ".", "", "1e", "2E-3"] {
            assert_eq!(short_decimal(t.as_bytes()), None, "{t}");
        }
        assert_eq!(number_value("1e"), 1.0);
        assert_eq!(number_value("2.5e1"), 25.0);
    }
}
