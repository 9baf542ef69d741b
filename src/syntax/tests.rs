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
    let nodes = parse("#declare A = (1 | 0 & 0);").expect("parses");
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

/// A float declared without its `;` is read and marked: evaluation refuses it from version 3.5
/// on and warns before, as POV-Ray does.
#[test]
fn declare_of_a_float_without_semicolon_is_marked() {
    let nodes = parse("#declare A = 1 sphere { 0, 1 }").expect("parses");
    assert!(
        nodes[0]
            .children
            .iter()
            .any(|c| c.kind == NodeKind::MissingSemicolon)
    );
    let nodes = parse("#declare A = 1; sphere { 0, 1 }").expect("parses");
    assert!(
        !nodes[0]
            .children
            .iter()
            .any(|c| c.kind == NodeKind::MissingSemicolon)
    );
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

/// The statements of `text` as `Statements` yields them, rendered for comparison.
fn statement_dump(statements: Statements) -> Vec<String> {
    statements.map(|s| format!("{s:?}")).collect()
}

fn statements_with_parts(text: &str, starts: &[usize]) -> Statements {
    let mut s = statements(text.into(), FileId(0), 0).expect("nesting is fine");
    s.ahead = ahead::spawn(&s.source, FileId(0), starts);
    s
}

/// Statements of every kind that a guessed start could land inside: blocks in directives,
/// declarations ending in `;`, macro bodies, comments and strings holding braces.
const MIXED: &str = "#declare R = 0.5;\n\
    sphere { <0,0,0>, R pigment { rgb <1,0,0> } }\n\
    #if (R > 0) sphere { 1, R } box { 0, 1 } #else plane { y, 0 } #end\n\
    #declare S = sphere { 0, 1 };\n\
    /* } a comment { */ #macro M(A) sphere { A, 1 } #end\n\
    M(<1,2,3>)\n\
    #debug \"}\"\n\
    object { S translate x }\n";

#[test]
fn parts_parsed_ahead_give_the_statements_of_one_thread_wherever_they_start() {
    let one_thread = statement_dump(statements(MIXED.into(), FileId(0), 0).unwrap());
    assert_eq!(one_thread.len(), 8);
    // Every offset as a start (most are not statement ends), alone and with a second part.
    for a in 1..MIXED.len() {
        let dump = statement_dump(statements_with_parts(MIXED, &[a]));
        assert_eq!(dump, one_thread, "one part at {a}");
        for b in (a + 1..MIXED.len()).step_by(7) {
            let dump = statement_dump(statements_with_parts(MIXED, &[a, b]));
            assert_eq!(dump, one_thread, "parts at {a} and {b}");
        }
    }
}

#[test]
fn a_syntax_error_in_a_part_parsed_ahead_ends_the_statements_as_with_one_thread() {
    let text = "sphere { 0, 1 }\nbox { 0, 1 }\nsphere { 0, 1 \nplane { y, 0 }\n";
    let one_thread = statement_dump(statements(text.into(), FileId(0), 0).unwrap());
    assert!(
        one_thread.last().unwrap().starts_with("Err"),
        "{one_thread:?}"
    );
    for a in 1..text.len() {
        assert_eq!(
            statement_dump(statements_with_parts(text, &[a])),
            one_thread,
            "part at {a}"
        );
    }
}

#[test]
fn statements_dropped_early_stop_their_helpers() {
    let mut s = statements_with_parts(MIXED, &[MIXED.find("box").unwrap() + 12]);
    assert!(s.next().is_some());
    drop(s); // (Must return: the helpers are told to stop and joined.)
}

#[test]
fn guessed_part_starts_are_ends_of_top_level_blocks() {
    let text =
        "sphere { 0, 1 }\n#if (1) box { 0, 1 } #end\n#declare S = sphere { 0, 1 };\nplane { y, 0 }";
    let ends = check_nesting(text, FileId(0), 0).unwrap();
    let expected: Vec<usize> = [
        "sphere { 0, 1 }".len(),
        text.find("#declare").unwrap() + "#declare S = sphere { 0, 1 }".len(),
        text.len(),
    ]
    .to_vec();
    assert_eq!(ends, expected);
}

#[test]
fn a_literal_takes_the_fast_path_only_before_a_non_operator() {
    // `<1,0,0> <0,0,1>` are two vectors (area_light), not a comparison.
    let nodes = parse("light_source { 0, 1 area_light <1,0,0> <0,0,1>, 2, 2 }").expect("parses");
    let area = &nodes[0].children[0];
    assert!(matches!(area.args[0].kind, ExprKind::PlainVector(_, 3)));
    assert!(matches!(area.args[1].kind, ExprKind::PlainVector(_, 3)));
    // Followed by an operator, a literal is the start of a larger expression.
    for (text, op) in [
        ("1 + 2", BinOp::Add),
        ("<1,2> * 2", BinOp::Mul),
        ("(2 < 3)", BinOp::Lt),
    ] {
        let nodes = parse(&format!("#declare X = {text};")).expect("parses");
        assert!(
            matches!(&nodes[0].args[0].kind, ExprKind::Binary(o, _, _) if *o == op),
            "{text}: {:?}",
            nodes[0].args[0].kind
        );
    }
    // Outside parentheses a comparison is refused, as POV-Ray refuses it.
    assert!(parse("#declare X = 2 < 3;").is_err());
    // At the end of the text (a macro body used as a value) it stands alone.
    let value = parse_fragment_expr("0.5", FileId(0), 0).expect("parses");
    assert!(matches!(value.expr.kind, ExprKind::Number(v) if v == 0.5));
}

#[test]
fn colour_types_are_the_eight_of_povray() {
    for word in [
        "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft",
    ] {
        let nodes = parse(&format!("background {{ {word} 1 }}")).expect(word);
        let ExprKind::Colour(parts) = &nodes[0].args[0].kind else {
            panic!("{word}: a colour expected")
        };
        assert_eq!(parts.len(), 1, "{word}");
    }
    // A longer word is an identifier, not a colour type followed by letters.
    let nodes = parse("background { rgbx }").expect("parses");
    assert!(matches!(nodes[0].args[0].kind, ExprKind::Ident(_)));
}
