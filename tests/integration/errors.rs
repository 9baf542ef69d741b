//! Every bad scene in tests/scenes/err gives a located, readable message (snapshotted).

#[test]
fn bad_scenes_give_located_messages() {
    insta::glob!("../scenes/err", "*.rt", |path| {
        let text = std::fs::read_to_string(path).expect("readable");
        let name = std::path::Path::new("scenes").join(path.file_name().expect("file name"));
        // (Data files such as meshes are found through the include path.)
        let options = trace::LoadOptions {
            width: 320,
            height: 240,
            include_paths: vec![path.parent().expect("folder").to_path_buf()],
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
