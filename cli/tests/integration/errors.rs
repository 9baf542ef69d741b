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

#[test]
fn a_cancelled_load_stops_with_a_located_error() {
    let text = "#declare I = 0;\n#while (I < 1e9)\n  #declare I = I + 1;\n#end\n";
    let options = trace::LoadOptions::default();
    let cancel = options.cancel.clone();
    let stopper = std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_millis(50));
        cancel.cancel();
    });
    let start = std::time::Instant::now();
    let message = trace::load_str(std::path::Path::new("loop.rt"), text.into(), &options)
        .expect_err("cancelled")
        .to_string();
    stopper.join().unwrap();
    assert!(
        message.contains("cancelled") && message.contains("-->"),
        "{message}"
    );
    // (A billion passes would take minutes: the load stopped soon after the cancel.)
    assert!(start.elapsed() < std::time::Duration::from_secs(20));
}

#[test]
fn a_load_lists_every_file_it_read_even_when_it_fails() {
    let dir = std::env::temp_dir().join(format!("trace-files-read-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("a.inc"), "#declare A = 1;\n").unwrap();
    std::fs::write(dir.join("b.inc"), "#declare B = 2;\n").unwrap();
    let scene = dir.join("scene.rt");
    let names = |files: &[std::path::PathBuf]| -> Vec<String> {
        files
            .iter()
            .map(|f| f.file_name().unwrap().to_string_lossy().into_owned())
            .collect()
    };
    std::fs::write(
        &scene,
        "#include \"a.inc\"\n#include \"b.inc\"\n#include \"a.inc\"\n#if (file_exists(\"c.inc\")) #end\nsphere { 0, A }\n",
    )
    .unwrap();
    let loaded = trace::load(&scene, &trace::LoadOptions::default()).unwrap();
    assert_eq!(names(&loaded.files), ["scene.rt", "a.inc", "b.inc"]);
    assert_eq!(
        loaded.missing,
        [dir.join("c.inc")],
        "looked for in the scene's folder"
    );
    std::fs::write(&scene, "#include \"b.inc\"\nsphere { 0, Nothing }\n").unwrap();
    match trace::load(&scene, &trace::LoadOptions::default()) {
        Err(trace::Error::Scene(e)) => assert_eq!(names(&e.files), ["scene.rt", "b.inc"]),
        other => panic!("{other:?}"),
    }
    let _ = std::fs::remove_dir_all(dir);
}
