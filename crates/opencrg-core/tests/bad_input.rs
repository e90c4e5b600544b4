//! Broken inputs: each is refused with an error that says what and where, or (for
//! what the reference library reads) loaded.

use opencrg_core::synth::RoadSpec;
use opencrg_core::Road;

fn small() -> RoadSpec {
    RoadSpec::straight(10.0, 2.0, 1.0, 0.5).with_heading(|u| 0.01 * u).with_elevation(|u, v| 0.1 * u + v)
}

/// A small LRFI file around the given $ROAD_CRG body and data rows (3 channels: phi, 2 sections).
fn lrfi(road: &str, rows: &[&str]) -> Vec<u8> {
    let mut s = format!(
        "$CT\ntest road\n$\n$ROAD_CRG\n{road}\n$\n$KD_Definition\n#:LRFI\nD:reference line phi,rad\nD:long section at v = -1.0,m\nD:long section at v = 1.0,m\n$\n$$$$$$$$$$\n"
    );
    for r in rows {
        s.push_str(r);
        s.push('\n');
    }
    s.into_bytes()
}

const OK_ROAD: &str = "REFERENCE_LINE_START_U = 0\nREFERENCE_LINE_INCREMENT = 1.0";
const ROWS: [&str; 3] =
    [" 0.0000000 0.0000000 0.0000000", " 0.0100000 0.1000000 0.2000000", " 0.0200000 0.2000000 0.3000000"];

fn err_of(bytes: Vec<u8>) -> String {
    match Road::from_bytes(bytes, "bad.crg") {
        Ok(_) => "loaded".to_string(),
        Err(e) => e.to_string(),
    }
}

fn tmp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("opencrg-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

#[test]
fn the_good_file_loads() {
    assert_eq!(err_of(lrfi(OK_ROAD, &ROWS)), "loaded");
}

#[test]
fn bad_inputs_are_refused_with_a_clear_error() {
    let full = small().to_crg();
    let data_start = full
        .windows(81)
        .position(|w| w == [b'$'; 80].iter().chain(b"\n").copied().collect::<Vec<_>>().as_slice())
        .unwrap()
        + 81;
    let mut truncated_binary = full.clone();
    truncated_binary.truncate(data_start + 100);
    let with_end_u = |end: &str| -> Vec<u8> {
        let head = String::from_utf8(full[..data_start].to_vec())
            .unwrap()
            .replace("REFERENCE_LINE_END_U = 10.0", &format!("REFERENCE_LINE_END_U = {end}"));
        head.into_bytes().into_iter().chain(full[data_start..].iter().copied()).collect()
    };
    let mut garbage: Vec<u8> = (0..4096u32).map(|i| (i.wrapping_mul(2654435761) >> 13) as u8).collect();
    garbage[0] = b'%';
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("truncated binary data", truncated_binary, "the header declares"),
        ("a header declaring 10^12 rows", with_end_u("1e12"), "the header declares"),
        ("a size that overflows", with_end_u("1e308"), "the header declares"),
        ("truncated text record", lrfi(OK_ROAD, &[ROWS[0], ROWS[1], " 0.0200000 0.20"]), "data record 3, channel 2"),
        ("wrong channel count", lrfi(OK_ROAD, &[" 0.0000000 0.0000000", " 0.0100000 0.1000000"]), "record ends after"),
        (
            "zero increment",
            lrfi("REFERENCE_LINE_INCREMENT = 0.0", &ROWS),
            "REFERENCE_LINE_INCREMENT: increment 0 must be positive",
        ),
        ("negative increment", lrfi("REFERENCE_LINE_INCREMENT = -1", &ROWS), "must be positive"),
        (
            "end before start",
            lrfi("REFERENCE_LINE_START_U = 5\nREFERENCE_LINE_END_U = 1", &ROWS),
            "is not after start u",
        ),
        (
            "NaN in the heading channel",
            lrfi(OK_ROAD, &[ROWS[0], " ********* 0.1000000 0.2000000", ROWS[2]]),
            "data record 2, channel 1: reference line phi: heading is NaN",
        ),
        ("NaN in a header value", lrfi("REFERENCE_LINE_INCREMENT = nan", &ROWS), "must be finite"),
        (
            "infinity in a header value",
            lrfi("REFERENCE_LINE_START_X = -inf", &ROWS),
            "REFERENCE_LINE_START_X: value must be finite",
        ),
        (
            "not a number in a header value",
            lrfi("REFERENCE_LINE_START_Y = north", &ROWS),
            "bad.crg:5: REFERENCE_LINE_START_Y: 'north' is not a number",
        ),
        ("a header without data", b"$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 1\n$\n".to_vec(), "no data section"),
        (
            "one long section",
            lrfi(OK_ROAD, &ROWS).replace_str("D:long section at v = 1.0,m\n", ""),
            "at least 2 are needed",
        ),
        ("two sections at the same v", lrfi(OK_ROAD, &ROWS).replace_str("v = 1.0", "v = -1.0"), "same v"),
        ("unknown unit", lrfi(OK_ROAD, &ROWS).replace_str("v = 1.0,m", "v = 1.0,ft"), "$KD_Definition"),
        ("only one cross section", lrfi(OK_ROAD, &ROWS[..1]), "at least 2 are needed"),
        ("binary garbage", garbage, "no data section"),
        (
            "an unknown data format",
            lrfi(OK_ROAD, &ROWS).replace_str("#:LRFI", "#:LRXI"),
            "bad.crg:9: $KD_Definition: unknown data format 'LRXI'",
        ),
        ("an empty file", Vec::new(), "is empty"),
    ];
    for (what, bytes, expected) in cases {
        let e = err_of(bytes);
        assert!(e.contains(expected), "{what}: got <{e}>, expected it to contain <{expected}>");
        assert!(e.contains("bad.crg"), "{what}: the message must name the file: <{e}>");
    }
}

trait ReplaceStr {
    fn replace_str(self, from: &str, to: &str) -> Vec<u8>;
}

impl ReplaceStr for Vec<u8> {
    fn replace_str(self, from: &str, to: &str) -> Vec<u8> {
        String::from_utf8(self).unwrap().replace(from, to).into_bytes()
    }
}

#[test]
fn missing_files_directories_and_reference_loops() {
    let e = Road::load(tmp("does-not-exist.crg")).unwrap_err().to_string();
    assert!(e.contains("does-not-exist.crg") && e.contains("No such file"), "{e}");
    let e = Road::load(std::env::temp_dir()).unwrap_err().to_string();
    assert!(e.contains("is a directory"), "{e}");

    let (a, b) = (tmp("loop_a.crg"), tmp("loop_b.crg"));
    std::fs::write(&a, format!("$ROAD_CRG_FILE\n{}\n$\n", b.display())).unwrap();
    std::fs::write(&b, format!("$ROAD_CRG_FILE\n{}\n$\n", a.display())).unwrap();
    let e = Road::load(&a).unwrap_err().to_string();
    assert!(e.contains("loop"), "{e}");

    // a chain of references deeper than the limit
    let depth = opencrg_core::reader::MAX_REFERENCE_DEPTH + 3;
    for i in 0..depth {
        std::fs::write(
            tmp(&format!("chain{i}.crg")),
            format!("$ROAD_CRG_FILE\n{}\n$\n", tmp(&format!("chain{}.crg", i + 1)).display()),
        )
        .unwrap();
    }
    let e = Road::load(tmp("chain0.crg")).unwrap_err().to_string();
    assert!(e.contains("nest deeper"), "{e}");

    let missing = tmp("refers_to_missing.crg");
    std::fs::write(&missing, "$ROAD_CRG_FILE\n  $OPENCRG_SURELY_UNSET_VAR/x.crg\n$\n").unwrap();
    let e = Road::load(&missing).unwrap_err().to_string();
    assert!(e.contains("OPENCRG_SURELY_UNSET_VAR"), "{e}");
}

#[test]
fn what_the_reference_reads_loads() {
    // ISO-8859-1 bytes and invalid UTF-8 in comments, comment lines far over 72 characters.
    let mut bytes = b"$CT\nStra\xdfe in K\xf6ln \xff\xfe\n".to_vec();
    bytes.extend(std::iter::repeat_n(b'x', 5000));
    bytes.extend(b"\n$\n");
    bytes.extend(lrfi(OK_ROAD, &ROWS));
    let road = Road::from_bytes(bytes, "latin1.crg").expect("loads");
    assert!(road.header().comments[0].contains("Straße in Köln"));
    assert_eq!(road.grid().nu, 3);

    // Keywords in any case, '!' comments, '*' comment lines, numbers touching.
    let text = lrfi(
        "reference_line_start_u = 2.0 ! start\n* a comment\nReference_Line_Increment=0.5",
        &[" 0.0000000-1.0000000-2.0000000", " 0.0100000 1.0000000 2.0000000"],
    );
    let road = Road::from_bytes(text, "case.crg").unwrap();
    assert_eq!(road.u_range(), (2.0, 2.5));
    assert_eq!(road.grid().at(0, 0), -1.0);
}

#[test]
fn v_sections_out_of_order_are_sorted_as_the_reference_does() {
    let text = lrfi(OK_ROAD, &ROWS).replace_str(
        "D:long section at v = -1.0,m\nD:long section at v = 1.0,m",
        "D:long section at v = 1.0,m\nD:long section at v = -1.0,m",
    );
    let road = Road::from_bytes(text, "swapped.crg").unwrap();
    assert_eq!(road.v_range(), (-1.0, 1.0));
    // the column written first (v = 1) holds 0.1 in the second row
    assert_eq!(road.grid().at(1, 1), 0.1);
    assert_eq!(road.grid().at(1, 0), 0.2);
}

#[test]
fn a_header_with_200000_channels_stays_bounded() {
    let mut h = String::from("$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 1\nREFERENCE_LINE_END_U = 1\nLONG_SECTION_V_RIGHT = 0\nLONG_SECTION_V_INCREMENT = 0.001\n$\n$KD_Definition\n#:KRBI\n");
    for i in 1..=200_000 {
        h.push_str(&format!("D:long section {i},m\n"));
    }
    h.push_str("$\n$$$$$$$$\n");
    let mut bytes = h.into_bytes();
    bytes.extend(std::iter::repeat_n(0u8, 200_000 * 4 * 2));
    let t = std::time::Instant::now();
    let road = Road::from_bytes(bytes, "wide.crg").unwrap();
    println!("200000 channels loaded in {:?}", t.elapsed());
    assert_eq!(road.grid().nv, 200_000);
}
