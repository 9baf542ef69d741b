//! The fast path for big `mesh2` lists.
//!
//! A mesh2 of a million triangles is tens of megabytes of `<x, y, z>` text. Before the text
//! goes to pest, the bodies of `vertex_vectors`, `normal_vectors`, `face_indices`,
//! `normal_indices` and `uv_indices` that are nothing but a count and plain numeric 3-vectors are read here
//! directly into arrays, and blanked out of the copy pest parses (a marker byte, then spaces,
//! so every other offset stays the same). Anything else in a body (an expression, a comment, a
//! directive) leaves it to the grammar, so the meaning is the same either way.

use std::collections::HashMap;

/// Lists shorter than this are left to the grammar (nothing to gain).
const MIN_ENTRIES: usize = 16;

/// The byte that replaces the first character of a list body read here; the grammar's
/// `bulk_list` rule matches it and the blanks after it.
pub const MARKER: u8 = 0x01;

/// A list body read by the fast path.
#[derive(Clone, Debug, PartialEq)]
pub struct BulkList {
    /// The announced entry count, as written.
    pub count: f64,
    /// Byte range of the count in the file.
    pub count_range: (u32, u32),
    /// The entries.
    pub values: Vec<[f64; 3]>,
    /// Byte offset in the file of each entry's `<`, and of the end of the last entry.
    pub offsets: Vec<u32>,
}

/// Lists read by the fast path, by the file offset of their body's first byte, and the text
/// pest should parse (`None`: the original text, nothing was read or blanked; a leading
/// byte-order mark is blanked too).
pub struct Prescanned {
    /// The text with the bodies blanked, if any was read.
    pub text: Option<String>,
    /// The lists read, by the file offset of their marker byte.
    pub lists: HashMap<usize, BulkList>,
}

const KEYWORDS: [&[u8]; 5] = [
    b"vertex_vectors",
    b"normal_vectors",
    b"face_indices",
    b"normal_indices",
    b"uv_indices",
];

/// Reads the plain list bodies of `text`, which starts at byte `offset` of its file.
pub fn prescan(text: &str, offset: usize) -> Prescanned {
    let bytes = text.as_bytes();
    let mut lists = HashMap::new();
    let mut blank: Vec<(usize, usize)> = Vec::new();
    // Most files hold no list: a substring search (much faster than the scan) tells.
    let mut i = if text.contains("_vectors") || text.contains("_indices") {
        0
    } else {
        bytes.len()
    };
    while i < bytes.len() {
        match bytes[i] {
            b'/' if bytes.get(i + 1) == Some(&b'/') => {
                while i < bytes.len() && bytes[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if bytes.get(i + 1) == Some(&b'*') => {
                // (Too deep a comment is check_nesting's error, reported before this runs.)
                i = skip_block_comment(bytes, i, usize::MAX).unwrap_or(bytes.len());
            }
            b'"' => {
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
            }
            c if c.is_ascii_alphabetic() || c == b'_' => {
                let start = i;
                while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                    i += 1;
                }
                if !KEYWORDS.contains(&&bytes[start..i]) {
                    continue;
                }
                let mut j = skip_ws(bytes, i);
                if bytes.get(j) != Some(&b'{') {
                    continue;
                }
                j += 1;
                if let Some((list, end)) = read_body(bytes, j, offset) {
                    if list.values.len() >= MIN_ENTRIES {
                        lists.insert(offset + j, list);
                        blank.push((j, end));
                        i = end;
                    }
                }
            }
            _ => i += 1,
        }
    }
    let bom = text.starts_with('\u{FEFF}');
    if blank.is_empty() && !bom {
        return Prescanned { text: None, lists };
    }
    let mut copy = bytes.to_vec();
    if bom {
        // A byte-order mark becomes three blanks (offsets stay put).
        copy[..3].fill(b' ');
    }
    for (start, end) in blank {
        copy[start] = MARKER;
        copy[start + 1..end].fill(b' ');
    }
    // Only ASCII bytes inside list bodies were replaced, by ASCII bytes.
    let text = String::from_utf8(copy).expect("blanking ASCII keeps UTF-8 valid");
    Prescanned {
        text: Some(text),
        lists,
    }
}

/// The end of the (nested) block comment starting at `i`, or, if its nesting passes
/// `max_depth`, `Err` with the offset of the `/*` that does.
pub(super) fn skip_block_comment(
    bytes: &[u8],
    mut i: usize,
    max_depth: usize,
) -> Result<usize, usize> {
    let mut depth = 0usize;
    while i < bytes.len() {
        if bytes[i..].starts_with(b"/*") {
            depth += 1;
            if depth > max_depth {
                return Err(i);
            }
            i += 2;
        } else if bytes[i..].starts_with(b"*/") {
            depth -= 1;
            i += 2;
            if depth == 0 {
                break;
            }
        } else {
            i += 1;
        }
    }
    Ok(i)
}

fn skip_ws(bytes: &[u8], mut i: usize) -> usize {
    while i < bytes.len() && matches!(bytes[i], b' ' | b'\t' | b'\r' | b'\n') {
        i += 1;
    }
    i
}

/// A plain number at `i` (the grammar's `plain_number`): its value and end.
fn number(bytes: &[u8], mut i: usize) -> Option<(f64, usize)> {
    let start = i;
    if matches!(bytes.get(i), Some(b'+' | b'-')) {
        i += 1;
    }
    let digits = |i: &mut usize| {
        let s = *i;
        while *i < bytes.len() && bytes[*i].is_ascii_digit() {
            *i += 1;
        }
        *i - s
    };
    let int = digits(&mut i);
    let mut frac = 0;
    if bytes.get(i) == Some(&b'.') {
        i += 1;
        frac = digits(&mut i);
    }
    if int == 0 && frac == 0 {
        return None;
    }
    if matches!(bytes.get(i), Some(b'e' | b'E')) {
        let mut k = i + 1;
        if matches!(bytes.get(k), Some(b'+' | b'-')) {
            k += 1;
        }
        if digits(&mut k) > 0 {
            i = k;
        }
    }
    // A number must end here: a letter or `_` right after it is some other token.
    if bytes
        .get(i)
        .is_some_and(|c| c.is_ascii_alphanumeric() || *c == b'_' || *c == b'.')
    {
        return None;
    }
    let text = std::str::from_utf8(&bytes[start..i]).ok()?;
    // An overflowing literal (1e400) is left to the grammar, whose evaluation reports it.
    let value: f64 = text.parse().ok()?;
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
        offsets: Vec::with_capacity(room + 1),
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
        list.offsets.push((offset + i) as u32);
        let mut v = [0.0; 3];
        i += 1;
        for (k, slot) in v.iter_mut().enumerate() {
            i = skip_ws(bytes, i);
            let (x, end) = number(bytes, i)?;
            *slot = x;
            i = skip_ws(bytes, end);
            let want = if k < 2 { b',' } else { b'>' };
            if bytes.get(i) != Some(&want) {
                return None;
            }
            i += 1;
        }
        list.values.push(v);
        i = skip_ws(bytes, i);
    }
    list.offsets.push((offset + i) as u32);
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
    fn reads_plain_lists_and_blanks_them_in_place() {
        let text = format!(
            "mesh2 {{ vertex_vectors {{ 20, {} }} face_indices {{ 1, <0,1,2> }} }}",
            body(20)
        );
        let p = prescan(&text, 100);
        let copy = p.text.expect("one list read");
        assert_eq!(copy.len(), text.len());
        let start = text.find("{ 20").unwrap() + 1;
        let list = &p.lists[&(100 + start)];
        assert_eq!(list.count, 20.0);
        assert_eq!(list.values[3], [3.0, -3.5, 30.0]);
        assert_eq!(list.offsets.len(), 21);
        assert_eq!(copy.as_bytes()[start], MARKER);
        // The short face list is left to the grammar.
        assert!(copy.contains("face_indices { 1, <0,1,2> }"));
    }

    #[test]
    fn leaves_anything_else_to_the_grammar() {
        for odd in [
            "<1, 2, 3> * 2",
            "<1, 2>",
            "<1 -2, 3>",
            "// note\n<1,2,3>",
            "<1, 2, x>",
            "<1, 2, 3, 4>",
            "<1,2,3e>",
        ] {
            let text = format!("vertex_vectors {{ 21, {}, {odd} }}", body(20));
            assert!(prescan(&text, 0).text.is_none(), "{odd}");
        }
        let in_comment = format!("// vertex_vectors {{ 20, {} }}", body(20));
        assert!(prescan(&in_comment, 0).text.is_none());
    }
}
