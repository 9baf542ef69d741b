//! The farm recipes of docs/farm.md, run on this machine: GNU parallel on 2 workers (tiles
//! merged, frames as subsets) and the Slurm and Kubernetes job scripts with stand-ins. They
//! need GNU parallel (and PyYAML for the Kubernetes manifests): without them the test says
//! so and passes, unless TRACE_REQUIRE_FARM=1 (CI installs them and sets it).

use std::process::Command;

fn have(program: &str, args: &[&str]) -> bool {
    Command::new(program)
        .args(args)
        .output()
        .is_ok_and(|o| o.status.success())
}

fn script(name: &str) {
    let path = crate::root().join("scripts/farm").join(name);
    let out = Command::new("bash")
        .arg(&path)
        .arg(env!("CARGO_BIN_EXE_trace"))
        .output()
        .expect("bash runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.status.success(), "{name} failed:\n{text}");
    assert!(text.contains("all checks passed"), "{name}:\n{text}");
}

#[test]
fn the_farm_recipes_give_the_single_render() {
    let required = std::env::var_os("TRACE_REQUIRE_FARM").is_some_and(|v| v == "1");
    let parallel = have("parallel", &["--version"]);
    let yaml = have("python3", &["-c", "import yaml"]);
    if !(parallel && yaml) {
        assert!(
            !required,
            "TRACE_REQUIRE_FARM=1 but GNU parallel or PyYAML is missing"
        );
        eprintln!(
            "farm recipes skipped: install GNU parallel and PyYAML (python3-yaml) to run them"
        );
        return;
    }
    script("parallel-test.sh");
    script("batch-test.sh");
}
