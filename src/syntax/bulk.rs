//! The fast path for big `mesh2` lists.
//!
//! A mesh2 of a million triangles is tens of megabytes of `<x, y, z>` text. Where the
//! directive reader meets the bodies of `vertex_vectors`, `normal_vectors`, `face_indices`,
//! `normal_indices` and `uv_indices` that are nothing but a count and plain numeric
//! 3-vectors, it reads them here directly into arrays, and hands the grammar one marker byte
//! in their place (`syntax::Unit::lists`). Anything else in a body (an expression, a comment,
//! a directive) leaves it to the usual reading, so the meaning is the same either way
//! (`parsing.rs` tests the two against each other).

/// Lists shorter than this are left to the grammar (nothing to gain).
const MIN_ENTRIES: usize = 16;

/// The text that stands for a list body read here; the grammar's `bulk_list` rule matches it.
pub const MARKER: &str = "\u{1}";

/// A list body read by the fast path.
#[derive(Clone, Debug, PartialEq)]
pub struct BulkList {
    /// The announced entry count, as written.
    pub count: f64,
    /// Byte range of the count in the file.
    pub count_range: (u32, u32),
    /// The entries.
    pub values: Vec<[f64; 3]>,
    /// Where each entry starts and ends in the file.
    pub spans: Vec<(u32, u32)>,
}

/// The words whose `{ … }` lists the fast path reads.
pub const KEYWORDS: [&str; 5] = [
    "vertex_vectors",
    "normal_vectors",
    "face_indices",
    "normal_indices",
    "uv_indices",
];

/// The list body that starts at byte `pos` of `text` (just after its `{`), if it is a count
/// and at least [`MIN_ENTRIES`] plain numeric 3-vectors ending before byte `end`: the list
/// (its spans those of `text`) and where its closing `}` stands.
pub fn read_list(text: &str, pos: usize, end: usize) -> Option<(BulkList, usize)> {
    let bytes = &text.as_bytes()[..end.min(text.len())];
    let (list, close) = read_body(bytes, pos, 0)?;
    (list.values.len() >= MIN_ENTRIES).then_some((list, close))
}

/// Past the blanks and comments at `i` (the lexer's trivia; an unclosed comment is left
/// where it starts, for the grammar to report).
fn skip_ws(bytes: &[u8], i: usize) -> usize {
    super::lexer::skip_trivia(bytes, i, bytes.len()).unwrap_or(i)
}

fn skip_spaces(bytes: &[u8], mut i: usize) -> usize {
    while i < bytes.len() && matches!(bytes[i], b' ' | b'\t'..=b'\r') {
        i += 1;
    }
    i
}

/// A plain number at `i` (the grammar's `plain_number`, the lexer's number with a sign): its
/// value and end.
fn number(bytes: &[u8], mut i: usize) -> Option<(f64, usize)> {
    let start = i;
    if matches!(bytes.get(i), Some(b'+' | b'-')) {
        i += 1;
    }
    let digit = |i: usize| bytes.get(i).is_some_and(u8::is_ascii_digit);
    if !(digit(i) || bytes.get(i) == Some(&b'.') && digit(i + 1)) {
        return None;
    }
    let i = super::lexer::number_end(bytes, i, bytes.len());
    // A number must end here: a word character right after it is some other token.
    if bytes
        .get(i)
        .is_some_and(|&c| super::lexer::is_word_byte(c) || c == b'.')
    {
        return None;
    }
    let text = std::str::from_utf8(&bytes[start..i]).ok()?;
    // An overflowing literal (1e400) is left to the grammar, whose evaluation reports it.
    let value = super::lexer::number_value(text);
    value.is_finite().then_some((value, i))
}

/// `count, <a, b, c>, … }` starting at `i`: the list and the offset of the closing `}`, or
/// `None` if the body holds anything else.
fn read_body(bytes: &[u8], i: usize, offset: usize) -> Option<(BulkList, usize)> {
    let mut i = skip_ws(bytes, i);
    let (count, end) = number(bytes, i)?;
    let count_range = ((offset + i) as u32, (offset + end) as u32);
    i = skip_ws(bytes, end);
    // Room for the announced entries, but no more than the rest of the file can hold (an
    // entry takes at least 8 bytes: `,<0,0,0>`), whatever the count says.
    let room = count.clamp(0.0, ((bytes.len() - i) / 8) as f64) as usize;
    let mut list = BulkList {
        count,
        count_range,
        values: Vec::with_capacity(room),
        spans: Vec::with_capacity(room),
    };
    loop {
        match bytes.get(i)? {
            b'}' => break,
            b',' => i = skip_ws(bytes, i + 1),
            _ => return None,
        }
        if bytes.get(i) == Some(&b'}') {
            break; // a trailing comma
        }
        if bytes.get(i) != Some(&b'<') {
            return None;
        }
        let start = (offset + i) as u32;
        let mut v = [0.0; 3];
        i += 1;
        // (Blanks only inside a vector, as in the grammar's `plain_vector`.)
        for (k, slot) in v.iter_mut().enumerate() {
            i = skip_spaces(bytes, i);
            let (x, end) = number(bytes, i)?;
            *slot = x;
            i = skip_spaces(bytes, end);
            let want = if k < 2 { b',' } else { b'>' };
            if bytes.get(i) != Some(&want) {
                return None;
            }
            i += 1;
        }
        list.values.push(v);
        list.spans.push((start, (offset + i) as u32));
        i = skip_ws(bytes, i);
    }
    Some((list, i))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn body(n: usize) -> String {
        (0..n)
            .map(|k| format!("<{k}, -{k}.5,{k}e1 >"))
            .collect::<Vec<_>>()
            .join(",\n")
    }

    #[test]
    fn reads_plain_lists() {
        let text = format!(
            "vertex_vectors {{ 20, {} }} face_indices {{ 1, <0,1,2> }}",
            body(20)
        );
        let start = text.find("{ 20").unwrap() + 1;
        let (list, close) = read_list(&text, start, text.len()).expect("a list");
        assert_eq!(list.count, 20.0);
        assert_eq!(list.values[3], [3.0, -3.5, 30.0]);
        assert_eq!(list.spans.len(), 20);
        assert_eq!(
            &text[list.spans[3].0 as usize..list.spans[3].1 as usize],
            "<3, -3.5,3e1 >"
        );
        assert_eq!(&text[close..close + 1], "}");
        // The short face list is left to the grammar.
        let faces = text.find("{ 1,").unwrap() + 1;
        assert!(read_list(&text, faces, text.len()).is_none());
        // Comments between entries are passed over, as the lexer passes over them.
        let commented = text.replacen(", <", ", // note\n /* a /* nested */ one */ <", 3);
        let (again, _) = read_list(&commented, start, commented.len()).expect("a list");
        assert_eq!(again.values, list.values);
        // A list that does not end before `end` is not read.
        assert!(read_list(&text, start, close).is_none());
    }

    #[test]
    fn leaves_anything_else_to_the_grammar() {
        for odd in [
            "<1, 2, 3> * 2",
            "<1, 2>",
            "<1 -2, 3>",
            "<1, /* a comment */ 2, 3>",
            "<1, 2, x>",
            "<1, 2, 3, 4>",
            "#if (1) <1,2,3> #end",
        ] {
            let text = format!("{{ 21, {}, {odd} }}", body(20));
            assert!(read_list(&text, 1, text.len()).is_none(), "{odd}");
        }
    }
}
