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
            "syntax", "ir", "diag", "meshfile", "pattern", "font", "func", "noise",
        ],
    ),
    ("ir", &["diag", "pattern", "func", "noise"]),
    // func: the isosurface's function (a function of a point, like a pattern).
    ("geometry", &["func"]),
    // func: compiled user functions (noise: f_noise3d is the patterns' noise).
    ("func", &["noise"]),
    // pattern: functions of a point (what a pigment or normal looks up), used by the IR's
    // materials and by the render-ready ones; func: function patterns.
    ("pattern", &["noise", "func"]),
    // noise: POV-Ray's noise, turbulence and hashes (patterns, functions, normals, blur).
    ("noise", &[]),
    ("scene", &["ir", "geometry", "pattern", "func", "noise"]),
    ("render", &["scene", "geometry", "film"]),
    // output: temporary files removed on interrupt or when memory runs out.
    ("film", &["output"]),
    ("meshfile", &["output"]),
    // font: TrueType outlines laid out into the IR's text.
    ("font", &["ir"]),
    ("memory", &["output"]),
    ("output", &[]),
];

#[test]
fn no_module_uses_one_against_the_pipeline_direction() {
    let src = root().join("src");
    let modules: BTreeSet<&str> = ALLOWED.iter().map(|(m, _)| *m).collect();
    let mut violations = Vec::new();
    let mut files = Vec::new();
    let mut stack = vec![src.clone()];
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
    for path in files {
        let rel = path.strip_prefix(&src).unwrap();
        let first = rel
            .iter()
            .next()
            .unwrap()
            .to_string_lossy()
            .replace(".rs", "");
        let Some((_, allowed)) = ALLOWED.iter().find(|(m, _)| *m == first) else {
            continue; // lib.rs and main.rs: the API and the CLI
        };
        let text = std::fs::read_to_string(&path).unwrap();
        for used in crate_paths(&text) {
            if used != first && modules.contains(used.as_str()) && !allowed.contains(&used.as_str())
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

/// The first segment of every `crate::…` path, including each item of `use crate::{a, b::c}`.
fn crate_paths(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let word = |s: &str| -> String {
        s.trim_start()
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect()
    };
    for (i, _) in text.match_indices("crate::") {
        let rest = &text[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            // Top-level items of the group: split at commas outside nested braces.
            let mut depth = 0;
            let mut start = 0;
            for (k, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        out.push(word(&group[start..k]));
                        break;
                    }
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        out.push(word(&group[start..k]));
                        start = k + 1;
                    }
                    _ => {}
                }
            }
        } else {
            out.push(word(rest));
        }
    }
    out
}

#[test]
fn the_path_reader_sees_grouped_imports() {
    let paths = crate_paths("use crate::{ir::{A, B}, diag};\nlet x = crate::scene::f();");
    assert_eq!(paths, ["ir", "diag", "scene"]);
}
