//! Roads on the earth: the global origin through modifiers, the map projection section
//! read, refused and written back, and the chain to WGS 84 and back. (The chain's
//! answers are compared with PROJ in the Python tests.)

use opencrg_core::synth::RoadSpec;
use opencrg_core::{ContactPoint, DataFormat, Earth, Error, Road};
use std::sync::Arc;

const PLACE: &str = "$ROAD_CRG\n\
    REFERENCE_LINE_OFFSET_X = 691000.25\n\
    REFERENCE_LINE_OFFSET_Y = 5322000.5\n\
    REFERENCE_LINE_OFFSET_Z = 584.0\n\
    REFERENCE_LINE_OFFSET_PHI = 0.4\n\
    $\n";

fn curved(header: &str) -> RoadSpec {
    RoadSpec::straight(300.0, 6.0, 0.5, 0.25)
        .starting_at(12.0, -3.0, 0.2)
        .with_heading(|u| 0.2 + 0.002 * u)
        .with_slope(|u| 0.01 * (u / 40.0).sin())
        .with_bank(|u| 0.02 * (u / 30.0).cos())
        .with_elevation(|u, v| 0.02 * (u / 7.0).sin() * (v / 2.0).cos())
        .with_header_text(header)
}

fn utm(extra: &str) -> String {
    format!("{PLACE}$ROAD_CRG_MPRO\nPROJ_NM = 'UTM_32U'\n{extra}$\n")
}

/// East, north, height of surface points (u, v) of a road.
fn surface_enh(road: &Arc<Road>) -> Vec<[f64; 3]> {
    let cp = ContactPoint::new(road.clone());
    let mut out = Vec::new();
    for u in [0.0, 77.7, 150.0, 299.0] {
        for v in [-2.5, 0.0, 1.75] {
            let (x, y) = cp.uv_to_xy(u, v).unwrap();
            let z = cp.uv_to_z(u, v).unwrap();
            out.push(road.xyz_to_enh(x, y, z));
        }
    }
    out
}

fn assert_close(a: &[[f64; 3]], b: &[[f64; 3]], tol: f64, what: &str) {
    for (p, q) in a.iter().zip(b) {
        for i in 0..3 {
            assert!((p[i] - q[i]).abs() < tol, "{what}: {p:?} vs {q:?}");
        }
    }
}

#[test]
fn the_surface_keeps_its_place_on_the_earth_through_modifiers() {
    let file = curved(&utm("")).to_crg();
    let unmoved = Road::from_bytes(file.clone(), "place.crg").unwrap();
    assert_eq!(unmoved.global_origin().phi, 0.4);
    let before = surface_enh(&Arc::new(unmoved.clone()));
    let earth = Earth::of(&unmoved).unwrap();
    let llh_before: Vec<_> = before.iter().map(|p| earth.enh_to_llh(*p).unwrap()).collect();
    let cases: [&[(&str, f64)]; 4] = [
        &[],
        &[("REFPOINT_X", 100.0), ("REFPOINT_Y", -50.0), ("REFPOINT_Z", 7.0), ("REFPOINT_PHI", 2.5)],
        &[("REFPOINT_U_FRACTION", 0.4), ("REFPOINT_V_FRACTION", 0.7), ("REFPOINT_X", 3.0), ("REFPOINT_PHI", -1.0)],
        &[("REFLINE_OFFSET_PHI", 1.1), ("REFLINE_OFFSET_X", -30.0), ("REFLINE_OFFSET_Z", 2.0)],
    ];
    for mods in cases {
        let mut road = unmoved.clone();
        if !mods.is_empty() {
            road.modifiers_mut().clear();
            for (name, value) in mods {
                let id = opencrg_core::settings::by_keyword(
                    opencrg_core::settings::Family::Modifier,
                    &name.to_ascii_lowercase(),
                )
                .unwrap()
                .id;
                road.modifiers_mut().set_double(id, *value).unwrap();
            }
        }
        road.apply_modifiers();
        assert_ne!(road.global_origin(), unmoved.global_origin(), "{mods:?} moved nothing");
        let road = Arc::new(road);
        let after = surface_enh(&road);
        assert_close(&before, &after, 1e-6, &format!("{mods:?}"));
        let llh_after: Vec<_> = after.iter().map(|p| earth.enh_to_llh(*p).unwrap()).collect();
        assert_close(&llh_before, &llh_after, 1e-11, "llh");
    }
}

#[test]
fn setting_the_origin_moves_the_frame_not_the_road() {
    let mut road = curved(&utm("")).build().unwrap();
    let cp = ContactPoint::new(Arc::new(road.clone()));
    let (x, y) = cp.uv_to_xy(40.0, 1.0).unwrap();
    let o = road.global_origin();
    road.set_global_origin(opencrg_core::georef::GlobalOrigin { z: 0.0, ..o });
    let enh = road.xyz_to_enh(x, y, 3.0);
    assert_eq!(enh[2], 3.0);
    let back = road.enh_to_xyz(enh[0], enh[1], enh[2]);
    assert!((back[0] - x).abs() < 1e-9 && (back[1] - y).abs() < 1e-9);
    road.set_global_origin(Default::default());
    assert_eq!(road.xyz_to_enh(x, y, 3.0), [x, y, 3.0]);
}

#[test]
fn wgs84_round_trips_within_a_tenth_of_a_millimetre() {
    // Each map section with the global origin of a place near 48 N, 11.7 E in its projection.
    let sections = [
        ("PROJ_NM = 'UTM_32U'\n", 691_000.0, 5_322_000.0),
        ("LELL_NM = BESSELDHDN\nPROJ_NM = GK3_4\n", 4_478_800.0, 5_320_500.0),
        (
            "LELL_NM = 'BESSELDHDN'\nTRAN_NM = 'HN7'\nTRAN_DS = -5.2379e-6\nTRAN_RX = 3.4911e-6\nTRAN_RY = 5.391e-7\n\
             TRAN_RZ = -8.3432e-6\nTRAN_TX = -604.7365\nTRAN_TY = -72.3946\nTRAN_TZ = -424.402\nPROJ_NM = GK3_4\n",
            4_478_800.0,
            5_320_500.0,
        ),
        (
            "LELL_NM = USERDEFINED\nLELL_A = 6378000\nLELL_B = 6356000\nTRAN_NM = HL7\nTRAN_TX = 10\n\
             PROJ_NM = TM\nPROJ_F0 = 0.9999\nPROJ_P0 = 0.8\nPROJ_L0 = 0.2\nPROJ_E0 = 200000\nPROJ_N0 = -100000\n",
            218_000.0,
            140_000.0,
        ),
        ("LELL_NM = GRS1980AUTHALICSPHERE\nTRAN_NM = HS7\nTRAN_TZ = 3\nPROJ_NM = TM_11\n", 52_000.0, 5_320_000.0),
    ];
    for (extra, east, north) in sections {
        let header = format!(
            "$ROAD_CRG\nREFERENCE_LINE_OFFSET_X = {east}\nREFERENCE_LINE_OFFSET_Y = {north}\n$\n$ROAD_CRG_MPRO\n{extra}$\n"
        );
        let road = curved(&header).build().unwrap();
        let earth = Earth::of(&road).unwrap();
        for xyz in [[12.0, -3.0, 0.0], [250.0, 90.0, 31.5], [-1000.0, 4000.0, -20.0]] {
            let llh = earth.xyz_to_llh(&road, xyz).unwrap();
            assert!((47.0..49.5).contains(&llh[0]) && (11.0..13.0).contains(&llh[1]), "{extra}: {llh:?}");
            let back = earth.llh_to_xyz(&road, llh).unwrap();
            assert_close(&[xyz], &[back], 1e-4, extra);
        }
    }
    let plain = curved("").build().unwrap();
    assert!(matches!(Earth::of(&plain), Err(Error::OutOfRange(_))));
}

/// The error of loading a road whose map section has `extra` in it.
fn refusal(extra: &str) -> String {
    match Road::from_bytes(curved(&format!("$ROAD_CRG_MPRO\n{extra}$\n")).to_crg(), "bad.crg") {
        Ok(_) => panic!("accepted: {extra}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn nonsense_is_refused_naming_file_line_and_keyword() {
    // The section starts on line 18 of the generated header.
    let line_of = |e: &str| e.split(':').nth(1).and_then(|l| l.trim().parse::<usize>().ok());
    let e = refusal("GELL_NM = MARS1900\nPROJ_NM = UTM_32U\n");
    assert!(e.contains("bad.crg") && e.contains("GELL_NM") && e.contains("MARS1900"), "{e}");
    let first = line_of(&e).expect("a line number");
    let e = refusal("PROJ_NM = UTM_32I\n");
    assert!(e.contains("PROJ_NM") && e.contains("band letter 'I'"), "{e}");
    assert_eq!(line_of(&e), Some(first));
    let e = refusal("LELL_NM = USERDEFINED\nPROJ_NM = TM_3\n");
    assert!(e.contains("LELL_NM") && e.contains("LELL_A"), "{e}");
    let e = refusal("PROJ_NM = 'MERCATOR'\n");
    assert!(e.contains("unknown projection"), "{e}");
    let e = refusal("TRAN_NM = HX7\nPROJ_NM = TM\n");
    assert!(e.contains("TRAN_NM") && e.contains("HX7"), "{e}");
    let e = refusal("GELL_A = abc\nPROJ_NM = TM\n");
    assert!(e.contains("GELL_A") && e.contains("not a finite number"), "{e}");
    let e = refusal("LELL_NM = BESSEL1841\n");
    assert!(e.contains("names no projection"), "{e}");
    assert_eq!(line_of(&e), Some(first));
}

#[test]
fn every_new_keyword_is_written_back_in_every_format() {
    let header = format!(
        "{PLACE}$ROAD_CRG\nREFERENCE_LINE_START_LAT = 48.0233\nREFERENCE_LINE_START_LON = 11.7158\n\
         REFERENCE_LINE_START_ALT = 584.5\nREFERENCE_LINE_END_LAT = 48.0251\nREFERENCE_LINE_END_LON = 11.7189\n\
         REFERENCE_LINE_END_ALT = 590.0\n$\n$ROAD_CRG_MPRO\nGELL_NM = WGS84\nLELL_NM = 'USERDEFINED'\nLELL_A = 6377397.155\n\
         LELL_B = 6356078.96\nTRAN_NM = HN7\nTRAN_DS = 1e-6\nTRAN_RX = 1e-6\nTRAN_RY = 2e-6\nTRAN_RZ = 3e-6\nTRAN_TX = 1\n\
         TRAN_TY = 2\nTRAN_TZ = 3\nPROJ_NM = TM\nPROJ_F0 = 0.9996\nPROJ_P0 = 0.1\nPROJ_L0 = 0.15\nPROJ_E0 = 500000\n\
         PROJ_N0 = 10\n$\n"
    );
    let road = curved(&header).build().unwrap();
    let dir = std::env::temp_dir().join(format!("opencrg-georef-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for format in [DataFormat::Lrfi, DataFormat::Ldfi, DataFormat::Krbi, DataFormat::Kdbi] {
        let path = dir.join(format!("{}.crg", format.name()));
        opencrg_core::write(&road, &path, format).unwrap();
        let back = Road::load(&path).unwrap();
        assert_eq!(back.header().mpro, road.header().mpro, "{format:?}");
        assert_eq!(back.header().map, road.header().map, "{format:?}");
        assert_eq!(back.header().road.offset, road.header().road.offset, "{format:?}");
        assert_eq!(back.global_origin(), road.global_origin(), "{format:?}");
        for end in [false, true] {
            assert_eq!(back.header().road.wgs84(end), road.header().road.wgs84(end), "{format:?}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn wgs84_keywords_are_checked_against_the_road() {
    // No projection: the geodesic start-to-end distance against the x/y one (300 m east).
    let keywords = |east_m: f64| {
        let lon_end = 11.0 + east_m / (111_319.49 * 48f64.to_radians().cos());
        format!(
            "$ROAD_CRG\nREFERENCE_LINE_START_LAT = 48.0\nREFERENCE_LINE_START_LON = 11.0\n\
             REFERENCE_LINE_END_LAT = 48.0\nREFERENCE_LINE_END_LON = {lon_end}\n$\n"
        )
    };
    let straight = |header: &str| RoadSpec::straight(300.0, 4.0, 0.5, 0.5).with_header_text(header).build().unwrap();
    assert!(opencrg_core::map_disagreements(&straight(&keywords(300.0))).is_empty());
    let found = opencrg_core::map_disagreements(&straight(&keywords(330.0)));
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("CHECK_WGS") && found[0].contains("300.000 m"), "{}", found[0]);
    // A tolerance of 50 m lets the 30 m pass.
    let tolerant = format!("{}$ROAD_CRG_OPTS\nCHECK_WGS = 50\n$\n", keywords(330.0));
    assert!(opencrg_core::map_disagreements(&straight(&tolerant)).is_empty());

    // With a projection: each given position against the line's own start and end.
    let road = curved(&utm("")).build().unwrap();
    let earth = Earth::of(&road).unwrap();
    let l = road.reference_line();
    let start = earth.xyz_to_llh(&road, [l.x[0], l.y[0], l.z_at(0)]).unwrap();
    let given = |lat: f64| {
        format!(
            "{}$ROAD_CRG\nREFERENCE_LINE_START_LAT = {lat}\nREFERENCE_LINE_START_LON = {}\n\
             REFERENCE_LINE_START_ALT = {}\n$\n",
            utm(""),
            start[1],
            start[2]
        )
    };
    assert!(opencrg_core::map_disagreements(&curved(&given(start[0])).build().unwrap()).is_empty());
    let off = opencrg_core::map_disagreements(&curved(&given(start[0] + 1e-5)).build().unwrap());
    assert!(off.len() == 1 && off[0].contains("WGS 84 start") && off[0].contains("CHECK_PRO"), "{off:?}");
}
