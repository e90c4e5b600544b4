//! What the oracle tests share: running another implementation's client program.

use std::io::Write;
use std::process::{Command, Stdio};

/// What `program args...` prints for `input` on its standard input (written beside the
/// reading, so that neither side waits on a full pipe).
pub fn answers(program: &str, args: &[&std::ffi::OsStr], input: String) -> String {
    let mut child = Command::new(program)
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap_or_else(|e| panic!("{program}: {e}"));
    let mut stdin = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap().unwrap();
    String::from_utf8(out.stdout).unwrap()
}
