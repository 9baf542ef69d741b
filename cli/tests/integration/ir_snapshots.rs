//! Snapshots of the IR that every example and every accepted test scene evaluates to.

use std::path::Path;

fn snapshot_ir(path: &Path) {
    // Scenes that need POV-Ray's include files (its fonts) are checked by the golden tests
    // only: their IR would depend on what is installed.
    if std::fs::read_to_string(path)
        .is_ok_and(|t| t.contains("Needs POV-Ray's include files installed."))
    {
        return;
    }
    let options = trace::LoadOptions {
        width: 320,
        height: 240,
        ..Default::default()
    };
    let loaded = trace::load(path, &options).unwrap_or_else(|e| panic!("{e}"));
    insta::assert_debug_snapshot!(loaded.scene);
    // The IR is data: the same text read again gives an equal scene (functions, patterns of
    // functions, pigment functions and object patterns included), which is what lets
    // `trace watch` keep what a save did not change.
    let again = trace::load(path, &options).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        loaded.scene == again.scene,
        "{}: two reads of one text differ",
        path.display()
    );
    if !loaded.debug_output.is_empty() {
        // What `#debug` printed (string functions are checked against POV-Ray's output).
        insta::assert_snapshot!("debug_output", loaded.debug_output);
    }
}

#[test]
fn examples_evaluate_to_stable_ir() {
    insta::glob!("../../../examples", "*.rt", snapshot_ir);
}

#[test]
fn accepted_scenes_evaluate_to_stable_ir() {
    insta::glob!("../../../tests/scenes/ok", "*.rt", snapshot_ir);
}
