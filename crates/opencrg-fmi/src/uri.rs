//! FMI 2's resource location, a `file:` URI, as a path: percent-decoded (spaces,
//! non-ASCII), `file:///path`, `file:/path` and `file://localhost/path` alike; on
//! Windows `file:///C:/dir` is `C:/dir` and `file://server/share` a UNC path.
//! Importers that write the URI loosely are followed: raw spaces and other characters
//! taken as they are, a `%` without two hex digits after it taken as itself, a plain
//! absolute path without the scheme, and on Windows `file://C:/dir` (the drive as a host).

use std::path::PathBuf;

/// The path a `file:` URI names; `None` for another scheme or another machine's path.
pub fn file_path(uri: &str) -> Option<PathBuf> {
    let Some(rest) = strip_prefix_ignore_case(uri, "file:") else {
        // A plain absolute path given where a URI belongs.
        let path = PathBuf::from(uri);
        return (path.is_absolute() && !uri.contains("://")).then_some(path);
    };
    let (host, path) = match rest.strip_prefix("//") {
        Some(after) => match after.find('/') {
            Some(i) => (&after[..i], &after[i..]),
            None => (after, ""),
        },
        None => ("", rest),
    };
    let host = if host.eq_ignore_ascii_case("localhost") { "" } else { host };
    let path = String::from_utf8(decode(path)).ok()?;
    native(host, &path)
}

fn strip_prefix_ignore_case<'a>(text: &'a str, prefix: &str) -> Option<&'a str> {
    let head = text.get(..prefix.len())?;
    head.eq_ignore_ascii_case(prefix).then(|| &text[prefix.len()..])
}

/// Percent-decoding; a `%` not followed by two hex digits is itself.
fn decode(text: &str) -> Vec<u8> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = bytes.get(i + 1..i + 3).filter(|h| h.iter().all(u8::is_ascii_hexdigit));
        match (bytes[i], hex) {
            (b'%', Some(h)) => {
                out.push(u8::from_str_radix(std::str::from_utf8(h).unwrap_or("0"), 16).unwrap_or(0));
                i += 3;
            }
            (b, _) => {
                out.push(b);
                i += 1;
            }
        }
    }
    out
}

#[cfg(not(windows))]
fn native(host: &str, path: &str) -> Option<PathBuf> {
    // A host other than this machine names no local path.
    host.is_empty().then(|| PathBuf::from(path))
}

#[cfg(windows)]
fn native(host: &str, path: &str) -> Option<PathBuf> {
    // "file://C:/dir": the drive written as the host.
    let h = host.as_bytes();
    if h.len() == 2 && h[0].is_ascii_alphabetic() && (h[1] == b':' || h[1] == b'|') {
        return Some(PathBuf::from(format!("{}:{path}", &host[..1])));
    }
    if !host.is_empty() {
        return Some(PathBuf::from(format!(r"\\{host}{}", path.replace('/', r"\"))));
    }
    // "/C:/dir" is the drive's path "C:/dir".
    let b = path.as_bytes();
    let drive = b.len() >= 3 && b[0] == b'/' && b[1].is_ascii_alphabetic() && (b[2] == b':' || b[2] == b'|');
    let path = if drive { format!("{}:{}", &path[1..2], &path[3..]) } else { path.to_string() };
    Some(PathBuf::from(path))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uris_decode() {
        assert_eq!(decode("a%20b%C3%A9"), "a bé".as_bytes().to_vec());
        assert_eq!(decode("100%"), b"100%".to_vec());
        assert_eq!(decode("%zz%4"), b"%zz%4".to_vec());
        assert_eq!(file_path("http://x/y"), None);
        assert_eq!(file_path("relative/dir"), None);
        assert_eq!(file_path("file:///tmp/x%25y"), file_path("file:/tmp/x%25y"));
    }

    #[cfg(not(windows))]
    #[test]
    fn unix_paths() {
        for uri in ["file:///tmp/a%20b/r%C3%A9s/", "file:/tmp/a%20b/r%C3%A9s/", "FILE://localhost/tmp/a%20b/r%C3%A9s/"]
        {
            assert_eq!(file_path(uri), Some(PathBuf::from("/tmp/a b/rés/")), "{uri}");
        }
        assert_eq!(file_path("file://elsewhere/tmp"), None);
        // Written loosely: raw spaces and accents, a lone %, no scheme.
        assert_eq!(file_path("file:///tmp/a b/rés/"), Some(PathBuf::from("/tmp/a b/rés/")));
        assert_eq!(file_path("file:///tmp/100% sure/"), Some(PathBuf::from("/tmp/100% sure/")));
        assert_eq!(file_path("/tmp/a b/"), Some(PathBuf::from("/tmp/a b/")));
    }

    #[cfg(windows)]
    #[test]
    fn windows_paths() {
        assert_eq!(file_path("file:///C:/Temp/a%20b/"), Some(PathBuf::from("C:/Temp/a b/")));
        assert_eq!(file_path("file://server/share/x"), Some(PathBuf::from(r"\\server\share\x")));
        assert_eq!(file_path("file://C:/Temp/a b/"), Some(PathBuf::from("C:/Temp/a b/")));
        assert_eq!(file_path(r"C:\Temp\a b"), Some(PathBuf::from(r"C:\Temp\a b")));
    }
}
