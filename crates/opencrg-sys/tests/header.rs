//! The checked-in include/crgBaseLib.h must be what cbindgen generates now.
//! Run with OPENCRG_BLESS=1 to rewrite it.

use std::path::PathBuf;

#[test]
fn header_is_current() {
    let crate_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let header = crate_dir.join("../../include/crgBaseLib.h");
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(&crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen failed")
        .write(&mut generated);
    let generated = String::from_utf8(generated).unwrap();
    if std::env::var_os("OPENCRG_BLESS").is_some() {
        std::fs::write(&header, &generated).unwrap();
        return;
    }
    let current = std::fs::read_to_string(&header).unwrap_or_default();
    assert!(
        current == generated,
        "include/crgBaseLib.h is stale: run OPENCRG_BLESS=1 cargo test -p opencrg-sys --test header"
    );
}

/// `#define NAME VALUE` lines of the header whose name starts with `prefix`.
fn defines(header: &str, prefix: &str) -> Vec<(String, String)> {
    header
        .lines()
        .filter_map(|l| {
            let mut words = l.strip_prefix("#define ")?.split_whitespace();
            let name = words.next()?;
            let value = words.next()?;
            name.starts_with(prefix).then(|| (name.to_string(), value.to_string()))
        })
        .collect()
}

#[test]
fn setting_constants_match_the_settings_table() {
    let crate_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let header = std::fs::read_to_string(crate_dir.join("../../include/crgBaseLib.h")).unwrap();
    let mut in_header: Vec<(String, String)> = defines(&header, "dCrgCpOption");
    in_header.extend(defines(&header, "dCrgMod"));
    assert_eq!(in_header.len(), opencrg_core::settings::SETTINGS.len(), "one constant per setting");
    for row in opencrg_core::settings::SETTINGS {
        let found = in_header.iter().find(|(name, _)| name == row.c_constant);
        let Some((_, value)) = found else { panic!("{} is not in crgBaseLib.h", row.c_constant) };
        assert_eq!(value, &row.id.to_string(), "{}", row.c_constant);
    }
    let size = defines(&header, "dCrgSizeOptList");
    assert_eq!(size, [("dCrgSizeOptList".to_string(), (opencrg_core::settings::TABLE_SIZE - 1).to_string())]);
}

/// The functions a header declares: a name followed by `(` after a return type, at the
/// start of a line.
fn declared(header: &str, prefix: &str) -> Vec<String> {
    let mut names: Vec<String> = header
        .lines()
        .filter(|l| l.starts_with("int ") || l.starts_with("void ") || l.starts_with("const "))
        .filter_map(|l| l.split('(').next()?.split([' ', '*']).next_back().map(str::to_string))
        .filter(|n| n.starts_with(prefix))
        .collect();
    names.sort();
    names
}

#[test]
fn the_opendrive_header_declares_exactly_the_opendrive_calls() {
    let crate_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let header = std::fs::read_to_string(crate_dir.join("../../include/crgOdr.h")).unwrap();
    let source = std::fs::read_to_string(crate_dir.join("src/odr.rs")).unwrap();
    let mut exported: Vec<String> = source
        .lines()
        .filter_map(|l| l.split("extern \"C\" fn ").nth(1))
        .filter_map(|rest| rest.split('(').next().map(str::to_string))
        .collect();
    exported.sort();
    let in_header = declared(&header, "crgOdr");
    assert!(exported.len() >= 8, "{exported:?}");
    assert_eq!(in_header, exported);
    // None of them in the classic header.
    let classic = std::fs::read_to_string(crate_dir.join("../../include/crgBaseLib.h")).unwrap();
    assert!(!classic.contains("crgOdr"));
}
