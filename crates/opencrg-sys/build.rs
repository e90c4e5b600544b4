//! Builds the C shim that formats `crgMsgPrint`'s variadic arguments.
fn main() {
    println!("cargo:rerun-if-changed=csrc/msg_shim.c");
    cc::Build::new().file("csrc/msg_shim.c").warnings(true).extra_warnings(true).compile("opencrg_shim");
}
