//! `$ROAD_CRG_FILE`: names split over lines, relative names resolved beside the
//! referencing file, `$VARIABLE` expansion, and which options and modifiers win.

use opencrg_core::settings::{m, opt};
use opencrg_core::synth::RoadSpec;
use opencrg_core::Road;
use std::path::PathBuf;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("opencrg-refs-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A data file carrying its own options and modifiers.
fn data_file(d: &std::path::Path) -> PathBuf {
    let spec = RoadSpec::straight(10.0, 2.0, 0.5, 0.5)
        .with_elevation(|u, _| 0.1 * u)
        .with_header_text("$ROAD_CRG_OPTS\nBORDER_MODE_U = 3\n$\n$ROAD_CRG_MODS\nSCALE_Z_GRID = 2.0\n$\n");
    let p = d.join("surface_data.crg");
    std::fs::write(&p, spec.to_crg()).unwrap();
    p
}

#[test]
fn split_names_resolve_beside_the_referencing_file() {
    let d = dir("split");
    data_file(&d);
    let top = d.join("top.crg");
    std::fs::write(
        &top,
        "$CT\nrefers to the data\n$\n$ROAD_CRG_FILE\n* a comment\n  surface_  ! first part\n  data.crg\n$\n",
    )
    .unwrap();
    // The working folder is not `d`: the name is found beside top.crg.
    let road = Road::load(&top).unwrap();
    assert_eq!(road.u_range(), (0.0, 10.0));
    assert_eq!(road.header().references, vec![d.join("surface_data.crg")]);
    // Without sections of its own, the referenced file's options and modifiers count.
    assert_eq!(road.options().get_int(opt::BORDER_MODE_U), Some(3));
    assert_eq!(road.modifiers().get_double(m::SCALE_Z), Some(2.0));
}

#[test]
fn the_referencing_file_wins_and_an_empty_section_means_none() {
    let d = dir("wins");
    let data = data_file(&d);
    let top = d.join("top.crg");
    std::fs::write(
        &top,
        format!("$ROAD_CRG_FILE\n{}\n$\n$ROAD_CRG_OPTS\nBORDER_MODE_V = 1\n$\n$ROAD_CRG_MODS\n$\n", data.display()),
    )
    .unwrap();
    let road = Road::load(&top).unwrap();
    // The top file's options replace the referenced file's (over the defaults) ...
    assert_eq!(road.options().get_int(opt::BORDER_MODE_V), Some(1));
    assert_eq!(road.options().get_int(opt::BORDER_MODE_U), Some(2));
    // ... and its empty modifier section means no modifiers at all.
    assert_eq!(road.modifiers().iter().count(), 0);
}

#[test]
fn variables_expand() {
    let d = dir("vars");
    data_file(&d);
    std::env::set_var("OPENCRG_TEST_ROAD_DIR", &d);
    // in column 1 (the reference would end the section there) and indented
    for line in ["$OPENCRG_TEST_ROAD_DIR/surface_data.crg", "   $OPENCRG_TEST_ROAD_DIR/surface_data.crg ! comment"] {
        let top = d.join("top.crg");
        std::fs::write(&top, format!("$ROAD_CRG_FILE\n{line}\n$!****\n")).unwrap();
        assert_eq!(Road::load(&top).unwrap().u_range(), (0.0, 10.0), "{line}");
    }
}

/// References read from files held in memory: by the path beside the referencing name, as
/// written, or by the last path component; none read from disk; a file not given named.
#[test]
fn references_are_read_from_files_held_in_memory() {
    let d = dir("memory");
    let data = std::fs::read(data_file(&d)).unwrap();
    let top = "$ROAD_CRG_FILE\n ../data/surface_data.crg\n$\n".as_bytes().to_vec();
    let from_disk = {
        std::fs::create_dir_all(d.join("top")).unwrap();
        std::fs::create_dir_all(d.join("data")).unwrap();
        std::fs::write(d.join("data/surface_data.crg"), &data).unwrap();
        std::fs::write(d.join("top/top.crg"), &top).unwrap();
        Road::load(d.join("top/top.crg")).unwrap()
    };
    for name in ["roads/data/surface_data.crg", "../data/surface_data.crg", "elsewhere/surface_data.crg"] {
        let files = [("unrelated.crg".to_string(), b"not a road".to_vec()), (name.to_string(), data.clone())];
        let road =
            Road::from_bytes_with_files(top.clone(), "roads/top/top.crg", &files, opencrg_core::Compat::default())
                .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(road.header().references, vec![PathBuf::from(name)]);
        assert_eq!(road.grid().values(), from_disk.grid().values(), "{name}");
        assert_eq!(road.options().get_int(opt::BORDER_MODE_U), Some(3));
    }
    // The file is on disk beside the name, but only the files given are read.
    let e = Road::from_bytes_with_files(top, d.join("top/top.crg"), &[], opencrg_core::Compat::default()).unwrap_err();
    assert!(e.to_string().contains("surface_data.crg") && e.to_string().contains("cannot read"), "{e}");
}
