//! Mutated road files: roads the project generates, in all four formats (and the ASAM
//! text samples in `../shared` when it is there), changed at random (bytes flipped, ranges cut or repeated, numbers replaced by extreme ones,
//! lines swapped, settings added, files cut short). Every mutant must either be refused
//! with an error or load; a loaded one then goes through the checks, the modifiers and
//! every evaluation call. Nothing may panic or hang.
//!
//! `OPENCRG_MUTANTS` sets how many mutants (default 1,200), `OPENCRG_MUTATION_SEED` the
//! first seed; a failing mutant is written to the temporary directory and named in the
//! failure message.

use opencrg_core::header::DataFormat;
use opencrg_core::synth::RoadSpec;
use opencrg_core::{ContactPoint, Road};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::mpsc;
use std::sync::Arc;
use std::time::Duration;

/// A small deterministic generator (the test must repeat exactly from its seed).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let x = self.0;
        (x ^ (x >> 33)).wrapping_mul(0xff51afd7ed558ccd) ^ (x >> 29)
    }

    fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next() % n as u64) as usize
        }
    }

    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The roads the mutants start from, each in the four formats.
fn seeds() -> Vec<Vec<u8>> {
    let header = "$ROAD_CRG_OPTS\nBORDER_MODE_U = 2\nBORDER_MODE_V = 3\nREFLINE_SEARCH_UFRAC = 0.5\n$\n\
                  $ROAD_CRG_MODS\nREFLINE_OFFSET_PHI = 0.1\nREFLINE_OFFSET_X = 10\nREFLINE_SCALE_Z = 1.5\n$\n";
    let roads = [
        RoadSpec::straight(6.0, 2.0, 0.5, 0.5).with_elevation(|u, v| 0.01 * u + 0.02 * v),
        RoadSpec::straight(8.0, 3.0, 0.25, 0.5)
            .with_heading(|u| 0.2 * u)
            .with_slope(|u| 0.01 * u)
            .with_bank(|u| 0.02 - 0.001 * u)
            .with_elevation(|u, v| (u * 1.3).sin() * 0.01 + v * 0.003)
            .with_header_text(header),
        RoadSpec::straight(5.0, 2.0, 0.5, 0.5)
            .with_sections(vec![-1.0, -0.6, 0.1, 0.2, 1.0])
            .with_heading(|u| -0.3 * u)
            .with_elevation(|u, v| if (u * 10.0) as i64 % 7 == 3 && v > 0.5 { f64::NAN } else { 0.1 * v }),
    ];
    let mut files = Vec::new();
    for spec in &roads {
        let road = spec.build().expect("a seed road builds");
        for format in [DataFormat::Lrfi, DataFormat::Ldfi, DataFormat::Krbi, DataFormat::Kdbi] {
            let mut bytes = Vec::new();
            opencrg_core::writer::write_to(&road, &mut bytes, format).expect("a seed road writes");
            files.push(bytes);
        }
    }
    files
}

/// The ASAM sample roads in text form beside the project (`../shared/conformance/crg-txt`).
fn shared_samples() -> Vec<Vec<u8>> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/conformance/crg-txt");
    let entries = std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    let mut paths: Vec<_> =
        entries.flatten().map(|e| e.path()).filter(|p| p.extension().is_some_and(|e| e == "crg")).collect();
    paths.sort();
    paths.iter().filter_map(|p| std::fs::read(p).ok()).collect()
}

/// Numbers a mutation puts in place of one in the text.
const EXTREMES: [&str; 16] = [
    "0",
    "-0",
    "1",
    "-1",
    "1e308",
    "-1e308",
    "1e-308",
    "nan",
    "inf",
    "-inf",
    "4294967297",
    "-2147483649",
    "1e9",
    "0.0000001",
    "",
    "1e",
];

/// Lines a mutation inserts after a header section's opening line.
fn setting_line(rng: &mut Rng) -> String {
    let rows = opencrg_core::settings::SETTINGS;
    let row = &rows[rng.below(rows.len())];
    let value = EXTREMES[rng.below(EXTREMES.len())];
    match row.keyword {
        Some(k) => format!("{k} = {value}\n"),
        None => format!("REFERENCE_LINE_INCREMENT = {value}\n"),
    }
}

/// One random change of `bytes`.
fn mutate(bytes: &mut Vec<u8>, rng: &mut Rng) {
    let len = bytes.len();
    match rng.below(8) {
        0 => {
            let at = rng.below(len);
            bytes[at] = rng.next() as u8;
        }
        1 => {
            let at = rng.below(len);
            let n = rng.below(64).min(len - at);
            bytes.drain(at..at + n);
        }
        2 => {
            let at = rng.below(len);
            let n = rng.below(256).min(len - at);
            let piece: Vec<u8> = bytes[at..at + n].to_vec();
            let to = rng.below(bytes.len());
            bytes.splice(to..to, piece);
        }
        3 => {
            // A number of the header replaced by an extreme one.
            let header_end = find(bytes, b"$$$$").unwrap_or(len).min(len);
            let starts: Vec<usize> = (1..header_end)
                .filter(|&i| bytes[i].is_ascii_digit() && !bytes[i - 1].is_ascii_alphanumeric() && bytes[i - 1] != b'.')
                .collect();
            if let Some(&start) = starts.get(rng.below(starts.len())) {
                let mut end = start;
                while end < len && (bytes[end].is_ascii_digit() || b".eE+-".contains(&bytes[end])) {
                    end += 1;
                }
                let with = EXTREMES[rng.below(EXTREMES.len())].as_bytes().to_vec();
                bytes.splice(start..end, with);
            }
        }
        4 => bytes.truncate(rng.below(len)),
        5 => {
            // Two lines swapped.
            let lines: Vec<usize> = std::iter::once(0)
                .chain(bytes.iter().enumerate().filter(|(_, &b)| b == b'\n').map(|(i, _)| i + 1))
                .collect();
            if lines.len() > 3 {
                let a = rng.below(lines.len() - 2);
                let b = a + 1 + rng.below(lines.len() - a - 2);
                let (a0, a1, b0, b1) = (lines[a], lines[a + 1], lines[b], lines[b + 1]);
                let mut out = bytes[..a0].to_vec();
                out.extend_from_slice(&bytes[b0..b1]);
                out.extend_from_slice(&bytes[a1..b0]);
                out.extend_from_slice(&bytes[a0..a1]);
                out.extend_from_slice(&bytes[b1..]);
                *bytes = out;
            }
        }
        6 => {
            // A setting with an extreme value added to a header section.
            let sections: Vec<usize> = ["$ROAD_CRG\n", "$ROAD_CRG_OPTS\n", "$ROAD_CRG_MODS\n"]
                .iter()
                .filter_map(|s| find(bytes, s.as_bytes()).map(|i| i + s.len()))
                .collect();
            if let Some(&at) = sections.get(rng.below(sections.len())) {
                let line = setting_line(rng);
                bytes.splice(at..at, line.into_bytes());
            } else {
                let line = format!("$ROAD_CRG_OPTS\n{}$\n", setting_line(rng));
                bytes.splice(0..0, line.into_bytes());
            }
        }
        _ => {
            // A run of bytes set to one value (zeros or 0xff in the binary data).
            let at = rng.below(len);
            let n = rng.below(32).min(len - at);
            let value = if rng.below(2) == 0 { 0 } else { 0xff };
            bytes[at..at + n].fill(value);
        }
    }
}

fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

/// Loads the mutant; when it loads, checks it, applies its modifiers and evaluates it.
/// Returns whether it loaded.
fn exercise(bytes: Vec<u8>, rng_seed: u64) -> bool {
    let Ok(mut road) = Road::from_bytes(bytes, "mutant.crg") else {
        return false;
    };
    let _ = road.check();
    road.apply_modifiers();
    let _ = road.check();
    let road = Arc::new(road);
    let mut rng = Rng(rng_seed);
    let (u0, u1) = road.u_range();
    let (v0, v1) = road.v_range();
    let mut cp = ContactPoint::new(road.clone());
    for round in 0..3 {
        if round == 1 {
            let _ = cp.set_option_int(opencrg_core::settings::opt::BORDER_MODE_U, 3);
            let _ = cp.set_option_int(opencrg_core::settings::opt::BORDER_MODE_V, 4);
        }
        if round == 2 {
            let _ = cp.set_option_double(opencrg_core::settings::opt::SMOOTH_U_BEGIN, 0.5);
            let _ = cp.set_option_int(opencrg_core::settings::opt::BORDER_MODE_U, 2);
        }
        let mut us = Vec::new();
        let mut vs = Vec::new();
        for _ in 0..20 {
            let u = u0 + (u1 - u0) * (rng.unit() * 1.6 - 0.3);
            let v = v0 + (v1 - v0) * (rng.unit() * 2.0 - 0.5);
            let _ = cp.uv_to_z(u, v);
            let _ = cp.uv_to_pk(u, v);
            let _ = cp.uv_to_normal(u, v);
            if let Ok((x, y)) = cp.uv_to_xy(u, v) {
                let _ = cp.xy_to_uv(x, y);
                let _ = cp.xy_to_z(x + 0.1, y);
                let _ = cp.xy_to_pk(x, y - 0.1);
                let _ = cp.xy_to_normal(x, y);
            }
            us.push(u);
            vs.push(v);
        }
        let mut out = vec![0.0; us.len()];
        cp.uv_to_z_many(&us, &vs, &mut out);
    }
    true
}

#[test]
fn mutated_files_never_panic_or_hang() {
    mutants_never_panic_or_hang(&seeds(), 1200);
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_samples_mutated_never_panic_or_hang() {
    mutants_never_panic_or_hang(&shared_samples(), 600);
}

/// Mutants of `seeds` (`OPENCRG_MUTANTS` of them, else `default_count`), each refused or
/// loaded, checked, modified and evaluated, none panicking or taking 20 s.
fn mutants_never_panic_or_hang(seeds: &[Vec<u8>], default_count: usize) {
    let count: usize = std::env::var("OPENCRG_MUTANTS").ok().and_then(|s| s.parse().ok()).unwrap_or(default_count);
    let first: u64 = std::env::var("OPENCRG_MUTATION_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1);
    std::panic::set_hook(Box::new(|_| {}));
    let mut loaded = 0;
    for k in 0..count as u64 {
        let seed = first + k;
        let mut rng = Rng(seed);
        let mut bytes = seeds[rng.below(seeds.len())].clone();
        for _ in 0..1 + rng.below(4) {
            if bytes.is_empty() {
                break;
            }
            mutate(&mut bytes, &mut rng);
        }
        let (tx, rx) = mpsc::channel();
        let copy = bytes.clone();
        std::thread::spawn(move || {
            let _ = tx.send(catch_unwind(AssertUnwindSafe(|| exercise(copy, seed))));
        });
        let verdict = match rx.recv_timeout(Duration::from_secs(20)) {
            Ok(Ok(did_load)) => {
                loaded += usize::from(did_load);
                continue;
            }
            Ok(Err(_)) => "panicked",
            Err(_) => "did not finish within 20 s",
        };
        let path = std::env::temp_dir().join(format!("opencrg-mutant-{seed}.crg"));
        std::fs::write(&path, &bytes).unwrap();
        let _ = std::panic::take_hook();
        panic!("mutant {seed} {verdict}; written to {}", path.display());
    }
    let _ = std::panic::take_hook();
    eprintln!("{count} mutants: {loaded} loaded and were evaluated, {} refused", count - loaded);
    // Both outcomes must be common, or the mutations test little.
    assert!(loaded * 5 > count && (count - loaded) * 5 > count, "{loaded} of {count} loaded");
}
