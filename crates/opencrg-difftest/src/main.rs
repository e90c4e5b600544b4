//! `crg-difftest`: the differential tester.
//!
//! Generates random roads (every data format and header variant the library reads),
//! random settings and query patterns, runs the same C client built against two
//! libraries of the classic OpenCRG C API on each, and reports where their answers
//! differ, call by call.
//!
//! ```text
//! crg-difftest --a INCLUDE_DIR:LIBRARY --b INCLUDE_DIR:LIBRARY
//!              [--roads N] [--seed S] [--profile current|2.0.1] [--work DIR] [--show N]
//!              [--timeout SECONDS]  (a client run that takes longer counts as hung; 10)
//!              [--a-env NAME=VALUE]...  (set for a's client only, e.g. OPENCRG_IN_PLACE=always)
//! crg-difftest --generate DIR [--roads N] [--seed S]     (roads and scripts only)
//! ```
//!
//! `a` is the library under test, `b` the one it is compared with. With
//! `--profile 2.0.1` both clients run with `OPENCRG_COMPAT=2.0.1` in their
//! environment; `--a-env` sets a variable for `a`'s client alone (the same library read
//! in place against itself read into memory). A road on which only `b` fails (hangs or crashes: the reference
//! library loops forever in its x/y search on some roads) is reported and counted, not
//! compared. The exit status is 0 when every answer agrees, 1 when some differ or `a`
//! failed, 2 on a usage or build error.

mod compare;
mod rng;
mod roads;
mod scripts;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

/// The client's source, built against each library.
const CLIENT_SOURCE: &str = include_str!("../client.c");

struct Args {
    a: Option<(PathBuf, PathBuf)>,
    b: Option<(PathBuf, PathBuf)>,
    roads: usize,
    seed: u64,
    profile: String,
    work: Option<PathBuf>,
    generate_only: Option<PathBuf>,
    show: usize,
    timeout: Duration,
    /// Environment variables set for a's client alone.
    a_env: Vec<(String, String)>,
}

fn usage() -> String {
    "usage: crg-difftest --a INCLUDE_DIR:LIBRARY --b INCLUDE_DIR:LIBRARY [--roads N] [--seed S] \
     [--profile current|2.0.1] [--work DIR] [--show N] [--timeout SECONDS] [--a-env NAME=VALUE]...\n       crg-difftest --generate DIR [--roads N] [--seed S]"
        .to_string()
}

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        a: None,
        b: None,
        roads: 200,
        seed: 1,
        profile: "current".into(),
        work: None,
        generate_only: None,
        show: 3,
        timeout: Duration::from_secs(10),
        a_env: Vec::new(),
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or_else(|| format!("{flag} needs a value\n{}", usage()));
        let library = |v: String| -> Result<(PathBuf, PathBuf), String> {
            let (inc, lib) = v.split_once(':').ok_or_else(|| format!("'{v}' is not INCLUDE_DIR:LIBRARY"))?;
            Ok((PathBuf::from(inc), PathBuf::from(lib)))
        };
        let number = |v: String| v.parse::<u64>().map_err(|_| format!("{flag}: '{v}' is not a whole number"));
        match flag.as_str() {
            "--a" => args.a = Some(library(value()?)?),
            "--b" => args.b = Some(library(value()?)?),
            "--roads" => args.roads = number(value()?)? as usize,
            "--seed" => args.seed = number(value()?)?,
            "--show" => args.show = number(value()?)? as usize,
            "--timeout" => args.timeout = Duration::from_secs(number(value()?)?.max(1)),
            "--profile" => {
                args.profile = value()?;
                if args.profile != "current" && args.profile != "2.0.1" {
                    return Err(format!("--profile: '{}' is neither current nor 2.0.1", args.profile));
                }
            }
            "--work" => args.work = Some(PathBuf::from(value()?)),
            "--a-env" => {
                let v = value()?;
                let (name, set) = v.split_once('=').ok_or_else(|| format!("--a-env: '{v}' is not NAME=VALUE"))?;
                args.a_env.push((name.to_string(), set.to_string()));
            }
            "--generate" => args.generate_only = Some(PathBuf::from(value()?)),
            "-h" | "--help" => return Err(usage()),
            other => return Err(format!("unknown argument '{other}'\n{}", usage())),
        }
    }
    Ok(args)
}

/// Writes road `index` (its files and its script) into `dir`; returns its summary.
fn write_case(dir: &Path, seed: u64, index: usize) -> std::io::Result<String> {
    let mut rng = rng::Rng::new(seed.wrapping_mul(1_000_003).wrapping_add(index as u64));
    let road = roads::generate(&mut rng, index);
    std::fs::create_dir_all(dir)?;
    for (name, bytes) in &road.files {
        std::fs::write(dir.join(name), bytes)?;
    }
    std::fs::write(dir.join("script.txt"), scripts::generate(&mut rng))?;
    Ok(road.summary)
}

/// Builds the client against one library.
fn build_client(work: &Path, name: &str, (include, library): &(PathBuf, PathBuf)) -> Result<PathBuf, String> {
    let source = work.join("difftest_client.c");
    std::fs::write(&source, CLIENT_SOURCE).map_err(|e| format!("{}: {e}", source.display()))?;
    let library = std::fs::canonicalize(library).map_err(|e| format!("{}: {e}", library.display()))?;
    let lib_dir = library.parent().unwrap_or(Path::new("/"));
    let exe = work.join(format!("client_{name}"));
    let mut cc = Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()));
    cc.args(["-O1", "-Wall", "-Wextra", "-Werror", "-std=c99"])
        .arg(format!("-I{}", include.display()))
        .arg(&source)
        .arg(&library)
        .args(["-lm", "-lpthread", "-ldl"])
        .arg(format!("-Wl,-rpath,{}", lib_dir.display()))
        .arg("-o")
        .arg(&exe);
    let out = cc.output().map_err(|e| format!("cannot run the C compiler: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "building the client against {}:\n{}",
            library.display(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(exe)
}

/// Runs a client on a case (with the variables `env` set); its output, or why there is none.
fn run_client(
    exe: &Path,
    dir: &Path,
    profile: &str,
    env: &[(String, String)],
    limit: Duration,
) -> Result<String, String> {
    let mut cmd = Command::new(exe);
    cmd.arg("script.txt").current_dir(dir).stdout(Stdio::piped()).stderr(Stdio::null()).env_remove("OPENCRG_COMPAT");
    if profile == "2.0.1" {
        cmd.env("OPENCRG_COMPAT", "2.0.1");
    }
    cmd.envs(env.iter().map(|(k, v)| (k, v)));
    let mut child = cmd.spawn().map_err(|e| format!("cannot start {}: {e}", exe.display()))?;
    let mut stdout = child.stdout.take().expect("stdout is piped");
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = std::io::Read::read_to_string(&mut stdout, &mut s);
        s
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("hung (killed after {} s)", limit.as_secs()));
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let output = reader.join().unwrap_or_default();
    if status.success() {
        Ok(output)
    } else {
        Err(format!("exited with {status}"))
    }
}

#[derive(Default)]
struct Totals {
    roads: usize,
    lines: usize,
    calls: usize,
    differing_lines: usize,
    differing_roads: usize,
    broken_runs: usize,
    b_failed: usize,
}

/// Compares the two outputs of one case; prints up to `show` differences.
fn compare_case(index: usize, summary: &str, a: &str, b: &str, show: usize, totals: &mut Totals) {
    let (la, lb): (Vec<&str>, Vec<&str>) = (a.lines().collect(), b.lines().collect());
    totals.lines += la.len().max(lb.len());
    totals.calls += la.iter().map(|l| l.matches('|').count().max(1)).sum::<usize>();
    let mut shown = 0;
    let mut differing = 0;
    for k in 0..la.len().max(lb.len()) {
        let (x, y) = (la.get(k).copied().unwrap_or("<no line>"), lb.get(k).copied().unwrap_or("<no line>"));
        if compare::lines_agree(x, y) {
            continue;
        }
        differing += 1;
        if shown < show {
            if shown == 0 {
                println!("road {index} ({summary}):");
            }
            println!("  line {} {}:\n    a: {x}\n    b: {y}", k + 1, compare::first_differing_call(x, y));
            shown += 1;
        }
    }
    if differing > 0 {
        if differing > shown {
            println!("  ... {} more differing lines", differing - shown);
        }
        totals.differing_lines += differing;
        totals.differing_roads += 1;
    }
}

fn run(args: Args) -> Result<bool, String> {
    if let Some(dir) = &args.generate_only {
        for i in 0..args.roads {
            let summary = write_case(&dir.join(format!("road{i:05}")), args.seed, i).map_err(|e| e.to_string())?;
            println!("road{i:05}: {summary}");
        }
        return Ok(true);
    }
    let (Some(a), Some(b)) = (&args.a, &args.b) else {
        return Err(usage());
    };
    let work =
        args.work.clone().unwrap_or_else(|| std::env::temp_dir().join(format!("crg-difftest-{}", std::process::id())));
    std::fs::create_dir_all(&work).map_err(|e| format!("{}: {e}", work.display()))?;
    let client_a = build_client(&work, "a", a)?;
    let client_b = build_client(&work, "b", b)?;
    let mut totals = Totals::default();
    for i in 0..args.roads {
        let dir = work.join(format!("road{i:05}"));
        let summary = write_case(&dir, args.seed, i).map_err(|e| format!("{}: {e}", dir.display()))?;
        totals.roads += 1;
        let differing_before = totals.differing_roads;
        let run = |exe: &Path, env: &[(String, String)]| run_client(exe, &dir, &args.profile, env, args.timeout);
        match (run(&client_a, &args.a_env), run(&client_b, &[])) {
            (Ok(x), Ok(y)) => compare_case(i, &summary, &x, &y, args.show, &mut totals),
            (x, y) => {
                let state = |r: &Result<String, String>| r.as_ref().map_or_else(|e| e.clone(), |_| "ran".into());
                println!("road {i} ({summary}): a {}, b {}", state(&x), state(&y));
                if x.is_ok() {
                    // Only b failed (the reference hangs on some roads): nothing to compare.
                    totals.b_failed += 1;
                } else {
                    totals.broken_runs += 1;
                    totals.differing_roads += 1;
                }
            }
        }
        // A road that shows a difference stays in a work folder given by --work.
        if totals.differing_roads == differing_before || args.work.is_none() {
            let _ = std::fs::remove_dir_all(&dir);
        }
    }
    if args.work.is_none() {
        let _ = std::fs::remove_dir_all(&work);
    }
    println!(
        "difftest ({} profile, seed {}): {} roads, {} answer lines, {} calls compared; {} differing lines in {} roads, {} runs of a failed, {} roads not compared (b failed)",
        args.profile,
        args.seed,
        totals.roads,
        totals.lines,
        totals.calls,
        totals.differing_lines,
        totals.differing_roads,
        totals.broken_runs,
        totals.b_failed
    );
    Ok(totals.differing_roads == 0)
}

fn main() -> ExitCode {
    match parse_args().and_then(run) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => {
            eprintln!("crg-difftest: {e}");
            ExitCode::from(2)
        }
    }
}
