//! Requests one typo away from sensible ones, each run as a user would run it but under
//! an address-space limit of 2 GB and a time limit of 20 s: each must end with status 1 or
//! 2 and one line saying why, write no output file, and never abort, panic or run out of
//! memory.
#![cfg(target_os = "linux")]

use opencrg_core::synth::RoadSpec;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("opencrg-cli-{}-absurd", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A 120 m curved road, a line of points 200 m long and a small point cloud.
fn inputs(d: &Path) {
    let road = RoadSpec::straight(120.0, 6.0, 0.5, 0.25)
        .with_heading(|u| 0.2 + 0.004 * u)
        .with_elevation(|u, v| 0.005 * (u * 0.4).sin() * (v + 3.0));
    std::fs::write(d.join("road.crg"), road.to_crg()).unwrap();
    let line: String = (0..=100).map(|i| format!("{},{}\n", i as f64 * 2.0, 20.0 * (i as f64 / 20.0).sin())).collect();
    std::fs::write(d.join("line.csv"), format!("x,y\n{line}")).unwrap();
    let cloud: String = (0..4000)
        .map(|i| {
            let (x, y) = ((i % 200) as f64 * 0.5, (i / 200) as f64 * 0.3 - 3.0);
            format!("{x} {y} {}\n", 0.01 * x.sin())
        })
        .collect();
    std::fs::write(d.join("cloud.xyz"), &cloud).unwrap();
    // The same cloud with two stray points 6,000 km away.
    std::fs::write(d.join("stray.xyz"), format!("{cloud}6000000 0 0\n20 -6000000 0\n")).unwrap();
    let ply = "ply\nformat binary_little_endian 1.0\nelement vertex 99999999999999999\n\
               property double x\nproperty double y\nproperty double z\nend_header\n";
    std::fs::write(d.join("claims.ply"), ply).unwrap();
}

/// Runs `opencrg args` in `d` under 2 GB of address space; its status, stderr and time.
fn run(d: &Path, args: &[&str]) -> (Option<i32>, String, Duration) {
    let started = Instant::now();
    let out = Command::new("sh")
        .current_dir(d)
        .arg("-c")
        .arg("ulimit -v 2000000 && exec timeout 20 \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_opencrg"))
        .args(args)
        .output()
        .unwrap();
    (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned(), started.elapsed())
}

#[test]
fn absurd_requests_are_refused_in_one_line() {
    let d = dir();
    inputs(&d);
    let huge_formula = format!("{}u{}", "(".repeat(3000), ")".repeat(3000));
    let cases: Vec<Vec<&str>> = vec![
        vec!["resample", "road.crg", "out.crg", "--u-inc", "1e-9"],
        vec!["resample", "road.crg", "out.crg", "--u-inc", "1e-7", "--v-inc", "1e-7"],
        vec!["resample", "road.crg", "out.crg", "--u-inc", "1e-7", "--v-inc", "1e-7", "--max-memory", "1T"],
        vec!["resample", "road.crg", "out.crg", "--u-inc", "-1"],
        vec!["resample", "road.crg", "out.crg", "--v-inc", "nan"],
        vec!["resample", "road.crg", "out.crg", "--max-memory", "1k"],
        vec!["resample", "road.crg", "out.crg", "--max-memory", "-5G"],
        vec!["generate", "out.crg", "--refline", "line.csv", "--width", "3", "--u-inc", "1e-9", "--v-inc", "0.1"],
        vec!["generate", "out.crg", "--refline", "line.csv", "--width", "3", "--u-inc", "0.1", "--v-inc", "1e-11"],
        vec!["generate", "out.crg", "--refline", "line.csv", "--width", "3e9", "--u-inc", "0.1", "--v-inc", "0.1"],
        vec!["generate", "out.crg", "--refline", "line.csv", "--width", "-3", "--u-inc", "0.1", "--v-inc", "0.1"],
        vec![
            "generate",
            "out.crg",
            "--refline",
            "line.csv",
            "--width",
            "3",
            "--u-inc",
            "0.1",
            "--v-inc",
            "0.1",
            "--surface",
            &huge_formula,
        ],
        vec!["import", "cloud.xyz", "out.crg", "--u-inc", "1e-9", "--v-inc", "0.1"],
        vec!["import", "cloud.xyz", "out.crg", "--u-inc", "0.1", "--v-inc", "0.1", "--width", "1e12"],
        vec!["import", "claims.ply", "out.crg", "--u-inc", "0.1", "--v-inc", "0.1"],
        vec!["import", "stray.xyz", "out.crg", "--u-inc", "1", "--v-inc", "1"],
        vec!["import", "cloud.xyz", "out.crg", "--u-inc", "1", "--v-inc", "1", "--crop", "0:1,5:6"],
        vec!["import", "cloud.xyz", "out.crg", "--u-inc", "1", "--v-inc", "1", "--crop", "0:100"],
        vec!["filter", "road.crg", "out.crg", "--median", "1000001"],
        vec!["filter", "road.crg", "out.crg", "--median", "-3"],
        vec!["filter", "road.crg", "out.crg", "--gauss", "1e9"],
        vec!["roughness", "road.crg", "--segment", "1e-300"],
        vec!["roughness", "road.crg", "--segment", "-1"],
        vec!["roughness", "road.crg", "--track", "1e300"],
        vec!["render", "road.crg", "out.png", "--size", "4000000000"],
        vec!["render", "road.crg", "out.png", "--profile", "u=1e300"],
        vec!["export", "road.crg", "out.glb", "--max-error", "-1"],
        vec!["export", "road.crg", "out.glb", "--max-memory", "10k"],
        vec!["export", "road.crg", "out.glb", "--max-error", "0.001", "--max-memory", "10k"],
        vec!["view", "road.crg", "out.html", "--max-memory", "10k"],
        vec!["cut", "road.crg", "out.crg", "--u", "1e300:2e300"],
    ];
    for args in &cases {
        for f in ["out.crg", "out.png", "out.glb", "out.html"] {
            let _ = std::fs::remove_file(d.join(f));
        }
        let (status, stderr, took) = run(&d, args);
        let shown = format!("opencrg {}", args.join(" ").chars().take(120).collect::<String>());
        assert!(matches!(status, Some(1) | Some(2)), "{shown}: status {status:?}, stderr {stderr}");
        assert!(!stderr.trim().is_empty(), "{shown}: no message");
        for bad in ["panicked", "internal error", "memory allocation", "overflow"] {
            assert!(!stderr.contains(bad), "{shown}: {stderr}");
        }
        assert!(took < Duration::from_secs(20), "{shown}: {took:?}");
        for f in ["out.crg", "out.png", "out.glb", "out.html"] {
            assert!(!d.join(f).exists(), "{shown}: wrote {f}");
        }
    }
    // The same limits let sensible requests through.
    let (status, stderr, _) = run(&d, &["resample", "road.crg", "out.crg", "--u-inc", "0.1", "--max-memory", "100M"]);
    assert_eq!(status, Some(0), "{stderr}");
    let _ = std::fs::remove_dir_all(&d);
}
