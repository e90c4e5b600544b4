//! The tools on roads read in place: what they make and find is what they make and find
//! from the same roads read into memory (the files they write, to the byte).

use opencrg_core::synth::RoadSpec;
use opencrg_core::{DataFormat, LoadOptions, ReadInPlace, Road};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A folder of its own for each test.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("opencrg-tools-in-place-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A curved, climbing, banked KRBI road of several tiles each way, with NaN at its right
/// border here and there, written to `dir`, read in place and into memory.
fn both(dir: &Path) -> (Arc<Road>, Arc<Road>) {
    let path = dir.join("winding.crg");
    RoadSpec::straight(80.0, 6.0, 0.05, 0.1)
        .with_heading(|u| 0.3 * (u / 20.0).sin())
        .with_slope(|u| 0.02 * (u / 30.0).cos())
        .with_bank(|u| 0.03 * (u / 15.0).sin())
        .with_elevation(|u, v| {
            if v < -2.8 && (u * 0.3).sin() > 0.5 {
                f64::NAN
            } else {
                0.01 * (u * 1.3).sin() * (v * 2.1).cos()
            }
        })
        .write(&path, DataFormat::Krbi)
        .unwrap();
    let load = |in_place| Arc::new(Road::load_with(&path, LoadOptions { in_place, ..LoadOptions::default() }).unwrap());
    let (placed, memory) = (load(ReadInPlace::Always), load(ReadInPlace::Never));
    assert!(placed.grid().is_in_place());
    (placed, memory)
}

/// `road` written to `path` as KRBI; the file's bytes.
fn written(road: &Road, path: &Path) -> Vec<u8> {
    opencrg_core::write(road, path, DataFormat::Krbi).unwrap();
    std::fs::read(path).unwrap()
}

#[test]
fn cuts_of_a_road_read_in_place_are_the_cuts_of_the_road_in_memory() {
    let dir = folder("cut");
    let (placed, memory) = both(&dir);
    // Along u and across v: a part of the file the cut reads itself.
    for (u, v) in [((10.0, 42.5), None), ((0.0, 80.0), Some((-1.0, 2.0))), ((33.3, 70.0), Some((-3.0, 0.5)))] {
        let a = opencrg_tools::cut(&placed, u, v).unwrap();
        let b = opencrg_tools::cut(&memory, u, v).unwrap();
        assert!(a.grid().is_in_place(), "a cut reads its part of the file in place");
        assert_eq!(written(&a, &dir.join("a.crg")), written(&b, &dir.join("b.crg")), "cut {u:?} {v:?}");
    }
    // After modifiers (the cut reads the values they made).
    let modified = |road: &Arc<Road>| {
        let mut r = (**road).clone();
        r.check().unwrap();
        r.apply_modifiers();
        Arc::new(r)
    };
    let (a, b) = (modified(&placed), modified(&memory));
    let (a, b) =
        (opencrg_tools::cut(&a, (5.0, 60.0), None).unwrap(), opencrg_tools::cut(&b, (5.0, 60.0), None).unwrap());
    assert!(!a.grid().is_in_place());
    assert_eq!(written(&a, &dir.join("a.crg")), written(&b, &dir.join("b.crg")));
}

#[test]
fn a_comparison_with_a_road_read_in_place_is_that_with_the_road_in_memory() {
    let dir = folder("compare");
    let (placed, memory) = both(&dir);
    let part = Arc::new(opencrg_tools::cut(&memory, (20.0, 50.0), Some((-2.0, 2.5))).unwrap());
    for (first, second) in [(&part, &placed), (&placed, &part)] {
        let same_first = if Arc::ptr_eq(first, &part) { part.clone() } else { memory.clone() };
        let same_second = if Arc::ptr_eq(second, &part) { part.clone() } else { memory.clone() };
        let a = opencrg_tools::compare(first, second, &|_, _, _| {}).unwrap();
        let b = opencrg_tools::compare(&same_first, &same_second, &|_, _, _| {}).unwrap();
        assert_eq!(format!("{a:?}"), format!("{b:?}"));
        assert!(a.compared > 0);
    }
}

#[test]
fn a_scan_of_a_road_read_in_place_finds_what_the_road_in_memory_holds() {
    let dir = folder("scan");
    let (placed, memory) = both(&dir);
    let a = opencrg_core::info::scan(&placed, &mut |_, _| {}).unwrap();
    let b = opencrg_core::info::scan(&memory, &mut |_, _| {}).unwrap();
    assert_eq!(a, b);
    assert!(a.nan_cells > 0, "the road has NaN cells");
    let text = opencrg_core::info::text(&placed, "winding.crg");
    assert!(text.contains("not scanned"), "{text}");
    let scanned = opencrg_core::info::text_scanned(&placed, "winding.crg", Some(&a));
    assert_eq!(scanned, opencrg_core::info::text(&memory, "winding.crg"));
}
