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
fn serve_help_answers_the_help_and_succeeds() {
    // Regression: `serve --help` exited 2 as an unknown argument.
    let output = Command::new(env!("CARGO_BIN_EXE_thrustline"))
        .args(["serve", "--help"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    let help = String::from_utf8(output.stdout).unwrap();
    assert!(
        help.contains("thrustline serve [--addr HOST:PORT]"),
        "{help}"
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

#[test]
fn settings_that_are_mistakes_stop_the_start_with_a_message() {
    // Issue 18, item 7: an empty token used to leave the service open silently, and a timeout
    // of 1e19 s panicked after "listening". Both now refuse to start, saying why.
    for (name, value, says) in [
        ("THRUSTLINE_TOKEN", "", "THRUSTLINE_TOKEN"),
        ("THRUSTLINE_SOLVE_TIMEOUT_SECS", "1e19", "86400"),
        ("THRUSTLINE_DRAIN_SECS", "-1", "THRUSTLINE_DRAIN_SECS"),
    ] {
        let output = Command::new(env!("CARGO_BIN_EXE_thrustline"))
            .args(["serve", "--addr", "127.0.0.1:0"])
            .env(name, value)
            .output()
            .unwrap();
        assert!(!output.status.success(), "{name}={value:?} started");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.contains(says), "{name}: {stderr}");
        assert!(!stderr.contains("panicked"), "{name}: {stderr}");
    }
}

#[test]
fn the_port_actually_listened_on_is_written_for_health_checks() {
    // Issue 38: the container's health check followed THRUSTLINE_ADDR only, so `serve --addr
    // 0.0.0.0:9000` turned unhealthy. The service writes the port it listens on.
    let dir = std::env::temp_dir().join(format!("thrustline-port-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("port");
    let mut child = Command::new(env!("CARGO_BIN_EXE_thrustline"))
        .args(["serve", "--addr", "127.0.0.1:0"])
        .env("THRUSTLINE_PORT_FILE", &file)
        .env("THRUSTLINE_ADDR", "127.0.0.1:1")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let mut port = None;
    for _ in 0..100 {
        if let Ok(text) = std::fs::read_to_string(&file) {
            port = text.trim().parse::<u16>().ok();
            if port.is_some() {
                break;
            }
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    let port = port.expect("the port file was written");
    assert_ne!(port, 0);
    let healthy = std::net::TcpStream::connect(("127.0.0.1", port)).and_then(|mut s| {
        use std::io::{Read, Write};
        s.write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")?;
        let mut answer = String::new();
        s.read_to_string(&mut answer)?;
        Ok(answer)
    });
    let _ = child.kill();
    let _ = child.wait();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(healthy.unwrap().starts_with("HTTP/1.1 200"));
}
