//! The command line: `--version`, and `--help` naming every setting the service reads.
#![allow(clippy::unwrap_used)]

use std::process::Command;

fn run(arg: &str) -> (bool, String) {
    let output = Command::new(env!("CARGO_BIN_EXE_thrustline"))
        .arg(arg)
        .output()
        .unwrap();
    (
        output.status.success(),
        String::from_utf8(output.stdout).unwrap(),
    )
}

#[test]
fn version_is_the_package_version() {
    let (ok, out) = run("--version");
    assert!(ok);
    assert_eq!(
        out.trim(),
        format!("thrustline {}", env!("CARGO_PKG_VERSION"))
    );
}

#[test]
fn help_lists_every_environment_setting_the_service_reads() {
    let (ok, help) = run("--help");
    assert!(ok);
    // Every THRUSTLINE_* name that src/config.rs reads must be in the help.
    let config = include_str!("../src/config.rs");
    let names: Vec<&str> = config
        .split('"')
        .filter(|s| s.starts_with("THRUSTLINE_") && !s.contains(' '))
        .collect();
    assert!(names.len() >= 7, "{names:?}");
    for name in names {
        assert!(help.contains(name), "--help does not mention {name}");
    }
    assert!(help.contains("RUST_LOG"));
}
