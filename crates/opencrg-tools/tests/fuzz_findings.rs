//! The inputs with which the fuzz targets (`fuzz/`) found a problem, replayed as those
//! targets feed them, under an address-space limit of 2 GB above what the test process
//! maps already: an allocation beyond it aborts the test, as it aborted the fuzzer.
#![cfg(target_os = "linux")]

use opencrg_tools::parse_points;
use std::path::Path;

/// Limits this process's address space to what it maps now plus `bytes`.
fn limit_address_space(bytes: u64) {
    let mapped = std::fs::read_to_string("/proc/self/statm").unwrap();
    let pages: u64 = mapped.split_whitespace().next().unwrap().parse().unwrap();
    // SAFETY: sysconf reads a constant; setrlimit reads the structure it is given.
    let page = unsafe { libc::sysconf(libc::_SC_PAGESIZE) } as u64;
    let limit = libc::rlimit { rlim_cur: pages * page + bytes, rlim_max: libc::RLIM_INFINITY };
    // SAFETY: as above.
    assert_eq!(unsafe { libc::setrlimit(libc::RLIMIT_AS, &limit) }, 0);
}

/// The `point_files` target: the first byte picks the kind of file.
fn point_files(data: &[u8]) {
    let (kind, bytes) = data.split_first().unwrap();
    let name = ["fuzz.csv", "fuzz.xyz", "fuzz.ply", "fuzz.las", "fuzz.laz"][usize::from(kind % 5)];
    let _ = parse_points(bytes, Path::new(name));
}

#[test]
fn fuzz_findings_are_answered_within_memory() {
    limit_address_space(2 << 30);
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz_findings");
    let mut replayed = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let data = std::fs::read(&path).unwrap();
        match name.split('-').next() {
            // A LAS header claiming 18 kB a point: the reader asked for a million of them at once.
            Some("point_files") => point_files(&data),
            other => panic!("{name}: no replay for target {other:?}"),
        }
        replayed += 1;
    }
    assert!(replayed >= 1);
}
