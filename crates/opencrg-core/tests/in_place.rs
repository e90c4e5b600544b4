//! Roads read in place answer as the same roads read into memory, to the last bit: every
//! evaluation call, with options, after every modifier (once and twice), in both
//! behaviour profiles, across tile borders, on many threads. A file cut short, changed or
//! removed under an open road kills nothing: what can no longer be read is refused with
//! an error naming the file.

use opencrg_core::settings::{m, opt};
use opencrg_core::synth::RoadSpec;
use opencrg_core::{Compat, ContactPoint, DataFormat, LoadOptions, ReadInPlace, Road};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A folder of its own for each test.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("opencrg-in-place-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The elevations: bumps, and NaN in places a scanner leaves them (runs at the right and
/// left border, a whole cross section, single cells inside).
fn surface(u: f64, v: f64) -> f64 {
    let border = (u * 0.37).sin();
    if (v < -1.6 && border > 0.3) || (v > 1.7 && border < -0.5) || (u > 12.0 && u < 12.3) {
        return f64::NAN;
    }
    if ((u * 10.0).round() as i64 * 7 + (v * 10.0).round() as i64 * 3) % 97 == 0 {
        return f64::NAN;
    }
    0.01 * (u * 3.1).sin() * (v * 2.3).cos() + 0.002 * (u * 17.0 + v * 5.0).sin()
}

/// The roads compared: several tiles along and across, each kind of reference line.
fn specs() -> Vec<(&'static str, RoadSpec)> {
    let straight = RoadSpec::straight(60.0, 4.0, 0.05, 0.1).with_elevation(surface);
    let winding = RoadSpec::straight(60.0, 4.0, 0.05, 0.1)
        .with_heading(|u| 0.6 * (u / 9.0).sin())
        .with_slope(|u| 0.03 * (u / 7.0).sin())
        .with_bank(|u| 0.02 * (u / 5.0).cos())
        .with_elevation(surface);
    let mut uneven =
        RoadSpec::straight(30.0, 4.0, 0.05, 0.1).with_heading(|u| 0.2 * (u / 6.0).sin()).with_elevation(surface);
    uneven.v_regular = false;
    uneven.v = (0..40).map(|i| -2.0 + 0.1 * f64::from(i) + 0.002 * f64::from(i % 3)).collect();
    // A loop: the reference line turns a full circle, so the track can be closed.
    let looped = RoadSpec::straight(2.0 * std::f64::consts::PI * 10.0, 3.0, 0.05, 0.1)
        .with_heading(|u| u / 10.0)
        .with_elevation(|u, v| 0.01 * (u * 1.3).sin() + 0.005 * v);
    vec![("straight", straight), ("winding", winding), ("uneven", uneven), ("loop", looped)]
}

/// `spec` written to `dir` in `format`, read in place and into memory.
fn both(spec: &RoadSpec, dir: &Path, name: &str, format: DataFormat, compat: Compat) -> (Road, Road) {
    let path = dir.join(format!("{name}_{}.crg", format.name()));
    if !path.exists() {
        opencrg_core::write(&spec.build().unwrap(), &path, format).unwrap();
    }
    let load = |in_place| Road::load_with(&path, LoadOptions { compat, in_place, ..LoadOptions::default() }).unwrap();
    let (placed, memory) = (load(ReadInPlace::Always), load(ReadInPlace::Never));
    assert!(placed.grid().is_in_place() && !memory.grid().is_in_place());
    (placed, memory)
}

/// An answer as bits (NaN as one value: its payload means nothing), or the refusal's text.
fn bits<const K: usize>(r: opencrg_core::Result<[f64; K]>) -> Result<[u64; K], String> {
    r.map(|v| v.map(|x| if x.is_nan() { u64::MAX } else { x.to_bits() })).map_err(|e| e.to_string())
}

/// Values as bits, NaN as one value.
fn value_bits(values: &[f32]) -> Vec<u32> {
    values.iter().map(|z| if z.is_nan() { u32::MAX } else { z.to_bits() }).collect()
}

/// Every evaluation call at points over and beyond the road, on both roads: equal.
fn same_answers(placed: &Road, memory: &Road, options: &[(u32, f64)], what: &str) {
    let make = |road: &Road| {
        let mut cp = ContactPoint::new(Arc::new(road.clone()));
        for &(id, value) in options {
            if matches!(opencrg_core::settings::describe(id).unwrap().1, opencrg_core::settings::Kind::Int) {
                cp.set_option_int(id, value as i32).unwrap();
            } else {
                cp.set_option_double(id, value).unwrap();
            }
        }
        cp
    };
    let (mut a, mut b) = (make(placed), make(memory));
    let (u0, u1) = memory.u_range();
    let (v0, v1) = memory.v_range();
    let mut points = Vec::new();
    for i in -20..=420 {
        for j in -14..=14 {
            let u = u0 + (u1 - u0) * f64::from(i) / 400.0 + 0.0013 * f64::from(j);
            let v = v0 + (v1 - v0) * (f64::from(j) + 10.0) / 20.0 + 0.0007 * f64::from(i % 5);
            points.push((u, v));
        }
    }
    for &(u, v) in &points {
        let at = format!("{what}: at ({u}, {v})");
        assert_eq!(bits(a.uv_to_z(u, v).map(|z| [z])), bits(b.uv_to_z(u, v).map(|z| [z])), "uv_to_z {at}");
        assert_eq!(
            bits(a.uv_to_normal(u, v).map(|(z, n)| [z, n[0], n[1], n[2]])),
            bits(b.uv_to_normal(u, v).map(|(z, n)| [z, n[0], n[1], n[2]])),
            "uv_to_normal {at}"
        );
        assert_eq!(
            bits(a.uv_to_pk(u, v).map(|(p, k)| [p, k])),
            bits(b.uv_to_pk(u, v).map(|(p, k)| [p, k])),
            "uv_to_pk {at}"
        );
        let (x, y) = b.uv_to_xy(u, v).unwrap();
        assert_eq!(
            bits(a.xy_to_uv(x, y).map(|(p, q)| [p, q])),
            bits(b.xy_to_uv(x, y).map(|(p, q)| [p, q])),
            "xy_to_uv {at}"
        );
        assert_eq!(bits(a.xy_to_z(x, y).map(|z| [z])), bits(b.xy_to_z(x, y).map(|z| [z])), "xy_to_z {at}");
        // The elevation the C library's x/y call gives after its search: the lean paths
        // with their kept cell.
        assert_eq!(bits(a.z_of_found(u, v).map(|z| [z])), bits(b.z_of_found(u, v).map(|z| [z])), "z_of_found {at}");
    }
    let (us, vs): (Vec<f64>, Vec<f64>) = points.iter().copied().unzip();
    let (mut za, mut zb) = (vec![0.0; us.len()], vec![0.0; us.len()]);
    assert_eq!(a.uv_to_z_many(&us, &vs, &mut za), b.uv_to_z_many(&us, &vs, &mut zb), "{what}");
    assert!(za.iter().zip(&zb).all(|(p, q)| p.to_bits() == q.to_bits() || (p.is_nan() && q.is_nan())), "batch {what}");
}

/// The option sets tried: the file's, each border mode in u and v, offsets, smoothing,
/// the lateral curvature.
fn option_sets() -> Vec<Vec<(u32, f64)>> {
    let mut sets = vec![vec![]];
    for mode in 0..=4 {
        sets.push(vec![(opt::BORDER_MODE_U, f64::from(mode)), (opt::BORDER_MODE_V, f64::from(4 - mode))]);
    }
    sets.push(vec![
        (opt::BORDER_MODE_U, 2.0),
        (opt::BORDER_OFFSET_U, 0.3),
        (opt::BORDER_MODE_V, 2.0),
        (opt::BORDER_OFFSET_V, -0.2),
    ]);
    sets.push(vec![(opt::SMOOTH_U_BEGIN, 3.0), (opt::SMOOTH_U_END, 2.0)]);
    sets.push(vec![(opt::CURV_MODE, 0.0), (opt::REFLINE_CONTINUE, 1.0)]);
    sets
}

#[test]
fn every_call_and_option_answers_as_in_memory() {
    let dir = folder("calls");
    for (name, spec) in specs() {
        for format in [DataFormat::Krbi, DataFormat::Kdbi] {
            for compat in [Compat::Upstream, Compat::Release201] {
                let (placed, memory) = both(&spec, &dir, name, format, compat);
                for options in option_sets() {
                    same_answers(&placed, &memory, &options, &format!("{name} {format:?} {compat:?} {options:?}"));
                }
                assert!(placed.grid().tiles_read() > 0, "{name}: the tiles were read");
            }
        }
    }
}

/// The modifier sets tried: each alone, and the file's defaults.
fn modifier_sets() -> Vec<Vec<(u32, f64)>> {
    let mut sets: Vec<Vec<(u32, f64)>> = vec![
        vec![(m::SCALE_Z, 1.7)],
        vec![(m::SCALE_SLOPE, 2.0)],
        vec![(m::SCALE_BANK, -1.5)],
        vec![(m::SCALE_LENGTH, 1.3)],
        vec![(m::SCALE_WIDTH, 0.8)],
        vec![(m::SCALE_CURVATURE, 0.5)],
        vec![
            (m::REFPOINT_U_FRAC, 0.4),
            (m::REFPOINT_V_FRAC, 0.3),
            (m::REFPOINT_X, 10.0),
            (m::REFPOINT_Y, -3.0),
            (m::REFPOINT_Z, 2.5),
            (m::REFPOINT_PHI, 1.0),
        ],
        vec![(m::REFPOINT_U, 5.0), (m::REFPOINT_V, 0.5), (m::REFPOINT_Z, -1.0)],
        vec![
            (m::REFLINE_OFFSET_X, 3.0),
            (m::REFLINE_OFFSET_Y, 4.0),
            (m::REFLINE_OFFSET_Z, 0.7),
            (m::REFLINE_OFFSET_PHI, -0.4),
        ],
        vec![(m::SCALE_Z, 0.5), (m::GRID_NAN_MODE, 1.0), (m::GRID_NAN_OFFSET, 0.25), (m::REFPOINT_Z, 1.0)],
    ];
    for mode in 0..=2 {
        sets.push(vec![(m::GRID_NAN_MODE, f64::from(mode))]);
    }
    for mode in 1..=2 {
        sets.push(vec![(m::GRID_NAN_MODE, f64::from(mode)), (m::GRID_NAN_OFFSET, 0.125)]);
    }
    sets
}

/// `road` with `mods` (none: the file's own) checked and applied `times` times.
fn modified(mut road: Road, mods: Option<&[(u32, f64)]>, times: usize) -> Road {
    if let Some(mods) = mods {
        road.modifiers_mut().clear();
        for &(id, value) in mods {
            if id == m::GRID_NAN_MODE {
                road.modifiers_mut().set_int(id, value as i32).unwrap();
            } else {
                road.modifiers_mut().set_double(id, value).unwrap();
            }
        }
    }
    road.check().unwrap();
    for _ in 0..times {
        road.apply_modifiers();
    }
    road
}

#[test]
fn every_modifier_acts_as_in_memory_without_copying_the_grid() {
    let dir = folder("modifiers");
    for (name, spec) in specs() {
        for compat in [Compat::Upstream, Compat::Release201] {
            let (placed, memory) = both(&spec, &dir, name, DataFormat::Krbi, compat);
            let mut sets: Vec<Option<Vec<(u32, f64)>>> = modifier_sets().into_iter().map(Some).collect();
            sets.push(None);
            for mods in &sets {
                for times in [1, 2] {
                    let a = modified(placed.clone(), mods.as_deref(), times);
                    let b = modified(memory.clone(), mods.as_deref(), times);
                    assert!(a.grid().is_in_place(), "modifiers keep the grid in place");
                    let what = format!("{name} {compat:?} {mods:?} x{times}");
                    same_answers(&a, &b, &[], &what);
                    // (Printed: a NaN in a channel is equal to itself there.)
                    assert_eq!(format!("{:?}", a.reference_line()), format!("{:?}", b.reference_line()), "{what}");
                    // Every value through the streaming read, as `write` and the tools read them.
                    assert_eq!(value_bits(a.grid().values()), value_bits(b.grid().values()), "{what}");
                }
            }
        }
    }
}

#[test]
fn written_back_a_road_in_place_is_the_road_in_memory() {
    let dir = folder("write");
    let (name, spec) = specs().remove(1);
    let (placed, memory) = both(&spec, &dir, name, DataFormat::Kdbi, Compat::Upstream);
    let (placed, memory) = (modified(placed, None, 1), modified(memory, None, 1));
    for format in [DataFormat::Krbi, DataFormat::Lrfi] {
        let (pa, pb) = (dir.join(format!("a.{}", format.name())), dir.join(format!("b.{}", format.name())));
        opencrg_core::write(&placed, &pa, format).unwrap();
        opencrg_core::write(&memory, &pb, format).unwrap();
        assert_eq!(std::fs::read(&pa).unwrap(), std::fs::read(&pb).unwrap(), "{format:?}");
    }
}

#[test]
fn threads_share_one_road_in_place() {
    let dir = folder("threads");
    // 10 tiles along (19 halves), 3 across.
    let spec = RoadSpec::straight(480.0, 4.0, 0.05, 0.1).with_elevation(surface);
    let (placed, memory) = both(&spec, &dir, "long", DataFormat::Krbi, Compat::Upstream);
    // A pool of the fewest slots (16 of the road's 30 tiles): the threads evict each
    // other's tiles and read tiles and halves of tiles at the same time all the time.
    let path = dir.join("long_KRBI.crg");
    let small = Road::load_with(
        &path,
        LoadOptions { in_place: ReadInPlace::Always, tile_cache: Some(1), ..LoadOptions::default() },
    )
    .unwrap();
    let memory = Arc::new(memory);
    for road in [Arc::new(placed), Arc::new(small)] {
        std::thread::scope(|s| {
            for t in 0..8 {
                let (road, memory) = (road.clone(), memory.clone());
                s.spawn(move || {
                    let (mut a, mut b) = (ContactPoint::new(road), ContactPoint::new(memory));
                    for k in 0..20_000 {
                        let u = (f64::from(k) * 0.023 * f64::from(t + 1)) % 479.0;
                        let v = -1.9 + 3.8 * ((f64::from(k) * 0.37 + f64::from(t)).sin() * 0.5 + 0.5);
                        let (za, zb) = (a.z_of_found(u, v), b.z_of_found(u, v));
                        assert_eq!(bits(za.map(|z| [z])), bits(zb.map(|z| [z])), "thread {t} at ({u}, {v})");
                        assert_eq!(bits(a.uv_to_z(u, v).map(|z| [z])), bits(b.uv_to_z(u, v).map(|z| [z])));
                    }
                });
            }
        });
        assert!(road.grid().tiles_read() >= 57, "{} halves of tiles read", road.grid().tiles_read());
    }
}

/// Threads on one tile of a road read in place, in a new pool each round: some read the
/// tile's first half through their windows while others reach its second half, which one
/// of them reads into the same slot meanwhile. Every answer is the road in memory's, bit
/// for bit.
#[test]
fn a_tile_read_half_by_half_while_threads_read_it() {
    let dir = folder("halves");
    // One tile along (1024 cross sections at 1 cm) and a bit, 2 across.
    let spec = RoadSpec::straight(10.5, 2.0, 0.01, 0.1).with_elevation(surface);
    let (_, memory) = both(&spec, &dir, "halves", DataFormat::Krbi, Compat::Upstream);
    let memory = Arc::new(memory);
    let path = dir.join("halves_KRBI.crg");
    for round in 0..40 {
        let road = Arc::new(
            Road::load_with(&path, LoadOptions { in_place: ReadInPlace::Always, ..LoadOptions::default() }).unwrap(),
        );
        std::thread::scope(|s| {
            for t in 0..4 {
                let (road, memory) = (road.clone(), memory.clone());
                s.spawn(move || {
                    let (mut a, b) = (ContactPoint::new(road), ContactPoint::new(memory));
                    for k in 0..4000 {
                        // Threads 0 and 1 stay in the first half; 2 and 3 drive from it
                        // into the second, each at its own pace.
                        let reach = if t < 2 { 5.0 } else { 10.2 };
                        let u = 0.02 + (f64::from(k) * 0.0031 * f64::from(t + 1 + round % 3)) % reach;
                        let v = -0.7 + 0.2 * f64::from(t) + 0.05 * (f64::from(k) * 0.1).sin();
                        let z = a.uv_to_z_plain(u, v).map(Ok).unwrap_or_else(|| a.z_of_found(u, v));
                        assert_eq!(
                            bits(z.map(|z| [z])),
                            bits(b.uv_to_z(u, v).map(|z| [z])),
                            "thread {t} at ({u}, {v})"
                        );
                    }
                });
            }
        });
        assert!(road.grid().tiles_read() >= 2, "round {round}: {} halves read", road.grid().tiles_read());
    }
}

#[test]
fn roads_below_the_size_stay_in_memory_and_text_roads_always() {
    let dir = folder("policy");
    let (_, spec) = specs().remove(0);
    let road = spec.build().unwrap();
    let (krbi, lrfi) = (dir.join("p.crg"), dir.join("p.lrfi"));
    opencrg_core::write(&road, &krbi, DataFormat::Krbi).unwrap();
    opencrg_core::write(&road, &lrfi, DataFormat::Lrfi).unwrap();
    let size = std::fs::metadata(&krbi).unwrap().len();
    let load =
        |path: &Path, in_place| Road::load_with(path, LoadOptions { in_place, ..LoadOptions::default() }).unwrap();
    assert!(load(&krbi, ReadInPlace::From(size)).grid().is_in_place());
    assert!(!load(&krbi, ReadInPlace::From(size + 1)).grid().is_in_place());
    assert!(!load(&lrfi, ReadInPlace::Always).grid().is_in_place());
    assert_eq!(ReadInPlace::parse("256M"), Ok(ReadInPlace::From(256_000_000)));
    assert_eq!(ReadInPlace::parse(" Never "), Ok(ReadInPlace::Never));
    assert!(ReadInPlace::parse("sometimes").unwrap_err().contains("never, always"));
}

/// A road read in place over a file that is then cut short: the tiles read before still
/// answer; what lies in the part cut off, and anything not read before, is refused naming
/// the file; nothing ends the process.
#[cfg(target_os = "linux")]
#[test]
fn a_file_cut_short_under_an_open_road_is_refused_not_fatal() {
    let dir = folder("cut");
    let (_, spec) = specs().remove(0);
    let path = dir.join("cut.crg");
    opencrg_core::write(&spec.build().unwrap(), &path, DataFormat::Krbi).unwrap();
    let road = Arc::new(
        Road::load_with(&path, LoadOptions { in_place: ReadInPlace::Always, ..LoadOptions::default() }).unwrap(),
    );
    let memory =
        Road::load_with(&path, LoadOptions { in_place: ReadInPlace::Never, ..LoadOptions::default() }).unwrap();
    let mut cp = ContactPoint::new(road.clone());
    let reference = ContactPoint::new(Arc::new(memory));
    let early = cp.uv_to_z(1.0, 0.2).unwrap();
    assert_eq!(early.to_bits(), reference.uv_to_z(1.0, 0.2).unwrap().to_bits());
    let len = std::fs::metadata(&path).unwrap().len();
    std::fs::OpenOptions::new().write(true).open(&path).unwrap().set_len(len / 3).unwrap();
    // In the part cut off: the read faults inside the guard, the call is refused.
    let late = cp.uv_to_z(55.0, 0.2).unwrap_err().to_string();
    assert!(late.contains(&path.display().to_string()) && late.contains("cut short"), "{late}");
    assert!(cp.xy_to_z(55.0, 0.2).is_err());
    assert!(cp.z_of_found(55.0, 0.2).is_err());
    // The tile read before the cut still answers, as the file was when it was opened.
    assert_eq!(cp.uv_to_z(1.0, 0.2).unwrap().to_bits(), early.to_bits());
    // The reference line is in memory: x/y to u/v goes on.
    assert!(cp.xy_to_uv(30.0, 0.5).is_ok());
    assert!(road.grid().fault().is_some());
    // Written out, the road is refused too, and nothing is left half written.
    let out = dir.join("copy.crg");
    let e = opencrg_core::write(&road, &out, DataFormat::Krbi).unwrap_err().to_string();
    assert!(e.contains(&path.display().to_string()), "{e}");
    assert!(!out.exists());
}

/// Threads reading different tiles of a road whose file was cut short, all at once (each
/// reads its tile outside the pool's lock, so reads fault in several threads together):
/// every call answers as the road read into memory or is refused naming the file; none
/// hangs or ends the process.
#[cfg(target_os = "linux")]
#[test]
fn threads_reading_a_file_cut_short_at_once_are_refused_not_fatal() {
    const THREADS: usize = 8;
    let dir = folder("cut-threads");
    let path = dir.join("cut.crg");
    let spec = RoadSpec::straight(60.0, 4.0, 0.01, 0.1).with_elevation(surface);
    opencrg_core::write(&spec.build().unwrap(), &path, DataFormat::Krbi).unwrap();
    let load = |in_place| Arc::new(Road::load_with(&path, LoadOptions { in_place, ..LoadOptions::default() }).unwrap());
    let (road, memory) = (load(ReadInPlace::Always), load(ReadInPlace::Never));
    // A tile read before the cut.
    ContactPoint::new(road.clone()).uv_to_z(1.0, 0.2).unwrap();
    let len = std::fs::metadata(&path).unwrap().len();
    std::fs::OpenOptions::new().write(true).open(&path).unwrap().set_len(len / 3).unwrap();
    let name = path.display().to_string();
    let start = std::sync::Barrier::new(THREADS);
    let counts: Vec<(usize, usize)> = std::thread::scope(|s| {
        let threads: Vec<_> = (0..THREADS)
            .map(|t| {
                let (road, memory, name, start) = (road.clone(), memory.clone(), &name, &start);
                s.spawn(move || {
                    let (cp, reference) = (ContactPoint::new(road), ContactPoint::new(memory));
                    // Each thread its own long sections, and along the road from its own place.
                    let v = -1.9 + 0.5 * t as f64;
                    start.wait();
                    let (mut answered, mut refused) = (0, 0);
                    for k in 0..400 {
                        let u = 0.5 + ((t * 53 + k * 7) % 590) as f64 * 0.1;
                        match cp.uv_to_z(u, v) {
                            Ok(z) => {
                                assert_eq!(Some(z.to_bits()), reference.uv_to_z(u, v).ok().map(f64::to_bits));
                                answered += 1;
                            }
                            Err(e) => {
                                let e = e.to_string();
                                assert!(e.contains(name.as_str()) && e.contains("cut short"), "{e}");
                                refused += 1;
                            }
                        }
                    }
                    (answered, refused)
                })
            })
            .collect();
        threads.into_iter().map(|t| t.join().unwrap()).collect()
    });
    assert!(counts.iter().all(|&(_, refused)| refused > 0), "{counts:?}");
    assert!(road.grid().fault().is_some());
}

#[test]
fn a_file_changed_or_removed_under_an_open_road() {
    let dir = folder("changed");
    let (_, spec) = specs().remove(0);
    let path = dir.join("changed.crg");
    opencrg_core::write(&spec.build().unwrap(), &path, DataFormat::Krbi).unwrap();
    let load = || {
        Arc::new(
            Road::load_with(&path, LoadOptions { in_place: ReadInPlace::Always, ..LoadOptions::default() }).unwrap(),
        )
    };
    // Removed: the open file is still read (the system keeps it while it is open).
    let road = load();
    let cp = ContactPoint::new(road.clone());
    std::fs::remove_file(&path).unwrap();
    assert!(cp.uv_to_z(40.0, 0.5).unwrap().is_finite());
    // Changed in place (same size, another modification time): refused where not yet read.
    opencrg_core::write(&spec.build().unwrap(), &path, DataFormat::Krbi).unwrap();
    let road = load();
    let cp = ContactPoint::new(road);
    assert!(cp.uv_to_z(1.0, 0.0).is_ok());
    let mut bytes = std::fs::read(&path).unwrap();
    let n = bytes.len();
    bytes[n - 100] ^= 0x40;
    std::thread::sleep(std::time::Duration::from_millis(20));
    use std::io::{Seek, Write};
    let mut file = std::fs::OpenOptions::new().write(true).open(&path).unwrap();
    file.seek(std::io::SeekFrom::Start(0)).unwrap();
    file.write_all(&bytes).unwrap();
    file.sync_all().unwrap();
    let e = cp.uv_to_z(58.0, 0.0).unwrap_err().to_string();
    assert!(e.contains("changed") && e.contains(&path.display().to_string()), "{e}");
}
