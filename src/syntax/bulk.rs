//! The fast path for big `mesh2` lists.
//!
//! A mesh2 of a million triangles is tens of megabytes of `<x, y, z>` text. Where the
//! directive reader meets the bodies of `vertex_vectors`, `normal_vectors`, `face_indices`,
//! `normal_indices` and `uv_indices` that are nothing but a count and plain numeric
//! 3-vectors, it reads them here directly into arrays, and hands the grammar one marker byte
//! in their place (`syntax::Unit::lists`). Anything else in a body (an expression, a comment,
//! a directive) leaves it to the usual reading, so the meaning is the same either way
//! (`parsing.rs` tests the two against each other).

use std::sync::Arc;

/// Lists shorter than this are left to the grammar (nothing to gain).
const MIN_ENTRIES: usize = 16;

/// The text that stands for a list body read here; the grammar's `bulk_list` rule matches it.
pub const MARKER: &str = "\u{1}";

/// A list body read by the fast path. Its values and spans are shared by the copies a
/// [`ListCache`] hands out.
#[derive(Clone, Debug, PartialEq)]
pub struct BulkList {
    /// The announced entry count, as written.
    pub count: f64,
    /// Byte range of the count in the file.
    pub count_range: (u32, u32),
    /// The entries.
    pub values: Arc<Vec<[f64; 3]>>,
    /// Where each entry starts and ends in the text it was read from, `shift` bytes before
    /// where it stands in this list's file (wrapping).
    spans: Arc<Vec<(u32, u32)>>,
    shift: u32,
}

impl BulkList {
    /// A list of `values`, each written at `spans` of its file.
    pub fn new(
        count: f64,
        count_range: (u32, u32),
        values: Vec<[f64; 3]>,
        spans: Vec<(u32, u32)>,
    ) -> BulkList {
        BulkList {
            count,
            count_range,
            values: Arc::new(values),
            spans: Arc::new(spans),
            shift: 0,
        }
    }

    /// Where entry `k` starts and ends in the file.
    pub fn span(&self, k: usize) -> (u32, u32) {
        let (start, end) = self.spans[k];
        (start.wrapping_add(self.shift), end.wrapping_add(self.shift))
    }

    /// The same list, `by` bytes further on in its file (wrapping: a move back is a
    /// wrapping move forward); the values and spans are shared.
    fn moved_by(&self, by: u32) -> BulkList {
        let (a, b) = self.count_range;
        BulkList {
            count_range: (a.wrapping_add(by), b.wrapping_add(by)),
            shift: self.shift.wrapping_add(by),
            ..self.clone()
        }
    }
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

/// Lists read by earlier loads, kept for the next (`trace watch` reads the scene again at
/// every save): a list body whose bytes equal those of a body read before (compared in full)
/// is taken from here, sharing its values, instead of read again. Only bodies that end at
/// their first `}` are kept, so a body is found again by looking for that byte. Each
/// complete load keeps only the lists it used ([`ListCache::finish_load`]). Clones share the
/// lists.
#[derive(Clone, Default)]
pub struct ListCache(Arc<std::sync::Mutex<Lists>>);

#[derive(Default)]
struct Lists {
    kept: Vec<Kept>,
    /// The lists the load in progress used or read.
    used: Vec<Kept>,
    /// Values made from lists, kept as the lists are.
    derived: Vec<Derived>,
    /// Those the load in progress used or made.
    derived_used: Vec<Derived>,
}

/// A value made from lists (by their values' identity) and a few words of other data.
#[derive(Clone)]
struct Derived {
    lists: Vec<Option<Arc<Vec<[f64; 3]>>>>,
    words: Vec<u64>,
    value: Arc<dyn std::any::Any + Send + Sync>,
}

impl Derived {
    fn is(&self, lists: &[Option<&BulkList>], words: &[u64]) -> bool {
        self.words == words
            && self.lists.len() == lists.len()
            && (self.lists.iter().zip(lists)).all(|(a, b)| match (a, b) {
                (Some(a), Some(b)) => Arc::ptr_eq(a, &b.values),
                (None, None) => true,
                _ => false,
            })
    }
}

/// A list and the text it was read from (kept alive to compare against).
#[derive(Clone)]
struct Kept {
    text: Arc<String>,
    /// The body's bytes: from after its `{` to its `}`.
    body: std::ops::Range<usize>,
    list: BulkList,
}

impl std::fmt::Debug for ListCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "ListCache({} lists)", self.count())
    }
}

impl ListCache {
    /// [`read_list`], through the cache.
    pub fn read_list(
        &self,
        text: &Arc<String>,
        pos: usize,
        end: usize,
    ) -> Option<(BulkList, usize)> {
        let end = end.min(text.len());
        let first_close = pos + text.get(pos..end)?.find('}')?;
        let body = &text.as_bytes()[pos..first_close];
        let mut lists = self.0.lock().unwrap_or_else(|e| e.into_inner());
        let Lists { kept, used, .. } = &mut *lists;
        let same = |k: &&Kept| {
            k.body.len() == body.len()
                && (Arc::ptr_eq(&k.text, text) && k.body.start == pos
                    || &k.text.as_bytes()[k.body.clone()] == body)
        };
        if let Some(k) = used
            .iter()
            .find(same)
            .or_else(|| kept.iter().find(same))
            .cloned()
        {
            let list = k
                .list
                .moved_by((pos as u32).wrapping_sub(k.body.start as u32));
            if !used
                .iter()
                .any(|u| Arc::ptr_eq(&u.text, &k.text) && u.body == k.body)
            {
                used.push(k);
            }
            return Some((list, first_close));
        }
        drop(lists);
        let (list, close) = read_list(text, pos, end)?;
        if close == first_close {
            let k = Kept {
                text: Arc::clone(text),
                body: pos..close,
                list: list.clone(),
            };
            self.0
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .used
                .push(k);
        }
        Some((list, close))
    }

    /// Ends a load: after a `complete` one the lists it used are kept for the next and the
    /// others let go; after one that stopped early (an error, a cancel) the lists it read are
    /// added and none let go (the next load may reach the lists this one did not).
    pub fn finish_load(&self, complete: bool) {
        let mut lists = self.0.lock().unwrap_or_else(|e| e.into_inner());
        let used = std::mem::take(&mut lists.used);
        let derived = std::mem::take(&mut lists.derived_used);
        if complete {
            lists.kept = used;
            lists.derived = derived;
        } else {
            lists.derived.extend(derived);
            for u in used {
                let known =
                    (lists.kept.iter()).any(|k| Arc::ptr_eq(&k.text, &u.text) && k.body == u.body);
                if !known {
                    lists.kept.push(u);
                }
            }
        }
    }

    /// The value made before from these very lists (taken from this cache, so the same
    /// values) and `words` of other data, if one is kept: what the lists make (a mesh from
    /// its mesh2 lists) is then not made again. [`ListCache::keep_derived`] keeps one.
    pub fn derived<T: std::any::Any + Send + Sync>(
        &self,
        lists: &[Option<&BulkList>],
        words: &[u64],
    ) -> Option<Arc<T>> {
        let mut cache = self.0.lock().unwrap_or_else(|e| e.into_inner());
        let found = (cache.derived_used.iter())
            .chain(&cache.derived)
            .find(|d| d.is(lists, words))?
            .clone();
        if !cache.derived_used.iter().any(|d| d.is(lists, words)) {
            cache.derived_used.push(found.clone());
        }
        Arc::downcast(found.value).ok()
    }

    /// Keeps `value`, made from `lists` and `words` alone, for [`ListCache::derived`] (while
    /// loads use it).
    pub fn keep_derived<T: std::any::Any + Send + Sync>(
        &self,
        lists: &[Option<&BulkList>],
        words: &[u64],
        value: Arc<T>,
    ) {
        let derived = Derived {
            lists: lists
                .iter()
                .map(|l| l.map(|l| Arc::clone(&l.values)))
                .collect(),
            words: words.to_vec(),
            value,
        };
        let mut cache = self.0.lock().unwrap_or_else(|e| e.into_inner());
        cache.derived_used.push(derived);
    }

    /// Lists kept now.
    pub fn count(&self) -> usize {
        self.0.lock().unwrap_or_else(|e| e.into_inner()).kept.len()
    }
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
    let (mut values, mut spans) = (Vec::with_capacity(room), Vec::with_capacity(room));
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
        values.push(v);
        spans.push((start, (offset + i) as u32));
        i = skip_ws(bytes, i);
    }
    Some((BulkList::new(count, count_range, values, spans), i))
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
        assert_eq!(list.values.len(), 20);
        let (a, b) = list.span(3);
        assert_eq!(&text[a as usize..b as usize], "<3, -3.5,3e1 >");
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
    fn a_cached_list_is_the_list_read_again_wherever_it_moved() {
        let text = |before: &str, n: usize| {
            Arc::new(format!("{before}vertex_vectors {{ {n}, {} }}", body(n)))
        };
        let start = |t: &str| t.find('{').unwrap() + 1;
        let cache = ListCache::default();
        let first = text("", 20);
        let (a, close) = cache.read_list(&first, start(&first), first.len()).unwrap();
        cache.finish_load(true);
        assert_eq!(cache.count(), 1);
        // The same body after a longer prefix: the values shared, every place moved.
        let moved = text("// a line added above\n", 20);
        let (b, b_close) = cache.read_list(&moved, start(&moved), moved.len()).unwrap();
        let (fresh, fresh_close) = read_list(&moved, start(&moved), moved.len()).unwrap();
        assert!(Arc::ptr_eq(&a.values, &b.values), "taken from the cache");
        assert_eq!(b.values, fresh.values);
        assert_eq!(b.count_range, fresh.count_range);
        assert_eq!(
            (0..20).map(|k| b.span(k)).collect::<Vec<_>>(),
            (0..20).map(|k| fresh.span(k)).collect::<Vec<_>>()
        );
        assert_eq!((b_close, close + 22), (fresh_close, fresh_close));
        // A body of other bytes is read anew; a load that stops early lets nothing go, a
        // complete one keeps only what it used.
        let other = text("", 21);
        let (c, _) = cache.read_list(&other, start(&other), other.len()).unwrap();
        assert!(!Arc::ptr_eq(&a.values, &c.values));
        assert_eq!(c.values.len(), 21);
        cache.finish_load(false);
        assert_eq!(cache.count(), 2);
        cache.read_list(&other, start(&other), other.len()).unwrap();
        cache.finish_load(true);
        assert_eq!(cache.count(), 1);
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
