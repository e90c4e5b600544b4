//! Files the reference loads without a word although they are not what their author
//! meant: they load the same way here, with a warning naming the file, line and word.

use opencrg_core::Road;

fn text_road(road_section: &str, rows: usize) -> String {
    let mut s = format!("{road_section}\nREFERENCE_LINE_START_U = 0.0\nREFERENCE_LINE_END_U = 4.0\n");
    s += "REFERENCE_LINE_INCREMENT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\n";
    s += "REFERENCE_LINE_END_X = 4.0\nREFERENCE_LINE_END_Y = 0.0\n$\n";
    s += "$KD_Definition\n#:LRFI\nD:long section 1,m\nD:long section 2,m\n$\n";
    s += &"$".repeat(80);
    s.push('\n');
    for i in 0..rows {
        s += &format!("{:10.4}{:10.4}\n", i as f64 * 0.1, i as f64 * 0.1);
    }
    s
}

fn load(text: &str) -> Road {
    Road::from_bytes(text.as_bytes().to_vec(), "road.crg").unwrap()
}

#[test]
fn misspelt_keyword() {
    let road = load(&text_road("$ROAD_CRG", 5).replace("REFERENCE_LINE_INCREMENT", "REFERENCE_LINE_INCREMNT"));
    assert!(
        road.warnings().iter().any(|w| w.starts_with("road.crg:4:") && w.contains("'REFERENCE_LINE_INCREMNT'")),
        "{:?}",
        road.warnings()
    );
    // Loaded as the reference loads it: with the default increment.
    assert_eq!(road.increments().0, 0.01);
}

#[test]
fn misspelt_section() {
    let road = load(&text_road("$ROAD_CGR", 5));
    assert!(
        road.warnings().iter().any(|w| w.starts_with("road.crg:1:") && w.contains("'ROAD_CGR'")),
        "{:?}",
        road.warnings()
    );
    assert_eq!(road.u_range(), (0.0, 0.04));
}

#[test]
fn text_data_ending_before_the_declared_end() {
    let road = load(&text_road("$ROAD_CRG", 3));
    assert_eq!(road.u_range(), (0.0, 2.0));
    assert!(road.warnings().iter().any(|w| w.contains("3 records") && w.contains("END_U")), "{:?}", road.warnings());
    // A complete file and the usual `$` and `$!` lines give no warning.
    let road = load(&text_road("$!***\n$ROAD_CRG", 5));
    assert!(road.warnings().is_empty(), "{:?}", road.warnings());
}

#[test]
fn option_keywords_the_reference_does_not_know() {
    // CHECK_PRO and CHECK_WGS (written by the MATLAB tools) are unknown to the reference,
    // which warns and ignores them; its logging options it knows and ignores quietly.
    let opts = "$ROAD_CRG_OPTS\nCHECK_PRO = 0.005\nLOG_STAT = -1\nCHECK_WGS = 10\n$\n$ROAD_CRG";
    let road = load(&text_road(opts, 5));
    let warned: Vec<&String> = road.warnings().iter().filter(|w| w.contains("unknown keyword")).collect();
    assert_eq!(warned.len(), 2, "{:?}", road.warnings());
    assert!(warned[0].starts_with("road.crg:2: CHECK_PRO"), "{:?}", warned);
    assert!(warned[1].starts_with("road.crg:4: CHECK_WGS"), "{:?}", warned);
}
