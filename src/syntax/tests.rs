//! Grammar tests: what each rule accepts and rejects.

use super::*;

fn parse(text: &str) -> Result<Vec<Node>, Diagnostic> {
    parse_scene(text, FileId(0))
}

#[test]
fn nested_block_comments_are_one_comment() {
    let nodes = parse("/* a /* b */ c */ sphere { 0, 1 }").expect("parses");
    assert_eq!(nodes.len(), 1);
    assert_eq!(nodes[0].kind, NodeKind::Sphere);
}

#[test]
fn line_comment_runs_to_end_of_line() {
    let nodes = parse("// sphere { 0, 1 }\nplane { y, 0 }").expect("parses");
    assert_eq!(nodes.len(), 1);
    assert_eq!(nodes[0].kind, NodeKind::Plane);
}

#[test]
fn keywords_need_a_word_boundary() {
    // `spheres` is not `sphere`: it parses as an unknown item.
    let nodes = parse("spheres { 0, 1 }").expect("parses");
    assert_eq!(nodes[0].kind, NodeKind::Unknown);
    assert_eq!(nodes[0].word, "spheres");
}

#[test]
fn vector_elements_stop_before_closing_angle() {
    // A general vector (with expressions) and a plain one (numbers only, the fast path).
    let nodes = parse("sphere { <1, 2*2, -3>, 1 }").expect("parses");
    let ExprKind::Vector(items) = &nodes[0].args[0].kind else {
        panic!("vector expected")
    };
    assert_eq!(items.len(), 3);
    let nodes = parse("sphere { <1, 2, -3>, 1 }").expect("parses");
    assert!(matches!(nodes[0].args[0].kind, ExprKind::PlainVector(_, 3)));
}

#[test]
fn vector_commas_are_optional_as_in_povray() {
    let nodes = parse("sphere { <4 0 x.y>, 1 }").expect("parses");
    let ExprKind::Vector(items) = &nodes[0].args[0].kind else {
        panic!("vector expected")
    };
    assert_eq!(items.len(), 3);
}

#[test]
fn and_or_share_one_level_left_to_right() {
    let nodes = parse("#declare A = 1 | 0 & 0;").expect("parses");
    // (1 | 0) & 0: the root is `&`.
    let ExprKind::Binary(op, ..) = &nodes[0].args[0].kind else {
        panic!("binary expected")
    };
    assert_eq!(*op, BinOp::And);
}

#[test]
fn products_bind_tighter_than_sums() {
    let nodes = parse("#declare A = 1 + 2 * 3;").expect("parses");
    let ExprKind::Binary(op, _, right) = &nodes[0].args[0].kind else {
        panic!("binary expected")
    };
    assert_eq!(*op, BinOp::Add);
    assert!(matches!(right.kind, ExprKind::Binary(BinOp::Mul, ..)));
}

#[test]
fn colour_with_channel_modifiers() {
    let nodes = parse("#declare C = color rgb <1, 0, 0> filter 0.5;").expect("parses");
    let ExprKind::Colour(parts) = &nodes[0].args[0].kind else {
        panic!("colour expected")
    };
    assert_eq!(parts.len(), 2);
}

#[test]
fn declare_of_a_float_needs_a_semicolon() {
    assert!(parse("#declare A = 1 sphere { 0, 1 }").is_err());
}

#[test]
fn unknown_statement_is_kept_for_evaluation() {
    let nodes = parse("difference { sphere { 0, 1 } box { 0, 1 } }").expect("parses");
    assert_eq!(nodes[0].kind, NodeKind::Unknown);
    assert_eq!(nodes[0].word, "difference");
}

#[test]
fn missing_brace_is_a_located_syntax_error() {
    let err = parse("sphere { 0, 1 ").expect_err("fails");
    assert!(err.message.starts_with("syntax error"), "{}", err.message);
    assert_eq!(err.span.map(|s| s.start), Some(14));
}

#[test]
fn signed_number_after_a_space_in_a_vector_is_a_subtraction() {
    let nodes = parse("sphere { <4 -1>, 1 }").expect("parses");
    let ExprKind::Vector(items) = &nodes[0].args[0].kind else {
        panic!("general vector expected")
    };
    assert_eq!(items.len(), 1);
}
