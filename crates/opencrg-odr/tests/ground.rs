//! The ground at a world x/y: world-to-road round trips on the shared maps, and the CRG
//! records of every mode and orientation, of roads and of junctions, against closed forms,
//! with plane CRG files (z = a u + b v + c on a reference line that climbs and is banked,
//! which the attached mode must disregard).

use opencrg_core::synth::RoadSpec;
use opencrg_odr::{Map, Surface};
use std::path::{Path, PathBuf};
use std::sync::Arc;

fn shared(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/opendrive").join(rel)
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_maps_world_points_find_their_road_again() {
    for file in [
        "carla/Town01.xodr",
        "esmini/curves_elevation.xodr",
        "esmini/straight_500_superelevation_elevation_curve.xodr",
        "esmini/multi_intersections.xodr",
    ] {
        let surface = Arc::new(Surface::load(shared(file)).unwrap());
        let mut probe = surface.probe();
        let (mut tried, mut same_road, mut worst) = (0, 0, 0.0f64);
        for (ri, road) in surface.map().roads.iter().enumerate() {
            let mut s = 0.3;
            while s < road.length {
                let Some((section, ds)) = road.lanes.section_at(s) else { break };
                let offset = road.lanes.offset.at(s);
                for left in [true, false] {
                    for span in section.spans(left, ds, offset) {
                        if (span.outer - span.inner).abs() < 0.5 || span.lane.kind == "none" {
                            continue;
                        }
                        let t = 0.5 * (span.inner + span.outer);
                        let p = road.surface_point(s, t);
                        let g = probe
                            .ground(p[0], p[1])
                            .unwrap_or_else(|| panic!("{file} road {} s {s} t {t}: no road", road.id));
                        tried += 1;
                        // Whatever road it finds, its surface there lies under the point.
                        let found = surface.map().roads[g.road].surface_point(g.s, g.t);
                        worst = worst.max((found[0] - p[0]).hypot(found[1] - p[1]));
                        if g.road == ri {
                            same_road += 1;
                            assert!(
                                (g.s - s).abs() < 1e-3 && (g.t - t).abs() < 1e-3,
                                "{file} road {} s {s} t {t}: {g:?}",
                                road.id
                            );
                            assert!(
                                (g.z - p[2]).abs() < 1e-3,
                                "{file} road {} s {s} t {t}: z {} vs {}",
                                road.id,
                                g.z,
                                p[2]
                            );
                            assert_eq!(g.lane, span.lane.id);
                        }
                    }
                }
                s += 7.3;
            }
        }
        assert!(worst < 1e-3, "{file}: {worst}");
        assert!(tried > 50 && same_road * 10 >= tried * 8, "{file}: {same_road} of {tried} on their own road");
    }
    // Far from every road: nothing.
    let surface = Arc::new(Surface::load(shared("carla/Town01.xodr")).unwrap());
    assert!(surface.probe().ground(1e6, 1e6).is_none());
}

/// A plane CRG file z = a u + b v + c, 20 m x 4 m, its reference line starting at
/// (x0, y0, phi0), climbing at 0.03 and banked at 0.02 when `tilted`.
fn plane_crg(dir: &Path, name: &str, (a, b, c): (f64, f64, f64), start: (f64, f64, f64), tilted: bool) -> PathBuf {
    let mut spec = RoadSpec::straight(20.0, 4.0, 0.25, 0.25)
        .starting_at(start.0, start.1, start.2)
        .with_elevation(move |u, v| a * u + b * v + c);
    if tilted {
        spec = spec.with_slope(|_| 0.03).with_bank(|_| 0.02);
    }
    let p = dir.join(name);
    std::fs::write(&p, spec.to_crg()).unwrap();
    p
}

const A: f64 = 0.01;
const B: f64 = -0.02;
const C: f64 = 0.05;

/// One lane section: a driving lane `width` wide each side of the centre, of friction
/// `friction`.
fn lanes(width: f64, friction: f64) -> String {
    let lane = |id: i32| {
        format!(
            r#"<lane id="{id}" type="driving"><width sOffset="0" a="{width}" b="0" c="0" d="0"/><material sOffset="0" friction="{friction}"/></lane>"#
        )
    };
    format!(
        r#"<lanes><laneSection s="0">
<left>{}</left>
<center><lane id="0" type="none"/></center>
<right>{}</right>
</laneSection></lanes>"#,
        lane(1),
        lane(-1)
    )
}

/// A straight road 100 m long along heading 0.4 from (10, 20), climbing at 0.05 and
/// superelevated by 0.04 rad, one lane of 4 m each side with friction 0.7, and `records`.
fn map_with(dir: &Path, records: &str) -> Arc<Surface> {
    let text = format!(
        r#"<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="r" length="100" junction="-1">
<planView><geometry s="0" x="10" y="20" hdg="0.4" length="100"><line/></geometry></planView>
<elevationProfile><elevation s="0" a="2" b="0.05" c="0" d="0"/></elevationProfile>
<lateralProfile><superelevation s="0" a="0.04" b="0" c="0" d="0"/></lateralProfile>
{lanes}
<surface>{records}</surface>
</road></OpenDRIVE>"#,
        lanes = lanes(4.0, 0.7)
    );
    let path = dir.join("map.xodr");
    std::fs::write(&path, text).unwrap();
    Arc::new(Surface::load(&path).unwrap())
}

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("opencrg-odr-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The road's own height at (s, t) and the world point there.
fn road_point(surface: &Surface, s: f64, t: f64) -> [f64; 3] {
    surface.map().roads[0].surface_point(s, t)
}

#[test]
fn attached_records_ride_on_the_road_and_disregard_their_own_line() {
    let d = dir("attached");
    plane_crg(&d, "plane.crg", (A, B, C), (500.0, -300.0, 1.3), true);
    let surface = map_with(
        &d,
        r#"<CRG file="plane.crg" sStart="30" sEnd="45" mode="attached" orientation="same" sOffset="28" tOffset="-0.5" zScale="2" zOffset="0.1"/>"#,
    );
    let mut probe = surface.probe();
    for (s, t) in [(31.0, 0.3), (40.0, -1.2), (44.5, 1.4)] {
        let p = road_point(&surface, s, t);
        let g = probe.ground(p[0], p[1]).unwrap();
        let (u, v) = (s - 28.0, t + 0.5);
        let want = (A * u + B * v + C) * 2.0 + 0.1 + p[2];
        assert!((g.z - want).abs() < 1e-6, "s {s} t {t}: {} vs {want}", g.z);
        assert_eq!(g.friction, 0.7);
    }
    // Outside sStart..sEnd: the road itself.
    let p = road_point(&surface, 50.0, 1.0);
    assert!((probe.ground(p[0], p[1]).unwrap().z - p[2]).abs() < 1e-9);
}

#[test]
fn opposite_records_turn_the_crg_about_its_origin() {
    let d = dir("opposite");
    plane_crg(&d, "plane.crg", (A, B, C), (0.0, 0.0, 0.0), false);
    let surface = map_with(
        &d,
        r#"<CRG file="plane.crg" sStart="10" sEnd="30" mode="attached" orientation="opposite" sOffset="30" tOffset="0.5"/>"#,
    );
    let mut probe = surface.probe();
    for (s, t) in [(12.0, 1.0), (25.0, -1.0)] {
        let p = road_point(&surface, s, t);
        let (u, v) = (-(s - 30.0), -(t - 0.5));
        let want = A * u + B * v + C + p[2];
        let g = probe.ground(p[0], p[1]).unwrap();
        assert!((g.z - want).abs() < 1e-6, "s {s} t {t}: {} vs {want}", g.z);
    }
}

#[test]
fn attached0_records_give_the_crg_height_whole() {
    let d = dir("attached0");
    plane_crg(&d, "plane.crg", (A, B, C), (500.0, -300.0, 1.3), true);
    let surface = map_with(
        &d,
        r#"<CRG file="plane.crg" sStart="0" sEnd="60" mode="attached0" orientation="same" sOffset="5" zScale="1.5"/>"#,
    );
    let mut probe = surface.probe();
    let crg = opencrg_core::ContactPoint::new(Arc::new(opencrg_core::Road::load(d.join("plane.crg")).unwrap()));
    for (s, t) in [(6.0, 0.5), (20.0, -1.5)] {
        let p = road_point(&surface, s, t);
        let (u, v) = (s - 5.0, t);
        // Its own climb (0.03 per m) and banking (0.02 v) count, the road's height does not.
        let closed = A * u + B * v + C + 0.03 * u + 0.02 * v;
        assert!((crg.uv_to_z(u, v).unwrap() - closed).abs() < 1e-5);
        let g = probe.ground(p[0], p[1]).unwrap();
        assert!((g.z - 1.5 * closed).abs() < 1e-5, "s {s} t {t}: {} vs {}", g.z, 1.5 * closed);
    }
}

#[test]
fn genuine_and_global_records_lay_the_crg_in_its_own_frame() {
    let d = dir("genuine");
    let (x0, y0, phi0) = (100.0, 50.0, 0.7);
    // genuine: the CRG's start at the road's point s = 20, t = 1 (its heading turned by
    // 0.1), wherever the file puts it: at (x0, y0, phi0), or where its own modifiers move it.
    let moved = RoadSpec::straight(20.0, 4.0, 0.25, 0.25)
        .starting_at(x0, y0, phi0)
        .with_elevation(|u, v| A * u + B * v + C)
        .with_header_text("$ROAD_CRG_MODS\nREFPOINT_X = 7\nREFPOINT_Y = -3\nREFPOINT_PHI = 2.5\n$\n");
    std::fs::write(d.join("moved.crg"), moved.to_crg()).unwrap();
    plane_crg(&d, "plane.crg", (A, B, C), (x0, y0, phi0), false);
    // The modifiers move the reference point's height (C) to REFPOINT_Z = 0 as well.
    for (file, lift) in [("plane.crg", 0.0), ("moved.crg", -C)] {
        let surface = map_with(
            &d,
            &format!(
                r#"<CRG file="{file}" sStart="15" sEnd="40" mode="genuine" sOffset="20" tOffset="1" hOffset="0.1" zOffset="-0.2"/>"#
            ),
        );
        let road = &surface.map().roads[0];
        let at = road.reference(20.0);
        let (ox, oy) = (at.x - at.hdg.sin(), at.y + at.hdg.cos());
        let dir_h = at.hdg + 0.1;
        let mut probe = surface.probe();
        for (s, t) in [(22.0, 1.5), (26.0, 0.5), (33.0, 2.5)] {
            let p = road_point(&surface, s, t);
            let (dx, dy) = (p[0] - ox, p[1] - oy);
            let (u, v) = (dx * dir_h.cos() + dy * dir_h.sin(), -dx * dir_h.sin() + dy * dir_h.cos());
            assert!((0.0..=20.0).contains(&u) && (-2.0..=2.0).contains(&v), "({u}, {v}) outside the CRG");
            let want = A * u + B * v + C - 0.2 + lift;
            let g = probe.ground(p[0], p[1]).unwrap();
            assert!((g.z - want).abs() < 1e-5, "genuine {file} s {s} t {t}: {} vs {want}", g.z);
        }
    }
    // global: the map's x/y turned by hOffset about (xOffset, yOffset) are the CRG's x/y.
    let d = dir("global");
    plane_crg(&d, "plane.crg", (A, B, C), (x0, y0, phi0), false);
    // Offsets that put the road's point s = 50, t = 0 on the CRG's u = 5, v = 0.5.
    let ho: f64 = 0.25;
    let p50 = (10.0 + 50.0 * 0.4f64.cos(), 20.0 + 50.0 * 0.4f64.sin());
    let q = (x0 + 5.0 * phi0.cos() - 0.5 * phi0.sin(), y0 + 5.0 * phi0.sin() + 0.5 * phi0.cos());
    let (xo, yo) = (p50.0 - (ho.cos() * q.0 - ho.sin() * q.1), p50.1 - (ho.sin() * q.0 + ho.cos() * q.1));
    let surface = map_with(
        &d,
        &format!(
            r#"<CRG file="plane.crg" sStart="0" sEnd="100" mode="global" xOffset="{xo}" yOffset="{yo}" hOffset="{ho}" zScale="3"/>"#
        ),
    );
    let mut probe = surface.probe();
    let mut inside = 0;
    for (s, t) in [(50.0, 0.0), (52.0, 0.5), (48.0, -0.5)] {
        let p = road_point(&surface, s, t);
        let (xc, yc) =
            ((p[0] - xo) * ho.cos() + (p[1] - yo) * ho.sin(), -(p[0] - xo) * ho.sin() + (p[1] - yo) * ho.cos());
        let (dx, dy) = (xc - x0, yc - y0);
        let (u, v) = (dx * phi0.cos() + dy * phi0.sin(), -dx * phi0.sin() + dy * phi0.cos());
        let g = probe.ground(p[0], p[1]).unwrap();
        if (0.0..=20.0).contains(&u) && (-2.0..=2.0).contains(&v) {
            let want = 3.0 * (A * u + B * v + C);
            assert!((g.z - want).abs() < 1e-5, "global s {s} t {t}: {} vs {want}", g.z);
            inside += 1;
        }
    }
    assert_eq!(inside, 3);
}

#[test]
fn friction_records_and_the_material_fallback_and_the_last_record_wins() {
    let d = dir("friction");
    plane_crg(&d, "mu.crg", (0.0, 0.05, 0.6), (0.0, 0.0, 0.0), false);
    plane_crg(&d, "bumps.crg", (0.0, 0.0, 0.01), (0.0, 0.0, 0.0), false);
    plane_crg(&d, "more.crg", (0.0, 0.0, 0.03), (0.0, 0.0, 0.0), false);
    let surface = map_with(
        &d,
        r#"<CRG file="mu.crg" sStart="10" sEnd="25" mode="attached0" purpose="friction" sOffset="10"/>
           <CRG file="bumps.crg" sStart="0" sEnd="50" mode="attached" orientation="same"/>
           <CRG file="more.crg" sStart="20" sEnd="30" mode="attached" orientation="same" sOffset="15"/>"#,
    );
    let mut probe = surface.probe();
    let at = |probe: &mut opencrg_odr::Probe, s: f64, t: f64| {
        let p = road_point(&surface, s, t);
        (probe.ground(p[0], p[1]).unwrap(), p[2])
    };
    let (g, z) = at(&mut probe, 12.0, 1.0);
    assert!((g.friction - (0.6 + 0.05 * 1.0)).abs() < 1e-6, "{}", g.friction);
    assert!((g.z - (z + 0.01)).abs() < 1e-6);
    // Both elevation records cover s = 22: the last one wins.
    let (g, z) = at(&mut probe, 22.0, -1.0);
    assert!((g.z - (z + 0.03)).abs() < 1e-6, "{} vs {}", g.z, z + 0.03);
    assert!((g.friction - (0.6 - 0.05)).abs() < 1e-6);
    // Beyond the friction record: the lane's material.
    let (g, _) = at(&mut probe, 40.0, 1.0);
    assert_eq!(g.friction, 0.7);
    // A missing CRG file: refused naming the map's line and the file.
    let e = match Surface::new(
        Map::from_bytes(
            br#"<OpenDRIVE><road id="r" length="10"><surface>
<CRG file="gone.crg" sStart="0" sEnd="5" mode="attached" orientation="same"/></surface></road></OpenDRIVE>"#,
            Path::new("/tmp/x.xodr"),
        )
        .unwrap(),
    ) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("a missing CRG file was accepted"),
    };
    assert!(e.contains("x.xodr:2") && e.contains("gone.crg"), "{e}");
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_maps_a_wheel_moving_in_small_steps_is_found_as_a_fresh_search_finds_it() {
    // esmini's curves_elevation (lines, spirals and arcs, climbing) and jolengatan
    // (paramPoly3). A probe following a wheel 2 cm a step reaches each station from an
    // anchor near it; a fresh probe searches the index and computes from the record's start.
    let mut compared = 0;
    for map in ["esmini/curves_elevation.xodr", "esmini/jolengatan.xodr"] {
        let surface = Arc::new(Surface::load(shared(map)).unwrap());
        let mut worst = 0.0f64;
        for (k, road) in surface.map().roads.iter().enumerate() {
            for t in [-1.3, 1.3] {
                let mut wheel = surface.probe();
                let steps = ((road.length - 0.1) / 0.02).min(20_000.0) as usize;
                for i in 0..steps {
                    let s = 0.05 + i as f64 * 0.02;
                    let p = road.surface_point(s, t);
                    let Some(a) = wheel.ground(p[0], p[1]) else { continue };
                    if a.road != k {
                        continue;
                    }
                    // Where a record's start lies micrometres off its predecessor's end,
                    // the point finds the other side of the gap.
                    assert!((a.s - s).abs() < 1e-4 && (a.t - t).abs() < 1e-4, "{map} road {k} s {s}: {a:?}");
                    if i % 25 == 0 {
                        let b = surface.probe().ground(p[0], p[1]).unwrap();
                        if b.road == k {
                            worst = worst.max((a.s - b.s).abs()).max((a.t - b.t).abs()).max((a.z - b.z).abs());
                            compared += 1;
                        }
                    }
                }
            }
        }
        assert!(worst < 1e-9, "{map}: {worst}");
    }
    assert!(compared > 1000, "{compared}");
}

/// Two roads end to end, the second a connecting road of junction `j` whose records are
/// `junction_records`; the connecting road carries `own` records.
fn junction_map(dir: &Path, junction_records: &str, own: &str) -> Map {
    let lanes = lanes(3.0, 0.8);
    let text = format!(
        r#"<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="r" length="30" junction="-1">
<planView><geometry s="0" x="0" y="0" hdg="0" length="30"><line/></geometry></planView>
<elevationProfile><elevation s="0" a="1" b="0.02" c="0" d="0"/></elevationProfile>
{lanes}
</road>
<road id="c" length="20" junction="j">
<planView><geometry s="0" x="30" y="0" hdg="0" length="20"><line/></geometry></planView>
<elevationProfile><elevation s="0" a="1.6" b="0.02" c="0" d="0"/></elevationProfile>
{lanes}
<surface>{own}</surface>
</road>
<junction id="j" name="j"><connection id="0" incomingRoad="r" connectingRoad="c" contactPoint="start"/>
<surface>{junction_records}</surface></junction>
</OpenDRIVE>"#
    );
    let path = dir.join("junction.xodr");
    std::fs::write(&path, text).unwrap();
    Map::load(&path).unwrap()
}

#[test]
fn a_junctions_records_lie_on_its_connecting_roads_only() {
    let d = dir("junction");
    // Both CRG files start at the connecting road's start, along it: u = x - 30, v = y.
    plane_crg(&d, "plane.crg", (A, B, C), (30.0, 0.0, 0.0), false);
    plane_crg(&d, "mu.crg", (0.0, 0.05, 0.6), (30.0, 0.0, 0.0), false);
    let records = r#"<CRG file="plane.crg" mode="global" zOffset="0.1" zScale="2"/>
                     <CRG file="mu.crg" mode="global" purpose="friction"/>"#;
    let map = junction_map(&d, records, "");
    assert!(opencrg_odr::check(&map).is_empty(), "{:?}", opencrg_odr::check(&map));
    let surface = Arc::new(Surface::new(map).unwrap());
    let mut probe = surface.probe();
    for (x, y) in [(31.0, 1.0), (38.5, -1.5), (49.0, 0.3)] {
        let g = probe.ground(x, y).unwrap();
        assert_eq!(surface.map().roads[g.road].id, "c");
        let want = 2.0 * (A * (x - 30.0) + B * y + C) + 0.1;
        assert!((g.z - want).abs() < 1e-6, "({x}, {y}): {} vs {want}", g.z);
        assert!((g.friction - (0.6 + 0.05 * y)).abs() < 1e-6, "({x}, {y}): {}", g.friction);
    }
    // The incoming road keeps its own height and material.
    let g = probe.ground(20.0, 1.0).unwrap();
    assert_eq!(surface.map().roads[g.road].id, "r");
    assert!((g.z - (1.0 + 0.02 * 20.0)).abs() < 1e-9 && g.friction == 0.8, "{g:?}");
    // A connecting road with records of its own under a junction that has some: a finding
    // naming the junction.
    let own = r#"<CRG file="plane.crg" sStart="0" sEnd="20" mode="attached" orientation="same"/>"#;
    let findings = opencrg_odr::check(&junction_map(&d, records, own));
    assert!(findings.iter().any(|f| f.place.contains("junction j")), "{findings:?}");
}

/// A map read from bytes with its CRG files given as bytes answers as the map read from
/// its folder; a file not given is refused, naming it and the record's line.
#[test]
fn a_map_from_bytes_with_its_crg_files_answers_as_from_its_folder() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/data");
    let from_disk = Arc::new(Surface::load(data.join("demo_map.xodr")).unwrap());
    let bytes = std::fs::read(data.join("demo_map.xodr")).unwrap();
    let map = || Map::from_bytes(&bytes, Path::new("demo_map.xodr")).unwrap();
    let crg = std::fs::read(data.join("demo_road.crg")).unwrap();
    // Found by its name as written, and by its last path component.
    for name in ["demo_road.crg", "somewhere/else/demo_road.crg"] {
        let in_memory = Arc::new(Surface::from_files(map(), &[(name.to_string(), crg.clone())]).unwrap());
        let (mut a, mut b) = (from_disk.probe(), in_memory.probe());
        let mut met = 0;
        for k in 0..400 {
            let (x, y) = (k as f64 * 0.4, -4.0 + (k % 17) as f64 * 0.5);
            let (ga, gb) = (a.ground(x, y), b.ground(x, y));
            // (Debug's text: NaN friction equal, every other number to the bit.)
            assert_eq!(format!("{ga:?}"), format!("{gb:?}"), "({x}, {y})");
            met += usize::from(ga.is_some());
        }
        assert!(met > 100, "{met}");
    }
    let e = Surface::from_files(map(), &[("other.crg".to_string(), crg)]).err().unwrap().to_string();
    assert!(e.contains("demo_map.xodr:") && e.contains("demo_road.crg") && e.contains("no file named"), "{e}");
}
