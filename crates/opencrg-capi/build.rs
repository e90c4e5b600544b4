//! Gives the shared library its versioned soname (`libopencrg.so.MAJOR`) and its export
//! list, with a link of that name beside the built library, so programs linked in the
//! build tree find it at run time.
fn main() {
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux") {
        let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_else(|_| "2".into());
        let soname = format!("libopencrg.so.{major}");
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,{soname}");
        // The variadic crgMsgPrint lives in opencrg-sys's C shim; rustc exports only Rust symbols.
        let map = std::path::Path::new(&std::env::var("CARGO_MANIFEST_DIR").unwrap()).join("exports.map");
        println!("cargo:rerun-if-changed=exports.map");
        println!("cargo:rustc-cdylib-link-arg=-Wl,--version-script={}", map.display());
        // OUT_DIR is <profile dir>/build/<crate>-<hash>/out; the library lands in <profile dir>.
        if let Some(profile_dir) = std::env::var_os("OUT_DIR")
            .map(std::path::PathBuf::from)
            .and_then(|o| o.ancestors().nth(3).map(|p| p.to_path_buf()))
        {
            let link = profile_dir.join(&soname);
            if std::fs::symlink_metadata(&link).is_err() {
                let _ = std::os::unix::fs::symlink("libopencrg.so", &link);
            }
        }
    }
}
