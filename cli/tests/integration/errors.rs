//! Every bad scene in tests/scenes/err gives a located, readable message (snapshotted).

#[test]
fn bad_scenes_give_located_messages() {
    insta::glob!("../../../tests/scenes/err", "*.rt", |path| {
        let text = std::fs::read_to_string(path).expect("readable");
        let name = std::path::Path::new("scenes").join(path.file_name().expect("file name"));
        // (Data files such as meshes are found through the include path, given relative to
        // the package root (cli/), where cargo runs tests, so that messages do not depend on it.)
        let options = trace::LoadOptions {
            width: 320,
            height: 240,
            include_paths: vec![std::path::PathBuf::from("../tests/scenes/err")],
            // (A small evaluation budget keeps the endless-loop scenes quick.)
            max_steps: 100_000,
            ..Default::default()
        };
        let message = match trace::load_str(&name, text, &options) {
            Ok(_) => panic!("{} should not load", path.display()),
            Err(e) => e.to_string(),
        };
        assert!(
            message.contains("-->") && message.contains('^'),
            "no location in:\n{message}"
        );
        insta::assert_snapshot!(message);
    });
}

#[test]
fn deep_nesting_is_an_error_not_a_stack_overflow() {
    let load = |text: String| {
        trace::load_str(
            std::path::Path::new("deep.rt"),
            text,
            &trace::LoadOptions::default(),
        )
    };
    let n = trace::MAX_NESTING - 10;
    let parens = format!("sphere {{ 0, {}1{} }}", "(".repeat(n), ")".repeat(n));
    let vectors = format!("#declare V = {}1{};", "<".repeat(n), ">".repeat(n));
    assert!(load(parens).is_ok(), "{n} nested parentheses load");
    assert!(
        load(vectors).is_err(),
        "a vector of one component is an error, not a crash"
    );
    for (open, close) in [("(", ")"), ("<", ">"), ("/*", "*/"), ("{", "}")] {
        let n = 100_000;
        let text = format!("sphere {{ 0, {}1{} }}", open.repeat(n), close.repeat(n));
        let message = load(text).expect_err("too deep").to_string();
        assert!(message.contains("nested more than"), "{open}: {message}");
    }
}
