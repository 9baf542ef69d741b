//! The pipeline runs one way (design: syntax → eval → IR → scene → render → film): each
//! module of the library may name only the modules below it. This test reads the sources and
//! fails on any `crate::module` path against that direction.

use crate::root;
use std::collections::BTreeSet;

/// The modules each module may use (besides itself).
const ALLOWED: &[(&str, &[&str])] = &[
    ("diag", &[]),
    ("syntax", &["diag"]),
    // meshfile: `mesh_file { }` reads OBJ and PLY files while evaluating.
    // font: `text { ttf … }` lays glyphs out while evaluating.
    // func: user functions compiled while evaluating.
    (
        "eval",
        &[
            "syntax", "ir", "diag", "meshfile", "pattern", "font", "func", "noise", "cancel",
        ],
    ),
    ("ir", &["diag", "pattern", "func", "noise"]),
    // func: the isosurface's function (a function of a point, like a pattern).
    // memory: buffers on huge pages for what rays read scattered (a mesh's tree).
    ("geometry", &["func", "memory"]),
    // func: compiled user functions (noise: f_noise3d is the patterns' noise).
    ("func", &["noise"]),
    // pattern: functions of a point (what a pigment or normal looks up), used by the IR's
    // materials and by the render-ready ones; func: function patterns.
    ("pattern", &["noise", "func"]),
    // noise: POV-Ray's noise, turbulence and hashes (patterns, functions, normals, blur).
    ("noise", &[]),
    // memory: huge pages for the objects and the top-level tree.
    (
        "scene",
        &["ir", "geometry", "pattern", "func", "noise", "memory"],
    ),
    // cancel: a load or render stopped by its caller.
    ("render", &["scene", "geometry", "film", "cancel"]),
    // output: temporary files removed on interrupt or when memory runs out.
    ("film", &["output"]),
    ("meshfile", &["output"]),
    // font: TrueType outlines laid out into the IR's text.
    ("font", &["ir"]),
    ("memory", &["output"]),
    ("output", &[]),
    ("cancel", &[]),
];

#[test]
fn no_module_uses_one_against_the_pipeline_direction() {
    let src = root().join("src");
    let modules: BTreeSet<&str> = ALLOWED.iter().map(|(m, _)| *m).collect();
    let mut violations = Vec::new();
    for path in rust_files(&src) {
        let rel = path.strip_prefix(&src).unwrap();
        let module = module_path(rel);
        let Some(first) = module.first() else {
            continue; // lib.rs: the API, which may use every stage
        };
        let Some((_, allowed)) = ALLOWED.iter().find(|(m, _)| m == first) else {
            continue;
        };
        let text = std::fs::read_to_string(&path).unwrap();
        for used in used_modules(&text, &module) {
            if &used != first
                && modules.contains(used.as_str())
                && !allowed.contains(&used.as_str())
            {
                violations.push(format!("{} uses crate::{used}", rel.display()));
            }
        }
    }
    assert!(
        violations.is_empty(),
        "against the pipeline: {violations:#?}"
    );
}

/// The evaluator's two halves (design: eval): the language (`eval/lang/`: values, directives,
/// macros, functions, files) and the IR builder (`eval/build/`: objects, shapes, materials,
/// lights, camera, the scene's settings). The builder asks the language for values; the
/// language hands a statement's blocks to the builder by calling it, and keeps and names no IR
/// itself: no path into `ir` (or the stages only the builder needs), none into `eval::build`,
/// and no use of the builder's state (`self.scene`).
#[test]
fn the_language_names_nothing_of_the_ir_builder() {
    let files = rust_files(&root().join("src/eval/lang"));
    assert!(files.len() >= 9, "the language's files: {files:?}");
    let src = root().join("src");
    let mut violations = Vec::new();
    for path in files {
        let rel = path.strip_prefix(&src).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        for found in builder_uses(&text, &module_path(rel)) {
            violations.push(format!("{}: {found}", rel.display()));
        }
    }
    assert!(
        violations.is_empty(),
        "the language reaches into the IR builder: {violations:#?}"
    );
}

/// What of the IR builder's side a file of the language names (see above).
fn builder_uses(text: &str, module: &[String]) -> Vec<String> {
    const BUILDER_ONLY: &[&str] = &["ir", "pattern", "meshfile", "font"];
    let mut found: Vec<String> = used_modules(text, module)
        .into_iter()
        .filter(|m| BUILDER_ONLY.contains(&m.as_str()))
        .map(|m| format!("crate::{m}"))
        .collect();
    // Paths and fields, with comments, strings and white space left out.
    let code: String = strip_comments_and_strings(text)
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect();
    let word_before = |at: usize| {
        code[..at]
            .chars()
            .next_back()
            .is_some_and(|c| c.is_alphanumeric() || c == '_')
    };
    for (at, _) in code.match_indices("build::") {
        if !word_before(at) {
            found.push("eval::build".into());
        }
    }
    for (at, _) in code.match_indices("ir::") {
        if !word_before(at) {
            found.push("ir::".into());
        }
    }
    if code.contains(".scene.") {
        found.push("the builder's state (.scene.)".into());
    }
    found
}

#[test]
fn builder_uses_are_found_however_they_are_spelled() {
    let m = |s: &str| s.split("::").map(String::from).collect::<Vec<_>>();
    let here = m("eval::lang::expr");
    assert!(builder_uses("let x = self.lang.env.len(); // self.scene.lights", &here).is_empty());
    assert!(builder_uses("let s = \"ir::Texture\"; let v = vir::x();", &here).is_empty());
    for text in [
        "use crate::ir::Texture;",
        "use crate::{diag, ir};",
        "let t: crate::ir::Texture = t;",
        "let t = ir::Pigment::default();",
        "crate::eval::build::material::layer(a, b)",
        "use crate::eval::{Evaluator, build::light};",
        "use super::super::build::camera::CameraItems;",
        "self\n    .scene\n    .lights\n    .push(l)",
        "use crate::pattern::Pattern;",
    ] {
        assert!(!builder_uses(text, &here).is_empty(), "{text}");
    }
}

/// The Rust files under `dir`, at any depth.
fn rust_files(dir: &std::path::Path) -> Vec<std::path::PathBuf> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    files
}

/// The module a source file holds, from its path under src/ (`eval/flow.rs` → eval::flow,
/// `eval/mod.rs` → eval, `lib.rs` → the crate root).
fn module_path(rel: &std::path::Path) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    if parts
        .last()
        .is_some_and(|p| p == "mod" || p == "lib" || p == "main")
    {
        parts.pop();
    }
    parts
}

/// The top-level modules a file's code reaches, however the path is spelled: `crate::a::…`,
/// `super::super::a`, `self::…` (resolved against the file's module and the inline modules
/// around the path), and each item of a group `use crate::{a, b::c}`. Comments and strings
/// are left out.
fn used_modules(text: &str, module: &[String]) -> Vec<String> {
    let code = strip_comments_and_strings(text);
    let b = code.as_bytes();
    let is_word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    // Inline modules open at each point: (name, brace depth inside them).
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'{' => {
                depth += 1;
                i += 1;
                continue;
            }
            b'}' => {
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
                depth = depth.saturating_sub(1);
                i += 1;
                continue;
            }
            c if is_word(c) && (i == 0 || !is_word(b[i - 1]) && b[i - 1] != b':') => {}
            _ => {
                i += 1;
                continue;
            }
        }
        let end = (i..b.len()).find(|&k| !is_word(b[k])).unwrap_or(b.len());
        let word = &code[i..end];
        if word == "mod" {
            // `mod name {`: an inline module.
            let rest = code[end..].trim_start();
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() && rest[name.len()..].trim_start().starts_with('{') {
                inline.push((name, depth + 1));
            }
            i = end;
            continue;
        }
        if !matches!(word, "crate" | "super" | "self") || !code[end..].starts_with("::") {
            i = end;
            continue;
        }
        // The module this path starts from.
        let mut here: Vec<String> = module.to_vec();
        here.extend(inline.iter().map(|(n, _)| n.clone()));
        let mut j = i;
        loop {
            let e = (j..b.len()).find(|&k| !is_word(b[k])).unwrap_or(b.len());
            match &code[j..e] {
                "crate" => here.clear(),
                "super" => {
                    here.pop();
                }
                "self" => {}
                _ => break,
            }
            j = e;
            if !code[j..].starts_with("::") {
                break;
            }
            j += 2;
        }
        // What follows the prefix: a name, or a group of paths.
        let mut firsts = Vec::new();
        if let Some(group) = code[j..].strip_prefix('{') {
            let mut level = 0;
            let mut start = 0;
            for (k, c) in group.char_indices() {
                match c {
                    '{' => level += 1,
                    '}' if level == 0 => {
                        firsts.push(first_word(&group[start..k]));
                        break;
                    }
                    '}' => level -= 1,
                    ',' if level == 0 => {
                        firsts.push(first_word(&group[start..k]));
                        start = k + 1;
                    }
                    _ => {}
                }
            }
        } else {
            firsts.push(first_word(&code[j..]));
        }
        for f in firsts {
            let top = match here.first() {
                Some(top) => top.clone(),
                None => f,
            };
            if !top.is_empty() {
                out.push(top);
            }
        }
        i = j.max(end);
    }
    out
}

fn first_word(s: &str) -> String {
    s.trim_start()
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect()
}

/// The text with comments and string literals blanked (lengths kept).
fn strip_comments_and_strings(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = b.to_vec();
    let mut i = 0;
    while i < b.len() {
        let blank_to = if b[i..].starts_with(b"//") {
            b[i..]
                .iter()
                .position(|&c| c == b'\n')
                .map_or(b.len(), |n| i + n)
        } else if b[i..].starts_with(b"/*") {
            b[i + 2..]
                .windows(2)
                .position(|w| w == b"*/")
                .map_or(b.len(), |n| i + n + 4)
        } else if b[i] == b'"' {
            let mut k = i + 1;
            while k < b.len() && b[k] != b'"' {
                k += if b[k] == b'\\' { 2 } else { 1 };
            }
            (k + 1).min(b.len())
        } else if b[i] == b'\'' && b.get(i + 2) == Some(&b'\'') {
            i + 3 // a character literal such as '{'
        } else if b[i] == b'\'' && b.get(i + 1) == Some(&b'\\') {
            b[i + 2..]
                .iter()
                .position(|&c| c == b'\'')
                .map_or(b.len(), |n| i + n + 3)
        } else {
            i += 1;
            continue;
        };
        for c in &mut out[i..blank_to] {
            if *c != b'\n' {
                *c = b' ';
            }
        }
        i = blank_to;
    }
    String::from_utf8_lossy(&out).into_owned()
}

#[test]
fn paths_are_resolved_however_they_are_spelled() {
    let m = |s: &str| s.split("::").map(String::from).collect::<Vec<_>>();
    let used = used_modules(
        "use crate::{ir::{A, B}, diag};\nlet x = crate::scene::f();\nuse super::super::render::X;\n\
         // crate::film in a comment\nlet s = \"crate::film\";\n\
         mod tests { use super::super::super::geometry::Ray; use super::*; }\nuse self::sub::Y;",
        &m("eval::flow"),
    );
    assert_eq!(
        used,
        ["ir", "diag", "scene", "render", "geometry", "eval", "eval"]
    );
    // From the crate root's own modules, `super::` reaches a sibling stage.
    assert_eq!(
        used_modules("use super::scene::Scene;", &m("render")),
        ["scene"]
    );
}
