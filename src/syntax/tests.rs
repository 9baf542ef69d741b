//! Grammar tests: what each rule accepts and rejects, on units as the directive reader hands
//! them over (directive-free text).

use super::*;

/// A statement unit of `text`, as one file's text.
fn parse(text: &str) -> Result<Vec<Node>, Diagnostic> {
    parse_statement(&Unit::from_file_text(text, FileId(0), 0)).map(|n| vec![n])
}

/// A declared value's unit.
fn value(text: &str) -> Result<Expr, Diagnostic> {
    match parse_value(&Unit::from_file_text(text, FileId(0), 0))? {
        ValueSyntax::Expr(e) => Ok(e),
        ValueSyntax::Item(n) => panic!("an expression expected, found {:?}", n.kind),
    }
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
fn past_five_a_component_without_a_comma_takes_the_fifths_place() {
    // POV-Ray 3.7: <1 2 3 4 5 6 7> is <1, 2, 3, 4, 7>; a comma past the fifth is refused
    // (left to evaluation, which reports a vector of more than five).
    let numbers = |e: &Expr| -> Vec<f64> {
        match &e.kind {
            ExprKind::PlainVector(c, n) => c[..*n as usize].to_vec(),
            ExprKind::Vector(items) => items
                .iter()
                .map(|i| match i.kind {
                    ExprKind::Number(n) => n,
                    _ => f64::NAN,
                })
                .collect(),
            _ => panic!("a vector expected"),
        }
    };
    for text in [
        "<1 2 3 4 5 6 7>",
        "<1, 2, 3, 4, 5 6 7>",
        "<1, 2, 3, 4 /* , */ 5 7>",
    ] {
        assert_eq!(
            numbers(&value(text).unwrap()),
            [1.0, 2.0, 3.0, 4.0, 7.0],
            "{text}"
        );
    }
    // The same through the grammar's general vector (an expression in it).
    let e = value("<1, 2, 3, 4, 5 6 (7)>").unwrap();
    let ExprKind::Vector(items) = &e.kind else {
        panic!("a vector expected")
    };
    assert_eq!(items.len(), 5);
    assert_eq!(items[4].span.start, 18); // the 7 in (7)
    for text in [
        "<1, 2, 3, 4, 5, 6>",
        "<1 2 3 4 5 6, 7>",
        "<1, 2, 3, 4, 5, (6)>",
    ] {
        assert_eq!(
            numbers(&value(text).unwrap()).len(),
            6 + usize::from(text.contains('7')),
            "{text}"
        );
    }
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
    let e = value("(1 | 0 & 0)").expect("parses");
    // (1 | 0) & 0: the root is `&`.
    let ExprKind::Binary(op, ..) = &e.kind else {
        panic!("binary expected")
    };
    assert_eq!(*op, BinOp::And);
}

#[test]
fn products_bind_tighter_than_sums() {
    let e = value("1 + 2 * 3").expect("parses");
    let ExprKind::Binary(op, _, right) = &e.kind else {
        panic!("binary expected")
    };
    assert_eq!(*op, BinOp::Add);
    assert!(matches!(right.kind, ExprKind::Binary(BinOp::Mul, ..)));
}

#[test]
fn colour_with_channel_modifiers() {
    let e = value("color rgb <1, 0, 0> filter 0.5").expect("parses");
    let ExprKind::Colour(parts) = &e.kind else {
        panic!("colour expected")
    };
    assert_eq!(parts.len(), 2);
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
        let e = value(text).expect("parses");
        assert!(
            matches!(&e.kind, ExprKind::Binary(o, _, _) if *o == op),
            "{text}: {:?}",
            e.kind
        );
    }
    // Outside parentheses a comparison is refused, as POV-Ray refuses it.
    assert!(value("2 < 3").is_err());
    // At the end of the text it stands alone.
    assert!(matches!(value("0.5").unwrap().kind, ExprKind::Number(v) if v == 0.5));
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
    assert!(matches!(nodes[0].args[0].kind, ExprKind::Ident(..)));
}

/// A unit as the reader makes one for a loop: `head`, then `body` read `n` times from the
/// same place of the file, then `tail`; every word has a slot.
fn looped_unit(head: &str, body: &str, n: usize, tail: &str) -> Unit {
    let mut unit = Unit::default();
    let mut add = |text: &str, start: usize| {
        if !unit.text.is_empty() {
            unit.text.push(' ');
        }
        let at = unit.text.len();
        unit.pieces.push(Piece {
            at: at as u32,
            len: text.len() as u32,
            file: FileId(0),
            start: start as u32,
            src_len: text.len() as u32,
        });
        unit.text.push_str(text);
        let mut lexer = lexer::Lexer::new(text, 0..text.len());
        while let Ok(Some(t)) = lexer.next() {
            if t.kind == lexer::TokenKind::Word {
                unit.words.push(at as u32 + t.start);
            }
        }
    };
    add(head, 0);
    for _ in 0..n {
        add(body, head.len() + 10);
    }
    add(tail, head.len() + body.len() + 20);
    unit
}

#[test]
fn big_containers_read_item_by_item_as_the_whole_parse_reads_them() {
    let cases = [
        (
            "union {",
            "sphere { <I, mod(I, 3), 0>, R texture { pigment { color rgb <1, I/9, 0> } } } \
             light_source { <0, 9, I> White } object { Thing translate x*I } translate <1, 2, 3>",
            "rotate y*90 }",
        ),
        (
            "light_group {",
            "union { sphere { 0, 1 } box { -1, 1 scale I } } cylinder { 0, y, 0.1 open }",
            "global_lights }",
        ),
        (
            "mesh {",
            "triangle { <0, 0, I>, <1, 0, I>, <0, 1, I> } \
             smooth_triangle { <0,0,0>, y, <1,0,0>, y, <0,1,0>, y uv_vectors <0,0>, <1,0>, <0,1> }",
            "inside_vector y texture { T } }",
        ),
        (
            "mesh2 { vertex_vectors { N,",
            "<I, 0, 0>, <I+1, 0, 0> <I, f(I), 0>,",
            "} face_indices { 2, <0, 1, 2>, <1, 2, 3> } inside_vector <0, 0, 1> pigment { P } }",
        ),
        (
            "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { N",
            "<3*I, 3*I+1, 3*I+2>, 7",
            "} normal_indices { 1, <0, 0, 0> } }",
        ),
    ];
    for (head, body, tail) in cases {
        for n in [0, 1, 3, 20] {
            let unit = looped_unit(head, body, n, tail);
            let whole = parse_unit_with(&unit, Rule::unit_statement, |top, lower| {
                lower.node(inner(top).next().expect("a statement"))
            })
            .unwrap_or_else(|e| panic!("{head} … ×{n}: {}", e.message));
            let mut items = incremental::read(&unit).unwrap_or_else(|| panic!("{head} … ×{n}"));
            incremental::unshare(&mut items);
            assert_eq!(format!("{items:?}"), format!("{whole:?}"), "{head} … ×{n}");
        }
    }
    // A union's members read again share the node first read (a union a loop filled holds
    // one node per place in the loop's body, not one per member).
    let unit = looped_unit("union {", "sphere { <I, 0, 0>, R }", 50, "}");
    let union = incremental::read(&unit).expect("read item by item");
    let shared: Vec<_> = union.children.iter().filter_map(Node::again).collect();
    assert_eq!(shared.len(), 50);
    // (The last is read on its own: a different token follows it.)
    let first = std::ptr::from_ref(shared[0].0);
    assert!(shared[..49].iter().all(|(n, _)| std::ptr::eq(*n, first)));
    // (Each member's words are bound three slots after the one before's: `sphere`, `I`, `R`.)
    let shifts: Vec<u32> = shared[..49].iter().map(|(_, by)| *by).collect();
    assert_eq!(shifts, (0..49).map(|i| 3 * i).collect::<Vec<u32>>());
    // Out of order or wrong: not read item by item (the whole parse reports it).
    for text in [
        "mesh2 { face_indices { 1, <0, 1, 2> } vertex_vectors { 1, 0 } }",
        "mesh2 { vertex_vectors { 1, 0 } }",
        "union { sphere { 0, 1 } sphere { } }",
        "union { sphere { 0, 1 } } sphere { 0, 1 }",
    ] {
        assert!(
            incremental::read(&looped_unit(text, "", 0, "")).is_none(),
            "{text}"
        );
    }
}

#[test]
fn a_reserved_word_before_a_parenthesis_is_not_called() {
    // `rotate (40)*x` after a cylinder's radius is a rotation (a blob component's strength
    // may follow its radius without a comma, so a call here would be read as a fourth value).
    for (text, values) in [
        ("cylinder { 0, y, 1 rotate (40)*x }", 3),
        ("sphere { 0, 1 scale (2) }", 2),
    ] {
        let nodes = parse(text).expect("parses");
        assert_eq!(nodes[0].args.len(), values, "{text}");
        assert_eq!(nodes[0].children.len(), 1, "{text}");
    }
}

/// Every node in `node`'s tree whose view is malformed (none, for what the grammar makes).
fn malformed(node: &Node, out: &mut Vec<String>) {
    if matches!(node.view(), View::Malformed) {
        out.push(format!(
            "{:?} `{}` ({} values)",
            node.kind,
            node.word,
            node.args.len()
        ));
    }
    for c in &node.children {
        malformed(c, out);
    }
    for e in &node.args {
        if let ExprKind::Item(n) = &e.kind {
            malformed(n, out);
        }
    }
}

#[test]
fn view_of_every_node_the_grammar_makes_is_well_formed() {
    // Each construct with values, in its forms (optional values given and left out).
    let statements = [
        "camera { perspective location <0, 1, -3> look_at 0 direction z up y right x sky y angle 60 }",
        "camera { spherical angle 360, 180 aperture 0.5 blur_samples 4, 16 focal_point 0 confidence 0.9 }",
        "camera { cylinder 2 }",
        "camera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } } }",
        "camera { mesh_camera { 1 3 0.5 mesh { triangle { 0, x, y } } smooth } }",
        "light_source { <1, 2, 3>, rgb 1 spotlight point_at 0 radius 10 falloff 20 tightness 5 \
         fade_distance 4 fade_power 2 area_light x, y, 4, 4 adaptive 1 jitter area_illumination on \
         looks_like { sphere { 0, 1 } } }",
        "light_source { <1, 2, 3> area_illumination }",
        "background { rgb 1 }",
        "fog { distance 10 fog_type 2 fog_alt 1 fog_offset 0.5 turb_depth 0.3 rgb 0.5 up y }",
        "global_settings { assumed_gamma 1 max_trace_level 5 adc_bailout 0.01 ambient_light 1 \
         irid_wavelength rgb <0.25, 0.18, 0.14> max_intersections 64 number_of_waves 10 }",
        "sphere { 0, 1 hollow on no_shadow }",
        "blob { threshold 0.5 component 1, 1, 0 sphere { 0, 1, 2 } cylinder { 0, y, 1, strength 2 } }",
        "plane { y, -1 }",
        "box { -1, 1 }",
        "cylinder { 0, y, 1 open }",
        "cone { 0, 1, y, 0 }",
        "disc { 0, y, 1 }",
        "disc { 0, y, 1, 0.5 }",
        "torus { 1, 0.25 }",
        "triangle { 0, x, y uv_vectors <0,0>, <1,0>, <0,1> }",
        "smooth_triangle { 0, y, x, y, z, y }",
        "mesh { triangle { 0, x, y } inside_vector z }",
        "mesh2 { vertex_vectors { 3, 0, x, y } normal_vectors { 1, y } uv_vectors { 1, <0, 0> } \
         texture_list { 1, texture { pigment { rgb 1 } } } face_indices { 1, <0, 1, 2>, 0 } \
         normal_indices { 1, <0, 0, 0> } uv_indices { 1, <0, 0, 0> } inside_vector z }",
        "isosurface { function { x + y } contained_by { box { -1, 1 } } threshold 0 max_gradient 2 open }",
        "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> \
         contained_by { sphere { 0, 2 } } precompute 10 x, y, z accuracy 0.01 }",
        "object { Thing translate x rotate y scale 2 matrix <1,0,0, 0,1,0, 0,0,1, 0,0,0> \
         transform { translate x inverse } }",
        "height_field { function 20, 20 { x * z } }",
        "quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }",
        "sphere { 0, 1 texture { pigment { gradient y color_map { [0 rgb 0] [0.2, 0.4 rgb 1 rgb 0] } \
         turbulence 0.5 frequency 2 poly_wave warp { repeat x offset y } } \
         normal { bumps 0.5 bump_size 2 slope_map { [0 <0, 1>] } } \
         finish { ambient 0.1 emission 0 diffuse 0.6, 0.2 brilliance 1 phong 0.5 phong_size 40 \
         specular 0.2 roughness 0.05 metallic crand 0.1 irid { 0.3 thickness 0.2 turbulence 0.1 } \
         reflection { 0.1, 0.5 falloff 2 exponent 1 fresnel metallic 0.5 } reflection_exponent 1 \
         conserve_energy } } }",
        "sphere { 0, 1 pigment { julia <0.3, 0.5>, 30 pigment_map { [0 rgb 1] [1 P] } } }",
        "sphere { 0, 1 pigment { magnet 1 mandel 20 interior 1, 1 } }",
        "sphere { 0, 1 pigment { object { box { 0, 1 } rgb 0, rgb 1 } } }",
        "sphere { 0, 1 pigment { slope { y, 0, 0.5 altitude y, 0, 1 } } }",
        "sphere { 0, 1 pigment { image_map { png \"a.png\" gamma 2.2 map_type 1 interpolate 2 once \
         filter all 0.5 transmit 1, 0.5 } } }",
        "sphere { 0, 1 pigment { image_map { png \"a.png\" gamma srgb } } }",
        "sphere { 0, 1 interior { ior 1.5 fade_distance 1 fade_power 2 fade_color rgb 1 } }",
        "sphere { 0, 1 texture { gradient x texture_map { [0 T1] [1 T2] } } }",
        "sky_sphere { pigment { rgb 1 } emission rgb 1 }",
    ];
    let mut bad = Vec::new();
    for text in statements {
        let node = parse(text)
            .unwrap_or_else(|e| panic!("{text}: {}", e.message))
            .remove(0);
        malformed(&node, &mut bad);
    }
    // Directive heads.
    for (text, head) in [
        ("(I, 0, 10, 2)", Head::For),
        ("(I, 0, 10)", Head::For),
        ("(1, 2)", Head::Range),
        ("(Name)", Head::Ifdef),
        ("(A[1])", Head::Ifdef),
        ("M(A, B)", Head::Macro),
        ("F \"file.txt\" write", Head::Fopen),
        ("(F, A, B[2])", Head::Read),
        ("(F, \"text\", uint8 3)", Head::Write),
        ("deprecated once \"old\" X[1][2] =", Head::Declare),
        ("X =", Head::Declare),
    ] {
        let node = parse_head(&Unit::from_file_text(text, FileId(0), 0), head)
            .unwrap_or_else(|e| panic!("{text}: {}", e.message));
        malformed(&node, &mut bad);
    }
    assert!(bad.is_empty(), "{bad:#?}");
}
