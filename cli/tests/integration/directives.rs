//! Directives that work on tokens, as POV-Ray's reader executes them (src/eval/lang/reader.rs):
//! a scene written with them is the scene written without them. (Their pictures against POV-Ray's: examples/token_directives.rt.)

use crate::load_text;

/// The scene `text` makes, as text (every resolved fact of it).
fn scene(text: &str) -> String {
    format!("{:?}", load_text(text, 32, 24))
}

const SET: &str = "camera { location <0, 1, -6> look_at 0 } light_source { <4, 8, -6> rgb 1 }\n";

fn same(with: &str, without: &str) {
    let (a, b) = (
        scene(&format!("{SET}{with}")),
        scene(&format!("{SET}{without}")),
    );
    assert!(a == b, "with directives:\n{with}\nwithout:\n{without}");
}

#[test]
fn a_value_is_chosen_where_it_stands() {
    for c in [0, 1] {
        let with = format!(
            "#declare C = {c};
             sphere {{ #if (C) 0 #else x #end, #if (C) 1 #elseif (1) 2 #else 3 #end
               pigment {{ rgb #if (C) <1, 0, 0> #else <0, 1, #if (C) 0 #else 1 #end> #end }}
               translate #if (C) y #else -y #end }}"
        );
        let without = if c == 1 {
            "sphere { 0, 1 pigment { rgb <1, 0, 0> } translate y }"
        } else {
            "sphere { x, 2 pigment { rgb <0, 1, 1> } translate -y }"
        };
        same(&with, without);
    }
}

#[test]
fn a_value_in_a_loop_is_chosen_at_each_pass() {
    same(
        "union { #for (I, 0, 3) sphere { <I, 0, 0>, #if (I < 2) 0.25 #else 0.5 #end } #end }
         #declare J = 0;
         #while (J < 2) box { 0, #if (J) 1 #else 2 #end #ifdef (Nothing) translate x #end } #declare J = J + 1; #end",
        "union { sphere { <0, 0, 0>, 0.25 } sphere { <1, 0, 0>, 0.25 } sphere { <2, 0, 0>, 0.5 } sphere { <3, 0, 0>, 0.5 } }
         box { 0, 2 } box { 0, 1 }",
    );
}

#[test]
fn a_value_not_chosen_is_not_evaluated() {
    // Neither the undeclared name nor the random number of the branch not taken is read:
    // the next number drawn is the first of the stream, as in POV-Ray.
    same(
        "#declare S = seed(7);
         sphere { 0, #if (1) 1 #else Undeclared + rand(S) #end }
         sphere { 0, rand(S) }",
        "#declare S = seed(7);
         sphere { 0, 1 }
         sphere { 0, rand(S) }",
    );
}

#[test]
fn a_branch_may_open_a_block_that_text_after_it_closes() {
    // As a macro of a real scene makes its pieces (BenoitPro's damier.pov): the branch taken
    // opens the union, the text after the #end fills and closes it.
    let with = "
        #macro Piece(Kind, Where)
          #if (Kind = 1)
            union { cone { 0, 0.1, y, 0 }
          #elseif (Kind = 2)
            union { torus { 0.3, 0.05 }
          #else
            union { box { -1, 1 }
          #end
            sphere { y, 0.4 }
            #if (Kind = 1) pigment { rgb x } #else pigment { rgb 1 } #end
            translate Where }
        #end
        Piece(1, x) Piece(2, -x) Piece(3, z)
        #declare UseMerge = 0;
        #if (UseMerge) merge { #else union { #end sphere { 0, 1 } sphere { x, 1 } }
        #ifndef (Undeclared) union { #else merge { #end box { 0, 1 } }";
    let without = "
        union { cone { 0, 0.1, y, 0 } sphere { y, 0.4 } pigment { rgb x } translate x }
        union { torus { 0.3, 0.05 } sphere { y, 0.4 } pigment { rgb 1 } translate -x }
        union { box { -1, 1 } sphere { y, 0.4 } pigment { rgb 1 } translate z }
        union { sphere { 0, 1 } sphere { x, 1 } }
        union { box { 0, 1 } }";
    same(with, without);
}

#[test]
fn a_condition_sees_the_declarations_before_it() {
    same(
        "#declare A = 1;
         #if (A) union { #else union { sphere { 0, 9 } #end sphere { 0, 1 } }
         #declare A = 0;
         #if (A) union { #else union { sphere { 0, 9 } #end sphere { 0, 1 } }
         sphere { 0, #if (A) 3 #else 4 #end }",
        "union { sphere { 0, 1 } }
         union { sphere { 0, 9 } sphere { 0, 1 } }
         sphere { 0, 4 }",
    );
}

#[test]
fn a_big_file_parsed_ahead_reads_them_as_one_thread_does() {
    // Over the size where helper threads parse ahead; the statement the grammar cannot read
    // whole comes late, inside a chunk a helper parsed.
    let mut body = String::new();
    for i in 0..6000 {
        body.push_str(&format!(
            "sphere {{ <{i}, 0, 0>, 0.5 pigment {{ rgb {} }} }}\n",
            i % 7
        ));
    }
    // (Early, too: the grammar goes back to reading the file whole after it, helpers parsing
    // ahead from there.)
    let token =
        "#if (U) union { box { 0, 1 } #else union { sphere { x, 1 } #end sphere { 0, 1 } }\n";
    let plain = "union { sphere { x, 1 } sphere { 0, 1 } }\n";
    let with = format!("#declare U = 0;\n{token}{body}{token}{body}");
    let without = format!("{plain}{body}{plain}{body}");
    assert!(with.len() > 1 << 19);
    let load = crate::parsing::load_with_threads;
    let expected = load(&without, 1);
    assert!(load(&with, 1) == expected);
    assert!(load(&with, 4) == expected);
}

#[test]
fn errors_still_point_at_the_culprit() {
    let err = |text: &str| {
        trace::load_str(
            std::path::Path::new("e.rt"),
            format!("{SET}{text}"),
            &Default::default(),
        )
        .expect_err("an error")
        .to_string()
    };
    // A syntax error in the text a branch leaves: where it stands.
    let e = err("#declare A = 1;\n#if (A) union { #else merge { #end sphere { 0, 1 ] } }");
    assert!(e.contains("e.rt:3:"), "{e}");
    // In a branch not taken: none (POV-Ray passes over its tokens).
    scene(&format!(
        "{SET}#if (0) sphere {{ 0, ] }} union {{ #else union {{ #end sphere {{ 0, 1 }} }}"
    ));
    // An unsupported construct a branch chooses is named.
    let e = err("#if (1) merge { #else union { #end sphere { 0, 1 } }");
    assert!(e.contains("merge"), "{e}");
}

#[test]
fn deeply_nested_directives_are_read_in_linear_time() {
    // The reader keeps its open blocks in a list, not on the stack: 100,000 nested `#if (1)`
    // (a fuzzed input that once ran for minutes) read in a fraction of a second, and without
    // their `#end`s give a located error just as fast; nested loops likewise.
    let n = 100_000;
    let load = |text: String| {
        let start = std::time::Instant::now();
        let result = trace::load_str(std::path::Path::new("deep.rt"), text, &Default::default());
        (result, start.elapsed().as_secs_f64())
    };
    let (ok, seconds) = load(format!(
        "{SET}{}sphere {{ 0, 1 }}\n{}",
        "#if (1)\n".repeat(n),
        "#end\n".repeat(n)
    ));
    assert_eq!(ok.expect("loads").scene.objects.len(), 1);
    assert!(seconds < 20.0, "{seconds} s");
    let (err, seconds) = load(format!("{SET}{}", "#if (1)\n".repeat(n)));
    let err = err.expect_err("no #end").to_string();
    assert!(
        err.contains("has no #end") && err.contains("deep.rt:"),
        "{err}"
    );
    assert!(seconds < 20.0, "{seconds} s");
    let m = 5000;
    let (err, seconds) = load(format!(
        "{SET}#declare I = 0;\n{}sphere {{ #if (1) 0 #else ] #end, ] }}\n#declare I = 1;\n{}",
        "#while (I < 1)\n".repeat(m),
        "#end\n".repeat(m)
    ));
    assert!(
        err.expect_err("a syntax error")
            .to_string()
            .contains("deep.rt:")
    );
    assert!(seconds < 20.0, "{seconds} s");
}

#[test]
fn a_loops_plain_directives_mean_what_the_token_reader_makes_of_them() {
    // Plain `#declare`s, `#local`s and conditions in a loop are read from a kept parse
    // (src/eval/lang/reader/quick.rs); a macro named in one sends it back to the token reader.
    same(
        "#macro Twice(A) (2*A) #end
         #macro Lim() 4 #end
         #declare V = array[3][2];
         #declare I = 0;
         #while (I < 3)
           #local J = 0;
           #while (J < 2)
             #declare V[I][J] = I*10 + J; // a subscripted name
             #local J = J + 1;
           #end
           #declare I = I + 1;
         #end
         #declare K = 0;
         #declare S = 0;
         #while (K < Lim())
           #declare S = S + Twice(K);
           #declare K = K + 1;
         #end
         #declare P = <0, 0, 0>;
         #for (N, 1, 3)
           #declare P = P + <N, -N/2, 0>*(1 + (N = 2));
         #end
         sphere { <V[2][1], V[1][0], S>, 1 translate P }",
        "sphere { <21, 10, 12>, 1 translate <8, -4, 0> }",
    );
}

#[test]
fn a_loop_making_a_big_unions_items_is_read_item_by_item() {
    // 20,000 spheres made by a loop inside a union's braces are one unit for the grammar:
    // read item by item (src/syntax/incremental.rs), each sphere's text parsed once.
    let text = format!(
        "{SET}union {{ #for (I, 0, 19999) sphere {{ <mod(I, 100), div(I, 100), 0>, 0.4 }} #end }}"
    );
    let start = std::time::Instant::now();
    let scene = trace::load_str(std::path::Path::new("big.rt"), text, &Default::default())
        .expect("loads")
        .scene;
    let seconds = start.elapsed().as_secs_f64();
    // (A union's members are the scene's objects, each its own.)
    assert_eq!(scene.objects.len(), 20000, "{:?}", scene.objects.len());
    assert!(seconds < 20.0, "{seconds} s");
}

#[test]
fn a_macros_last_declaration_of_a_parameter_changes_the_callers_name() {
    // (POV-Ray's macro2.pov: the `#declare` ends the macro's body, and the name it binds is
    // still the parameter, which stands for the caller's `T`.)
    same(
        "#macro Turn(S, D) #declare S = object { S rotate y*D } #end
         #declare T = box { 0, 1 }
         Turn(T, 90)
         object { T pigment { rgb 1 } }",
        "object { box { 0, 1 rotate y*90 } pigment { rgb 1 } }",
    );
}

#[test]
fn a_loops_plain_statements_mean_what_the_token_reader_makes_of_them() {
    // A loop body's plain statement is read from a kept parse (src/eval/lang/reader/quick.rs),
    // its names bound at each pass; a macro named in it sends it to the token reader.
    same(
        "#macro Half() 0.5 #end
         #declare R = 0.25;
         #for (I, 0, 2)
           sphere { <I, 0, 0>, R pigment { rgb <I/2, 0, 1> } }
           #declare R = R + 0.25;
           cylinder { <I, 1, 0>, <I, 2, 0>, Half() }
         #end",
        "sphere { <0, 0, 0>, 0.25 pigment { rgb <0, 0, 1> } }
         cylinder { <0, 1, 0>, <0, 2, 0>, 0.5 }
         sphere { <1, 0, 0>, 0.5 pigment { rgb <0.5, 0, 1> } }
         cylinder { <1, 1, 0>, <1, 2, 0>, 0.5 }
         sphere { <2, 0, 0>, 0.75 pigment { rgb <1, 0, 1> } }
         cylinder { <2, 1, 0>, <2, 2, 0>, 0.5 }",
    );
}
