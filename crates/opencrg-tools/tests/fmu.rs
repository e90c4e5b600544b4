//! Packing roads as FMUs: what the zip holds, the same bytes for the same road, a map's
//! CRG files wherever the map names them, references kept, refusals that write nothing.

use opencrg_fmu::{Config, Fmi};
use opencrg_tools::fmu::{write_fmu, Binary, FmuOptions, Platform};
use std::io::Read;
use std::path::{Path, PathBuf};

fn demo(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/data").join(name)
}

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("opencrg-fmu-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A stand-in binary (packing copies it, nothing runs it here).
fn options(d: &Path, fmi: Fmi, wheels: u32) -> FmuOptions {
    let file = d.join("libstand_in.so");
    std::fs::write(&file, b"not a library").unwrap();
    FmuOptions { wheels, fmi, binaries: vec![Binary { platform: Platform::LinuxX86_64, file }], outside: false }
}

/// The zip's entries: names and contents.
fn entries(fmu: &Path) -> Vec<(String, Vec<u8>)> {
    let mut zip = zip::ZipArchive::new(std::fs::File::open(fmu).unwrap()).unwrap();
    (0..zip.len())
        .map(|i| {
            let mut f = zip.by_index(i).unwrap();
            let mut bytes = Vec::new();
            f.read_to_end(&mut bytes).unwrap();
            (f.name().unwrap().to_string(), bytes)
        })
        .collect()
}

fn text(entries: &[(String, Vec<u8>)], name: &str) -> String {
    String::from_utf8(entries.iter().find(|e| e.0 == name).unwrap_or_else(|| panic!("no {name}")).1.clone()).unwrap()
}

#[test]
fn a_crg_file_is_packed_with_its_description_resources_and_binary_the_same_each_time() {
    let d = dir("crg");
    let report = write_fmu(&demo("demo_road.crg"), &d.join("a.fmu"), &options(&d, Fmi::V2, 4)).unwrap();
    assert_eq!(report.identifier, "demo_road");
    assert_eq!(report.variables, 11 + 4 * 13);
    let got = entries(&d.join("a.fmu"));
    let names: Vec<&str> = got.iter().map(|e| e.0.as_str()).collect();
    assert_eq!(
        names,
        [
            "modelDescription.xml",
            "resources/road/demo_road.crg",
            "resources/opencrg-fmu.txt",
            "binaries/linux64/demo_road.so"
        ]
    );
    assert_eq!(got[1].1, std::fs::read(demo("demo_road.crg")).unwrap());
    let config = Config::parse(&text(&got, "resources/opencrg-fmu.txt"), Path::new("c")).unwrap();
    let description = text(&got, "modelDescription.xml");
    assert!(description.contains(&format!("guid=\"{}\"", config.token)), "the token ties them");
    assert!(description.contains("name=\"wheel[4].curvature\"") && !description.contains("wheel[5]"));
    assert!(description.contains("numberOfEventIndicators=\"4\""), "one event indicator per wheel");
    // The same road packed alike: the same bytes.
    write_fmu(&demo("demo_road.crg"), &d.join("b.fmu"), &options(&d, Fmi::V2, 4)).unwrap();
    assert_eq!(std::fs::read(d.join("a.fmu")).unwrap(), std::fs::read(d.join("b.fmu")).unwrap());
    // FMI 3: the platform tuple, the time, another token.
    write_fmu(&demo("demo_road.crg"), &d.join("c.fmu"), &options(&d, Fmi::V3, 1)).unwrap();
    let three = entries(&d.join("c.fmu"));
    assert!(three.iter().any(|e| e.0 == "binaries/x86_64-linux/demo_road.so"));
    let description = text(&three, "modelDescription.xml");
    assert!(description.contains("fmiVersion=\"3.0\"") && description.contains("causality=\"independent\""));
    assert!(!description.contains(&config.token));
    assert!(description.contains("friction under 1 wheel\""), "one wheel, not one wheels");
    assert!(description.contains("<EventIndicator valueReference=\"116\" dependencies=\"100 101\""));
}

#[test]
fn a_maps_crg_files_are_packed_wherever_the_map_names_them() {
    let d = dir("map");
    std::fs::create_dir_all(d.join("maps")).unwrap();
    std::fs::create_dir_all(d.join("surfaces")).unwrap();
    std::fs::copy(demo("demo_road.crg"), d.join("surfaces/patch.crg")).unwrap();
    // The demo map's record, its file named up and across, and again by an absolute path.
    let map = std::fs::read_to_string(demo("demo_map.xodr")).unwrap();
    let record = map.find("file=\"demo_road.crg\"").expect("the demo map names demo_road.crg");
    let absolute = d.join("surfaces/patch.crg");
    let twice = map[..record].to_string() + "file=\"../surfaces/patch.crg\"" + &map[record + 20..];
    assert!(twice.contains("../surfaces/patch.crg"));
    std::fs::write(d.join("maps/town.xodr"), &twice).unwrap();
    let report = write_fmu(&d.join("maps/town.xodr"), &d.join("town.fmu"), &options(&d, Fmi::V3, 2)).unwrap();
    assert_eq!(report.resources, ["road/town.xodr", "crg/1/patch.crg", "opencrg-fmu.txt"]);
    let got = entries(&d.join("town.fmu"));
    assert!(text(&got, "modelDescription.xml").contains("with 1 CRG file: height, normal and friction under 2 wheels"));
    let config = Config::parse(&text(&got, "resources/opencrg-fmu.txt"), Path::new("c")).unwrap();
    assert_eq!(config.crg, [("../surfaces/patch.crg".to_string(), "crg/1/patch.crg".to_string())]);
    let abs_map = map[..record].to_string() + &format!("file=\"{}\"", absolute.display()) + &map[record + 20..];
    std::fs::write(d.join("maps/abs.xodr"), abs_map).unwrap();
    write_fmu(&d.join("maps/abs.xodr"), &d.join("abs.fmu"), &options(&d, Fmi::V2, 2)).unwrap();
    let got = entries(&d.join("abs.fmu"));
    assert!(got.iter().any(|e| e.0 == "resources/crg/1/patch.crg"));
}

#[test]
fn refusals_name_the_file_and_write_nothing() {
    let d = dir("refused");
    let map = std::fs::read_to_string(demo("demo_map.xodr")).unwrap().replace("demo_road.crg", "missing.crg");
    std::fs::write(d.join("lacking.xodr"), map).unwrap();
    let out = d.join("lacking.fmu");
    let e = write_fmu(&d.join("lacking.xodr"), &out, &options(&d, Fmi::V2, 4)).unwrap_err().to_string();
    assert!(e.contains("lacking.xodr") && e.contains("missing.crg"), "{e}");
    assert!(!out.exists() && !d.join("lacking.fmu.partial").exists());
    let e = write_fmu(&demo("demo_road.crg"), &out, &options(&d, Fmi::V2, 0)).unwrap_err().to_string();
    assert!(e.contains("0 wheels"), "{e}");
    let none = FmuOptions { binaries: Vec::new(), ..options(&d, Fmi::V2, 4) };
    let e = write_fmu(&demo("demo_road.crg"), &out, &none).unwrap_err().to_string();
    assert!(e.contains("no FMU binary"), "{e}");
    std::fs::write(d.join("broken.crg"), "$ROAD_CRG\nthis is not a road\n").unwrap();
    assert!(write_fmu(&d.join("broken.crg"), &out, &options(&d, Fmi::V2, 4)).is_err());
    assert!(!out.exists());
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_a_crg_file_referencing_another_is_packed_with_it() {
    let d = dir("references");
    let conformance = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/conformance");
    // fileref.crg names ../crg-txt/handmade_curved_banked_sloped.crg.
    let report =
        write_fmu(&conformance.join("crg-txt/fileref.crg"), &d.join("r.fmu"), &options(&d, Fmi::V2, 1)).unwrap();
    assert_eq!(
        report.resources,
        ["road/crg-txt/fileref.crg", "road/crg-txt/handmade_curved_banked_sloped.crg", "opencrg-fmu.txt"]
    );
}
