//! docs/keywords.md is the table in src/eval/lang/keywords.rs.

use crate::root;

#[test]
fn keywords_doc_matches_the_table() {
    let path = root().join("docs/keywords.md");
    let expected = trace::keyword_table();
    if std::env::var_os("TRACE_UPDATE_DOCS").is_some() {
        std::fs::write(&path, &expected).expect("write docs/keywords.md");
    }
    let actual = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        actual == expected,
        "docs/keywords.md is out of date: run TRACE_UPDATE_DOCS=1 cargo test keywords"
    );
}
