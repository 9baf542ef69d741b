//! User files (POV-Ray §3.3.2.3): `#fopen F "name" read|write|append`, `#read (F, A, …)`,
//! `#write (F, …)`, `#fclose F`.
//!
//! A file is read from the folders the scene may read (the sandbox: the scene's folder and
//! the `-L` folders) and written only inside the scene's own folder. POV-Ray's reading is
//! kept: values are float literals (signed), vectors of 2 to 5 of them and string literals,
//! separated by commas, with comments; a value not followed by a comma loses the token after
//! it (POV-Ray drops it); at the end of the file the variable keeps its value, the file is
//! closed and its name undefined (so `#while (defined(F)) #read (F, V) … #end` reads it all).
//! Writing is POV-Ray's too: strings as they are, floats as C's `%g`, vectors as
//! `<%g,%g,%g> ` (with the trailing space), and binary integers (`uint8`, `sint16le` …)
//! rounded and clamped to their range.

use crate::diag::{Diagnostic, FileId, Span};
use crate::eval::{Evaluator, Result, Value, value::Vector};
use crate::syntax::{Expr, Node, View};
use std::io::Write;
use std::path::PathBuf;

/// Most files open at once (each holds an operating-system file while writing).
pub const MAX_OPEN_FILES: usize = 256;
/// Most bytes a scene may write to its files, all together (a loop writing forever stops).
pub const MAX_WRITTEN_BYTES: u64 = 256 << 20;

/// An open user file.
pub(in crate::eval) enum UserFile {
    /// Its text (in the source map, so errors point into it) and how far it has been read.
    Read { file: FileId, pos: usize },
    Write {
        out: std::io::BufWriter<std::fs::File>,
        path: PathBuf,
    },
}

/// The scene's user files.
#[derive(Default)]
pub(in crate::eval) struct Files {
    open: Vec<Option<UserFile>>,
    written: u64,
    /// Files read so far, by path, while the scene has not written them since: a loop
    /// opening one file again and again keeps one copy of its text.
    read: std::collections::HashMap<PathBuf, FileId>,
}

impl Files {
    /// Writes what is buffered; called when evaluation ends.
    pub(in crate::eval) fn flush(&mut self) -> std::io::Result<()> {
        for f in self.open.iter_mut().flatten() {
            if let UserFile::Write { out, .. } = f {
                out.flush()?;
            }
        }
        Ok(())
    }
}

/// One token of a data file.
#[derive(Debug, PartialEq)]
enum Token {
    Number(f64),
    Str(String),
    /// `<`, `>`, `,`, `+`, `-`, or any other character (an error where a value is wanted).
    Symbol(char),
    /// A word: POV-Ray reads identifiers in data files as errors too.
    Word(String),
    End,
}

/// Reads tokens of a data file's text from a byte offset, with the scene's lexer (POV-Ray
/// reads data files with its scene tokenizer too).
struct Lexer<'t> {
    text: &'t str,
    pos: usize,
}

impl Lexer<'_> {
    /// The next token and where it starts.
    fn next(&mut self) -> std::result::Result<(Token, usize), (String, usize)> {
        use crate::syntax::lexer::{self, TokenKind};
        let end = self.text.len();
        let t = lexer::Lexer::new(self.text, self.pos.min(end)..end)
            .next()
            .map_err(|e| (e.message.to_string(), e.at))?;
        let Some(t) = t else {
            self.pos = end;
            return Ok((Token::End, end));
        };
        let (start, text) = (t.start as usize, t.text(self.text));
        self.pos = t.end as usize;
        let token = match t.kind {
            TokenKind::Number => match lexer::number_value(text) {
                v if v.is_finite() => Token::Number(v),
                _ => return Err((format!("`{text}` is not a number"), start)),
            },
            TokenKind::Str => Token::Str(unescape(&text[1..text.len() - 1])),
            TokenKind::Word => Token::Word(text.to_string()),
            // (One character a token here: `<=` is `<`, then `=`.)
            _ => {
                let c = text.chars().next().unwrap_or('#');
                self.pos = start + c.len_utf8();
                Token::Symbol(c)
            }
        };
        Ok((token, start))
    }
}

/// A string literal's text with POV-Ray's escapes replaced (`\"`, `\\`, `\n`, `\t`, `\r`,
/// `\a`, `\b`, `\f`, `\v`, `\'`, `\uXXXX`); any other backslash stays as written.
pub(in crate::eval) fn unescape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut chars = s.chars();
    while let Some(c) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        let Some(e) = chars.next() else {
            out.push('\\');
            break;
        };
        match e {
            '"' => out.push('"'),
            '\\' => out.push('\\'),
            '\'' => out.push('\''),
            'n' => out.push('\n'),
            't' => out.push('\t'),
            'r' => out.push('\r'),
            'a' => out.push('\x07'),
            'b' => out.push('\x08'),
            'f' => out.push('\x0c'),
            'v' => out.push('\x0b'),
            'u' => {
                let hex: String = chars.clone().take(4).collect();
                match u32::from_str_radix(&hex, 16).ok().and_then(char::from_u32) {
                    Some(ch) if hex.len() == 4 => {
                        out.push(ch);
                        for _ in 0..4 {
                            chars.next();
                        }
                    }
                    _ => out.push_str("\\u"),
                }
            }
            other => {
                out.push('\\');
                out.push(other);
            }
        }
    }
    out
}

/// `v` as C's `printf("%g")` writes it: 6 significant digits, trailing zeros dropped,
/// scientific notation (`1e+07`) when the exponent is below -4 or at least 6.
pub fn format_g(v: f64) -> String {
    if v.is_nan() {
        return if v.is_sign_negative() { "-nan" } else { "nan" }.into();
    }
    if v.is_infinite() {
        return if v < 0.0 { "-inf" } else { "inf" }.into();
    }
    if v == 0.0 {
        return if v.is_sign_negative() { "-0" } else { "0" }.into();
    }
    // Rounded to 6 significant digits first: the exponent is the rounded number's.
    let sci = format!("{v:.5e}");
    let (mantissa, exp) = sci.split_once('e').expect("`{:e}` writes an exponent");
    let exp: i32 = exp.parse().expect("an integer exponent");
    let trim = |s: &str| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    if !(-4..6).contains(&exp) {
        let sign = if exp < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mantissa), exp.abs())
    } else {
        let decimals = (5 - exp) as usize;
        trim(&format!("{v:.decimals$}"))
    }
}

impl Evaluator<'_> {
    /// `#fopen`, `#fclose`, `#read`, `#write`.
    pub(in crate::eval) fn file_directive(&mut self, item: &Node) -> Result<()> {
        match item.view() {
            View::FileOpen { name, file, mode } => self.fopen(item, name, file, mode),
            View::FileClose { name } => {
                // Closing a name that is not an open file does nothing, as in POV-Ray.
                let name = name.word.as_str();
                if let Some(Value::File(id)) = self.lang.env.get(name).map(|v| &**v) {
                    let id = *id;
                    self.close_file(id, item.span)?;
                    self.lang.env.remove(name);
                }
                Ok(())
            }
            View::FileRead { file, targets } => self.read_values(file, targets),
            View::FileWrite { file, items } => self.write_values(item, file, items),
            _ => Err(crate::eval::malformed(item, "a file directive")),
        }
    }

    fn fopen(
        &mut self,
        item: &Node,
        name_node: &Node,
        file: &Expr,
        mode_node: &Node,
    ) -> Result<()> {
        let mode = mode_node.word.as_str();
        let name = self.string(file)?;
        let span = file.span;
        if !matches!(mode, "read" | "write" | "append") {
            return Err(Diagnostic::error(
                format!("expected `read`, `write` or `append`, found `{mode}`"),
                mode_node.span,
            ));
        }
        // Opening a name again first closes the file it held, as POV-Ray replaces the symbol.
        if let Some(Value::File(id)) = self.lang.env.get(name_node.word.as_str()).map(|v| &**v) {
            let id = *id;
            self.close_file(id, item.span)?;
        }
        let open = self.lang.files.open.iter().filter(|f| f.is_some()).count();
        if open >= MAX_OPEN_FILES {
            return Err(Diagnostic::error(
                format!("more than {MAX_OPEN_FILES} files open at once"),
                item.word_span,
            ));
        }
        let file = if mode == "read" {
            let path = self.find_file(&name, "user file", span)?;
            let file = match self.lang.files.read.get(&path) {
                Some(id) => *id,
                None => {
                    let text = crate::diag::read_source(&path).map_err(|e| {
                        Diagnostic::error(format!("cannot read {}: {e}", path.display()), span)
                    })?;
                    let id = self.sources.add(&path, text);
                    self.lang.files.read.insert(path, id);
                    id
                }
            };
            UserFile::Read { file, pos: 0 }
        } else {
            let path = self.sandbox.writable(&name).map_err(|why| {
                Diagnostic::error(format!("cannot write user file \"{name}\": {why}"), span)
                    .with_note("a scene writes files only inside its own folder")
            })?;
            let opened = std::fs::OpenOptions::new()
                .create(true)
                .write(true)
                .append(mode == "append")
                .truncate(mode == "write")
                .open(&path)
                .map_err(|e| {
                    Diagnostic::error(format!("cannot write {}: {e}", path.display()), span)
                })?;
            // (Read again after this, the file is read anew.)
            self.lang.files.read.remove(&path);
            UserFile::Write {
                out: std::io::BufWriter::new(opened),
                path,
            }
        };
        let id = match self.lang.files.open.iter().position(Option::is_none) {
            Some(free) => {
                self.lang.files.open[free] = Some(file);
                free
            }
            None => {
                self.lang.files.open.push(Some(file));
                self.lang.files.open.len() - 1
            }
        };
        self.set(name_node.word.to_string(), Value::File(id));
        Ok(())
    }

    fn close_file(&mut self, id: usize, span: Span) -> Result<()> {
        if let Some(UserFile::Write { mut out, path }) = self.lang.files.open[id].take() {
            out.flush().map_err(|e| {
                Diagnostic::error(format!("cannot write {}: {e}", path.display()), span)
            })?;
        }
        Ok(())
    }

    /// The open file a `#read`/`#write` names.
    fn user_file(&self, node: &Node) -> Result<usize> {
        match self.lang.env.get(node.word.as_str()).map(|v| &**v) {
            Some(Value::File(id)) => Ok(*id),
            Some(other) => Err(crate::eval::lang::expr::type_error(
                "a file opened by #fopen",
                other,
                node.span,
            )),
            None => Err(Diagnostic::error(
                format!("`{}` is not an open file", node.word),
                node.span,
            )
            .with_note("open it with #fopen (a file read to its end is closed)")),
        }
    }

    /// `#read (F, A, B[i], …)`.
    fn read_values(&mut self, file_node: &Node, targets: &[Node]) -> Result<()> {
        let id = self.user_file(file_node)?;
        let Some(UserFile::Read { file, pos }) = &self.lang.files.open[id] else {
            return Err(Diagnostic::error(
                format!("cannot read `{}`: it is open for writing", file_node.word),
                file_node.span,
            ));
        };
        let (file, mut pos) = (*file, *pos);
        let mut at_end = false;
        for target in targets {
            let text = self.sources.file(file).text.clone();
            let mut lexer = Lexer { text: &text, pos };
            let value = read_value(&mut lexer).map_err(|(message, at)| {
                let end = (at + 1).min(text.len()).max(at);
                Diagnostic::error(message, Span::new(file, at, end))
                    .with_note(format!("read by #read at {}", self.location(target.span)))
            })?;
            pos = lexer.pos;
            let Some((value, ended)) = value else {
                at_end = true;
                break;
            };
            self.charge(1, "#read", target.span)?;
            if target.children.is_empty() {
                self.set(target.word.to_string(), value);
            } else {
                let subs: Vec<&Node> = target.children.iter().collect();
                self.assign_element(target, &subs, value)?;
            }
            if ended {
                at_end = true;
                break;
            }
        }
        if at_end {
            self.lang.files.open[id] = None;
            self.lang.env.remove(file_node.word.as_str());
        } else if let Some(UserFile::Read { pos: p, .. }) = &mut self.lang.files.open[id] {
            *p = pos;
        }
        Ok(())
    }

    /// `#write (F, value, …)`.
    fn write_values(&mut self, item: &Node, file_node: &Node, items: &[Node]) -> Result<()> {
        let id = self.user_file(file_node)?;
        if !matches!(self.lang.files.open[id], Some(UserFile::Write { .. })) {
            return Err(Diagnostic::error(
                format!("cannot write `{}`: it is open for reading", file_node.word),
                file_node.span,
            ));
        }
        let mut bytes: Vec<u8> = Vec::new();
        for w in items {
            let View::WriteItem { value: expr, kind } = w.view() else {
                return Err(crate::eval::malformed(w, "a value of #write"));
            };
            match kind {
                Some(kind) => {
                    let v = self.eval(expr)?;
                    let Some((c, n)) = v.components() else {
                        return Err(crate::eval::lang::expr::type_error(
                            "a number or vector",
                            &v,
                            expr.span,
                        ));
                    };
                    write_binary(&mut bytes, &kind.word, &c[..n])
                        .map_err(|m| Diagnostic::error(m, kind.span))?;
                }
                None => match self.eval(expr)? {
                    Value::Str(s) => bytes.extend_from_slice(s.as_bytes()),
                    Value::Float(f) => bytes.extend_from_slice(format_g(f).as_bytes()),
                    v => {
                        let Some((c, n)) = v.components() else {
                            return Err(crate::eval::lang::expr::type_error(
                                "a string, number or vector",
                                &v,
                                expr.span,
                            ));
                        };
                        let parts: Vec<String> = c[..n].iter().map(|x| format_g(*x)).collect();
                        bytes.extend_from_slice(format!("<{}> ", parts.join(",")).as_bytes());
                    }
                },
            }
        }
        self.lang.files.written += bytes.len() as u64;
        if self.lang.files.written > MAX_WRITTEN_BYTES {
            return Err(Diagnostic::error(
                format!("the scene writes more than {MAX_WRITTEN_BYTES} bytes to its files"),
                item.word_span,
            ));
        }
        let Some(UserFile::Write { out, path }) = &mut self.lang.files.open[id] else {
            unreachable!("checked above");
        };
        out.write_all(&bytes).map_err(|e| {
            Diagnostic::error(
                format!("cannot write {}: {e}", path.display()),
                item.word_span,
            )
        })
    }
}

/// The next value of a data file and whether the file ends right after it, or `None` at
/// its end.
fn read_value(lexer: &mut Lexer) -> std::result::Result<Option<(Value, bool)>, (String, usize)> {
    const WANTED: &str = "expected a float, vector, or string literal";
    let (token, at) = lexer.next()?;
    let value = match token {
        Token::End => return Ok(None),
        Token::Str(s) => Value::Str(s),
        Token::Symbol('<') => {
            let mut c = Vec::with_capacity(5);
            loop {
                c.push(signed(lexer)?);
                // (Inside a vector a missing comma loses nothing.)
                let save = lexer.pos;
                if lexer.next()?.0 != Token::Symbol(',') {
                    lexer.pos = save;
                }
                if c.len() >= 2 {
                    let save = lexer.pos;
                    if let (Token::Symbol('>'), _) = lexer.next()? {
                        break;
                    }
                    lexer.pos = save;
                }
                if c.len() == 5 {
                    let (_, at) = lexer.next()?;
                    return Err(("vector data too long (at most 5 components)".into(), at));
                }
            }
            if c.len() == 5 {
                Value::Colour([c[0], c[1], c[2], c[3], c[4]])
            } else {
                Value::Vector(Vector::new(&c))
            }
        }
        Token::Number(_) | Token::Symbol('+' | '-') => {
            lexer.pos = at;
            Value::Float(signed(lexer)?)
        }
        Token::Word(w) => return Err((format!("{WANTED}, found `{w}`"), at)),
        Token::Symbol(c) => return Err((format!("{WANTED}, found `{c}`"), at)),
    };
    // After a value a comma is taken; any other token is lost, as POV-Ray loses it, and the
    // end of the file ends the reading at once (POV-Ray closes the file after this value).
    let ended = lexer.next()?.0 == Token::End;
    Ok(Some((value, ended)))
}

/// A float literal with any number of `+` and at most one `-` before it.
fn signed(lexer: &mut Lexer) -> std::result::Result<f64, (String, usize)> {
    loop {
        match lexer.next()? {
            (Token::Symbol('+'), _) => {}
            (Token::Symbol('-'), _) => {
                return match lexer.next()? {
                    (Token::Number(v), _) => Ok(-v),
                    (_, at) => Err(("expected a float after `-`".into(), at)),
                };
            }
            (Token::Number(v), _) => return Ok(v),
            (_, at) => return Err(("expected a float".into(), at)),
        }
    }
}

/// `values` as binary integers of `kind` (`uint8`, `sint16be` …): rounded, clamped to the
/// kind's range, least significant byte first unless big-endian.
fn write_binary(out: &mut Vec<u8>, kind: &str, values: &[f64]) -> std::result::Result<(), String> {
    let (min, max, bytes, big): (i64, i64, usize, bool) = match kind {
        "sint8" => (-128, 127, 1, false),
        "uint8" => (0, 255, 1, false),
        "sint16le" => (-32768, 32767, 2, false),
        "sint16be" => (-32768, 32767, 2, true),
        "uint16le" => (0, 65535, 2, false),
        "uint16be" => (0, 65535, 2, true),
        "sint32le" => (i32::MIN as i64, i32::MAX as i64, 4, false),
        "sint32be" => (i32::MIN as i64, i32::MAX as i64, 4, true),
        other => {
            return Err(format!(
                "`{other}` is not a binary kind (uint8, sint16le …)"
            ));
        }
    };
    for &v in values {
        let n = if v <= min as f64 {
            min
        } else if v >= max as f64 {
            max
        } else {
            (v + 0.5).floor() as i64
        };
        for j in 0..bytes {
            let shift = if big { bytes - 1 - j } else { j } * 8;
            out.push(((n >> shift) & 0xff) as u8);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_written_as_c_writes_percent_g() {
        for (v, s) in [
            (1.5, "1.5"),
            (1.0 / 3.0, "0.333333"),
            (1e7, "1e+07"),
            (123456789.0, "1.23457e+08"),
            (-0.0001, "-0.0001"),
            (0.00001234, "1.234e-05"),
            (100000.0, "100000"),
            (999999.5, "1e+06"),
            (0.0, "0"),
            (2.0, "2"),
        ] {
            assert_eq!(format_g(v), s, "{v}");
        }
    }

    #[test]
    fn escapes_are_povrays() {
        assert_eq!(unescape(r#"a\"b\\n\n\t\u0041\q"#), "a\"b\\n\n\tA\\q");
    }

    fn read_all(text: &str) -> Vec<Value> {
        let mut lexer = Lexer { text, pos: 0 };
        let mut out = Vec::new();
        while let Some((v, _)) = read_value(&mut lexer).unwrap() {
            out.push(v);
        }
        out
    }

    #[test]
    fn data_files_read_as_povray_reads_them() {
        let values = read_all(
            "\"s1\",-1.5,<1,2,3> ,\"two\\\\x\", // c\n - 3, + +2, <1,2>, /* c */ <1,2,3,4,5>, 1e3",
        );
        let shown: Vec<String> = values
            .iter()
            .map(|v| match v {
                Value::Str(s) => s.clone(),
                Value::Float(f) => f.to_string(),
                Value::Vector(v) => format!("{:?}", &v.c[..v.len]),
                Value::Colour(c) => format!("{c:?}"),
                _ => unreachable!(),
            })
            .collect();
        assert_eq!(
            shown,
            [
                "s1",
                "-1.5",
                "[1.0, 2.0, 3.0]",
                "two\\x",
                "-3",
                "2",
                "[1.0, 2.0]",
                "[1.0, 2.0, 3.0, 4.0, 5.0]",
                "1000"
            ]
        );
    }

    #[test]
    fn a_value_without_a_comma_loses_the_next_token() {
        // POV-Ray 3.7: `<4,5,6> "s", 7` reads the vector, loses "s", then reads `,` (an error).
        let mut lexer = Lexer {
            text: "1 2, 3",
            pos: 0,
        };
        assert!(matches!(
            read_value(&mut lexer),
            Ok(Some((Value::Float(1.0), false)))
        ));
        assert!(read_value(&mut lexer).is_err());
    }

    #[test]
    fn binary_integers_are_rounded_clamped_and_ordered() {
        let mut out = Vec::new();
        write_binary(&mut out, "uint8", &[1.4, 300.0, -5.0]).unwrap();
        write_binary(&mut out, "sint16be", &[-2.0]).unwrap();
        write_binary(&mut out, "uint16le", &[258.0]).unwrap();
        assert_eq!(out, [1, 255, 0, 0xff, 0xfe, 2, 1]);
    }
}
