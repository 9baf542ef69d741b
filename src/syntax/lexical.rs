//! What POV-Ray's token reader accepts and trace's grammar does not, rewritten in the text with
//! every byte position kept (so errors still point at the file as written).
//!
//! An object keyword chosen by a directive, as shapes.inc writes it:
//!
//! ```text
//! #if (UseMerge)
//!    merge {
//! #else
//!    union {
//! #end
//!    …members… }
//! ```
//!
//! POV-Ray reads tokens, so a directive may choose the keyword that opens a block; trace's
//! grammar reads whole items. The text is rewritten, byte positions kept, to
//! `#if (UseMerge) merge { }#end union {`: where the condition holds, the CSG keyword stands
//! alone and is reported as CSG is (outside trace's subset, with its position); otherwise the
//! block is a union. Only this form (a CSG keyword in the `#if` branch, `union` in the
//! `#else` branch) is rewritten.
//!
//! Also a lone `#`, which POV-Ray passes over (see [`lone_hashes`]).

const CSG: [&str; 4] = ["merge", "intersection", "difference", "union"];

/// The text with each such choice rewritten, and each lone `#` blanked, or `None` if it has
/// neither.
pub fn rewrite(text: &str) -> Option<String> {
    match lone_hashes(text) {
        Some(blanked) => Some(choices(&blanked).unwrap_or(blanked)),
        None => choices(text),
    }
}

/// A `#` that starts no directive (the next thing after it is not a word: `look_at <0, 2, 0>#`
/// before a `}`, as a POV-Ray sample scene has it) is nothing to POV-Ray; it is blanked here
/// (outside strings and comments), or `None` if the text has none.
fn lone_hashes(text: &str) -> Option<String> {
    let b = text.as_bytes();
    let mut out: Option<Vec<u8>> = None;
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'"' => {
                i += 1;
                while i < b.len() && b[i] != b'"' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
            }
            b'/' if b.get(i + 1) == Some(&b'/') => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                i += 2;
                while i + 1 < b.len() && !(b[i] == b'*' && b[i + 1] == b'/') {
                    i += 1;
                }
                i += 1;
            }
            b'#' => {
                let next = skip_space(b, i + 1);
                if !b
                    .get(next)
                    .is_some_and(|c| c.is_ascii_alphabetic() || *c == b'_')
                {
                    out.get_or_insert_with(|| b.to_vec())[i] = b' ';
                }
            }
            _ => {}
        }
        i += 1;
    }
    out.map(|o| String::from_utf8(o).expect("an ASCII byte replaced by a space"))
}

/// The text with each keyword choice rewritten, or `None` if it has none.
fn choices(text: &str) -> Option<String> {
    if !text.contains("#else") {
        return None;
    }
    let mut out: Option<Vec<u8>> = None;
    let bytes = text.as_bytes();
    let mut from = 0;
    while let Some(found) = text[from..].find("#if") {
        let at = from + found;
        from = at + 3;
        if let Some(edits) = choice(bytes, at) {
            let out = out.get_or_insert_with(|| bytes.to_vec());
            for (pos, with) in edits {
                out[pos..pos + with.len()].copy_from_slice(with.as_bytes());
            }
        }
    }
    out.map(|o| String::from_utf8(o).expect("ASCII replaced by ASCII"))
}

/// The edits (position, replacement of the same length) for a choice starting at `#if` at
/// `at`, if one stands there.
fn choice(b: &[u8], at: usize) -> Option<Vec<(usize, &'static str)>> {
    let mut i = at + 3;
    if b.get(i)
        .is_some_and(|c| c.is_ascii_alphanumeric() || *c == b'_')
    {
        return None; // (#ifdef, #ifndef)
    }
    i = skip_space(b, i);
    if b.get(i) != Some(&b'(') {
        return None;
    }
    let mut depth = 0;
    while i < b.len() {
        match b[i] {
            b'(' => depth += 1,
            b')' => {
                depth -= 1;
                if depth == 0 {
                    break;
                }
            }
            b'\n' | b'{' | b'}' | b'#' => return None,
            _ => {}
        }
        i += 1;
    }
    i = skip_space(b, i + 1);
    let first = word(b, i)?;
    if !CSG[..3].contains(&first) {
        return None;
    }
    i = skip_space(b, i + first.len());
    if b.get(i) != Some(&b'{') {
        return None;
    }
    i = skip_space(b, i + 1);
    if !b[i..].starts_with(b"#else") {
        return None;
    }
    let else_at = i;
    i = skip_space(b, i + 5);
    if word(b, i)? != "union" {
        return None;
    }
    i = skip_space(b, i + 5);
    if b.get(i) != Some(&b'{') {
        return None;
    }
    i = skip_space(b, i + 1);
    if !b[i..].starts_with(b"#end") || b.get(i + 4).is_some_and(|c| c.is_ascii_alphanumeric()) {
        return None;
    }
    // `#else` → `}#end`, `#end` → blanks: the union's `{` stays, outside the directive.
    Some(vec![(else_at, "}#end"), (i, "    ")])
}

fn skip_space(b: &[u8], mut i: usize) -> usize {
    while b.get(i).is_some_and(|c| c.is_ascii_whitespace()) {
        i += 1;
    }
    i
}

fn word(b: &[u8], i: usize) -> Option<&str> {
    let end = (i..b.len())
        .find(|&k| !(b[k].is_ascii_alphanumeric() || b[k] == b'_'))
        .unwrap_or(b.len());
    (end > i).then(|| std::str::from_utf8(&b[i..end]).expect("ASCII"))
}

#[cfg(test)]
mod tests {
    #[test]
    fn shapes_inc_choice_becomes_a_union_or_a_lone_merge() {
        let text = "#macro M(U)\n   #if(U)\n      merge {\n   #else\n      union {\n   #end\n      sphere { 0, 1 }\n   }\n#end\n";
        let out = super::rewrite(text).expect("rewritten");
        assert_eq!(out.len(), text.len());
        assert_eq!(
            out,
            "#macro M(U)\n   #if(U)\n      merge {\n   }#end\n      union {\n       \n      sphere { 0, 1 }\n   }\n#end\n"
        );
        assert_eq!(super::rewrite("#if (A) union { #else merge { #end"), None);
        assert_eq!(
            super::rewrite("#if (A) sphere { 0, 1 } #else box { 0, 1 } #end"),
            None
        );
    }

    #[test]
    fn a_lone_hash_is_blanked_outside_strings_and_comments() {
        let text = "camera { look_at <0, 2, 0>#\n }\n# declare A = \"#\"; // #\n/* # */ #1";
        assert_eq!(
            super::rewrite(text).unwrap(),
            "camera { look_at <0, 2, 0> \n }\n# declare A = \"#\"; // #\n/* # */  1"
        );
        assert_eq!(super::rewrite("#declare A = 1;"), None);
    }
}
