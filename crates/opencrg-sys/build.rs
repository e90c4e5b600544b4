//! Builds the C shim that formats `crgMsgPrint`'s variadic arguments, and gives
//! the shared library its soname.
fn main() {
    println!("cargo:rerun-if-changed=csrc/msg_shim.c");
    cc::Build::new().file("csrc/msg_shim.c").warnings(true).extra_warnings(true).compile("opencrg_shim");
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libopencrg.so");
        // The variadic crgMsgPrint lives in the C shim; rustc exports only Rust symbols.
        let map = std::path::Path::new(&std::env::var("CARGO_MANIFEST_DIR").unwrap()).join("csrc/exports.map");
        println!("cargo:rerun-if-changed=csrc/exports.map");
        println!("cargo:rustc-cdylib-link-arg=-Wl,--version-script={}", map.display());
    }
}
