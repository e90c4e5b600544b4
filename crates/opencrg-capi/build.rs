//! What the platforms need beside the libraries themselves (rustc exports the API's
//! functions, and only those, everywhere):
//! - Linux: the soname `libopencrg.so.MAJOR`, with a link of that name beside the built
//!   library, so programs linked in the build tree find it at run time;
//! - Windows: the import library for MSVC's linker, `opencrg.lib` (rustc writes
//!   `libopencrg.dll.a` for MinGW itself), and the module-definition file `opencrg.def`,
//!   both of exactly the functions `crgBaseLib.h`, `crgBaseLibPrivate.h` and `crgOdr.h`
//!   declare, made from the headers and written beside the DLL.
use std::path::{Path, PathBuf};

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap());
    // OUT_DIR is <profile dir>/build/<crate>-<hash>/out; the library lands in <profile dir>.
    let profile_dir =
        std::env::var_os("OUT_DIR").map(PathBuf::from).and_then(|o| o.ancestors().nth(3).map(Path::to_path_buf));
    match std::env::var("CARGO_CFG_TARGET_OS").as_deref() {
        Ok("linux") => linux(profile_dir),
        Ok("windows") => windows(&manifest, profile_dir),
        _ => {}
    }
}

fn linux(profile_dir: Option<PathBuf>) {
    let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_else(|_| "2".into());
    let soname = format!("libopencrg.so.{major}");
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,{soname}");
    #[cfg(unix)]
    if let Some(dir) = profile_dir {
        let link = dir.join(&soname);
        if std::fs::symlink_metadata(&link).is_err() {
            let _ = std::os::unix::fs::symlink("libopencrg.so", &link);
        }
    }
    #[cfg(not(unix))]
    let _ = profile_dir;
}

fn windows(manifest: &Path, profile_dir: Option<PathBuf>) {
    let mut text = String::new();
    for name in ["crgBaseLib.h", "crgBaseLibPrivate.h", "crgOdr.h"] {
        let header = manifest.join("../../include").join(name);
        println!("cargo:rerun-if-changed={}", header.display());
        text += &std::fs::read_to_string(&header).unwrap_or_else(|e| panic!("{}: {e}", header.display()));
    }
    let mut names: Vec<&str> = text.lines().filter_map(declared_function).collect();
    names.sort_unstable();
    names.dedup();
    assert!(names.len() > 50, "only {} function declarations found in the headers", names.len());
    let mut def = String::from("; The functions of crgBaseLib.h, crgBaseLibPrivate.h and crgOdr.h, made from the headers by crates/opencrg-capi/build.rs.\nLIBRARY opencrg.dll\nEXPORTS\n");
    for name in &names {
        def.push_str("    ");
        def.push_str(name);
        def.push('\n');
    }
    if let Some(dir) = profile_dir {
        std::fs::write(dir.join("opencrg.def"), &def).unwrap();
        write_import_library(&dir.join("opencrg.lib"), &names);
    }
}

/// `opencrg.lib`: the short import library MSVC's `lib /def:` would make for `names`.
fn write_import_library(path: &Path, names: &[&str]) {
    use ar_archive_writer::{write_import_library, COFFShortExport, MachineTypes};
    let machine = match std::env::var("CARGO_CFG_TARGET_ARCH").as_deref() {
        Ok("aarch64") => MachineTypes::ARM64,
        Ok("x86") => MachineTypes::I386,
        _ => MachineTypes::AMD64,
    };
    let exports: Vec<COFFShortExport> = names
        .iter()
        .map(|name| COFFShortExport {
            name: name.to_string(),
            ext_name: None,
            symbol_name: None,
            import_name: None,
            export_as: None,
            ordinal: 0,
            noname: false,
            data: false,
            private: false,
            constant: false,
        })
        .collect();
    let mut out = std::io::Cursor::new(Vec::new());
    write_import_library(&mut out, "opencrg.dll", &exports, machine, false, false, &[])
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    std::fs::write(path, out.into_inner()).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
}

/// The name of the function a header line declares at its start (`int crgCheck(int
/// dataSetId);`): a return type, the name starting with `crg`, an opening parenthesis.
fn declared_function(line: &str) -> Option<&str> {
    if !line.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
        return None;
    }
    let open = line.find('(')?;
    let head = line[..open].trim_end();
    let name = &head[head.rfind([' ', '*'])? + 1..];
    (name.starts_with("crg") && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')).then_some(name)
}
