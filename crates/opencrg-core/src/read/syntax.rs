//! Header syntax: lines, sections, keywords, numbers and channel definitions.
//!
//! CRG headers are ISO-8859-1 text. Lines are split on `\n` or `\r`; keywords are
//! case-insensitive; `!` starts an inline comment and a line whose first non-blank
//! character is `*` is a comment. Numbers are read like C's `atof`: the longest
//! numeric prefix counts, the rest of the field is ignored.

use crate::model::header::Channel;

/// The sections of a CRG header.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Section {
    /// Outside any section.
    None,
    /// `$CT`: free comment text.
    Comment,
    /// `$ROAD_CRG`: road parameters.
    Road,
    /// `$ROAD_CRG_OPTS`: default options.
    Options,
    /// `$ROAD_CRG_MODS`: modifiers.
    Modifiers,
    /// `$ROAD_CRG_MPRO`: processing data, kept as key/value pairs.
    Mpro,
    /// `$ROAD_CRG_FILE`: a reference to another CRG file.
    File,
    /// `$KD_Definition`: data format and channels.
    DataDef,
}

/// What a line starting with `$` means.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Tag {
    /// The start of a section (ending the previous one).
    Start(Section),
    /// `$$$$...`: the data section starts after this line.
    Data,
    /// Any other `$` line (`$`, `$!****`): ends the current section.
    End,
}

/// Classifies a header line; `None` when it does not start with `$`.
pub(crate) fn tag(line: &str) -> Option<Tag> {
    let t = line.trim_start_matches(' ');
    if !t.starts_with('$') {
        return None;
    }
    const TAGS: [(&str, Tag); 8] = [
        ("$ROAD_CRG_MODS", Tag::Start(Section::Modifiers)),
        ("$ROAD_CRG_OPTS", Tag::Start(Section::Options)),
        ("$ROAD_CRG_FILE", Tag::Start(Section::File)),
        ("$ROAD_CRG_MPRO", Tag::Start(Section::Mpro)),
        ("$ROAD_CRG", Tag::Start(Section::Road)),
        ("$CT", Tag::Start(Section::Comment)),
        ("$KD_DEFINITION", Tag::Start(Section::DataDef)),
        ("$$$$", Tag::Data),
    ];
    for (name, tag) in TAGS {
        if starts_with_ignore_case(t, name) {
            return Some(tag);
        }
    }
    Some(Tag::End)
}

/// Case-insensitive ASCII prefix test.
pub(crate) fn starts_with_ignore_case(s: &str, prefix: &str) -> bool {
    s.len() >= prefix.len() && s.as_bytes()[..prefix.len()].eq_ignore_ascii_case(prefix.as_bytes())
}

/// Decodes ISO-8859-1 bytes (every byte is one character).
pub(crate) fn latin1(bytes: &[u8]) -> String {
    bytes.iter().map(|&b| b as char).collect()
}

/// One header line: its 1-based number, its text without the terminator, and the offset after it.
pub(crate) struct Line<'a> {
    /// 1-based line number.
    pub number: usize,
    /// The bytes of the line, without `\r`/`\n`.
    pub bytes: &'a [u8],
    /// Offset of the first byte after the line and its terminator.
    pub end: usize,
}

/// Iterates over the lines of a buffer, starting at an offset.
pub(crate) struct Lines<'a> {
    buf: &'a [u8],
    pos: usize,
    number: usize,
}

impl<'a> Lines<'a> {
    /// Lines of `buf` from its start.
    pub(crate) fn new(buf: &'a [u8]) -> Self {
        Lines { buf, pos: 0, number: 0 }
    }
}

impl<'a> Iterator for Lines<'a> {
    type Item = Line<'a>;
    fn next(&mut self) -> Option<Line<'a>> {
        if self.pos >= self.buf.len() {
            return None;
        }
        let rest = &self.buf[self.pos..];
        let len = rest.iter().position(|&b| b == b'\n' || b == b'\r').unwrap_or(rest.len());
        let mut end = self.pos + len;
        // One terminator: "\r\n", "\n" or "\r".
        if end < self.buf.len() {
            if self.buf[end] == b'\r' && self.buf.get(end + 1) == Some(&b'\n') {
                end += 2;
            } else {
                end += 1;
            }
        }
        self.number += 1;
        let line = Line { number: self.number, bytes: &rest[..len], end };
        self.pos = end;
        Some(line)
    }
}

/// A comment line: empty, blank, or starting with `*` after blanks.
pub(crate) fn is_comment(line: &str) -> bool {
    let t = line.trim_start_matches([' ', '\t']);
    t.is_empty() || t.starts_with('*')
}

/// Removes an inline `!` comment.
pub(crate) fn strip_inline_comment(line: &str) -> &str {
    match line.find('!') {
        Some(i) => &line[..i],
        None => line,
    }
}

/// Reads a number like C's `atof`: blanks, then the longest prefix that is a decimal
/// number (`inf`, `infinity` and `nan` included). `None` when there is no such prefix.
pub(crate) fn parse_f64_prefix(s: &str) -> Option<f64> {
    let t = s.trim_start_matches([' ', '\t']);
    let b = t.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    for word in ["infinity", "inf", "nan"] {
        if starts_with_ignore_case(&t[i..], word) {
            let v = if word == "nan" { f64::NAN } else { f64::INFINITY };
            return Some(if b.first() == Some(&b'-') { -v } else { v });
        }
    }
    let digits_start = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    let mut mantissa_digits = i - digits_start;
    if i < b.len() && b[i] == b'.' {
        i += 1;
        let frac_start = i;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        mantissa_digits += i - frac_start;
    }
    if mantissa_digits == 0 {
        return None;
    }
    let mantissa_end = i;
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        let exp_start = j;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
        }
        if j > exp_start {
            i = j;
        }
    }
    let text = &t[..if i > mantissa_end { i } else { mantissa_end }];
    text.parse::<f64>().ok()
}

/// Reads an integer like C's `atoi`: blanks, sign, digits; `None` when there are no digits.
pub(crate) fn parse_i32_prefix(s: &str) -> Option<i32> {
    let t = s.trim_start_matches([' ', '\t']);
    let b = t.as_bytes();
    let mut i = 0;
    let neg = match b.first() {
        Some(b'-') => {
            i += 1;
            true
        }
        Some(b'+') => {
            i += 1;
            false
        }
        _ => false,
    };
    let start = i;
    let mut value: i64 = 0;
    while i < b.len() && b[i].is_ascii_digit() {
        value = (value * 10 + i64::from(b[i] - b'0')).min(i64::from(i32::MAX) + 1);
        i += 1;
    }
    if i == start {
        return None;
    }
    let v = if neg { -value } else { value };
    Some(v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32)
}

/// Splits `KEY = value ! comment` into a lower-case key and the value text.
pub(crate) fn key_value(line: &str) -> Option<(String, &str)> {
    let eq = line.find('=')?;
    let key = line[..eq].trim().to_ascii_lowercase();
    Some((key, &line[eq + 1..]))
}

/// Finds the table entry whose name is the longest prefix of `key`.
pub(crate) fn lookup<T: Copy>(table: &[(&'static str, T)], key: &str) -> Option<(&'static str, T)> {
    table.iter().filter(|(name, _)| key.starts_with(name)).max_by_key(|(name, _)| name.len()).copied()
}

/// Finds `token` (case-insensitively) in `s` before any `!`; returns the text after it.
fn find_token<'a>(s: &'a str, token: &str) -> Option<&'a str> {
    let s = strip_inline_comment(s);
    (0..s.len()).filter(|&i| s.is_char_boundary(i)).find_map(|i| {
        if starts_with_ignore_case(&s[i..], token) {
            Some(&s[i + token.len()..])
        } else {
            None
        }
    })
}

/// Parses a `D:` line into a channel; the error says what is wrong.
pub(crate) fn parse_channel(line: &str) -> Result<Channel, String> {
    let body = find_token(line, "D:").ok_or("not a channel definition")?;
    if let Some(rest) = find_token(body, "long section") {
        let (at, value_text) = match find_token(rest, "at v ") {
            Some(after) => (true, find_token(after, "=").ok_or("long section position lacks '='")?),
            None => (false, rest),
        };
        let value = parse_f64_prefix(value_text)
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("long section position '{}' is not a number", value_text.trim()))?;
        let unit = find_token(value_text, ",").ok_or("long section lacks a unit")?;
        if !unit.trim_start_matches(' ').starts_with('m') {
            return Err(format!("long section unit '{}' is not m", unit.trim()));
        }
        return Ok(if at { Channel::SectionAt(value) } else { Channel::SectionIndex(value) });
    }
    let rest = find_token(body, "reference line").ok_or("unknown channel definition")?;
    let kinds: [(&str, Channel, &str); 6] = [
        ("x", Channel::RefX, "m"),
        ("y", Channel::RefY, "m"),
        ("u", Channel::RefU, "m"),
        ("phi", Channel::RefPhi, "rad"),
        ("banking", Channel::RefBank, "m/m"),
        ("slope", Channel::RefSlope, "m/m"),
    ];
    let name = rest.split(',').next().unwrap_or("").trim();
    let (chan, unit) = kinds
        .iter()
        .find(|(n, _, _)| name.eq_ignore_ascii_case(n))
        .map(|(_, c, u)| (*c, *u))
        .ok_or_else(|| format!("unknown reference line channel '{name}'"))?;
    let unit_text = find_token(rest, ",").ok_or("reference line channel lacks a unit")?;
    if find_token(unit_text, unit).is_none() {
        return Err(format!("unit '{}' is not {unit}", unit_text.trim()));
    }
    Ok(chan)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::header::DataFormat;

    #[test]
    fn numbers_read_like_atof() {
        assert_eq!(parse_f64_prefix(" 1.5e+002 ! c"), Some(150.0));
        assert_eq!(parse_f64_prefix("-0.25"), Some(-0.25));
        assert_eq!(parse_f64_prefix("1.0D-03"), Some(1.0));
        assert_eq!(parse_f64_prefix("5e"), Some(5.0));
        assert_eq!(parse_f64_prefix(".5"), Some(0.5));
        assert_eq!(parse_f64_prefix("abc"), None);
        assert!(parse_f64_prefix("nan").unwrap().is_nan());
        assert_eq!(parse_i32_prefix(" 1.0000e+000"), Some(1));
        assert_eq!(parse_i32_prefix("-3"), Some(-3));
        assert_eq!(parse_i32_prefix("x"), None);
    }

    #[test]
    fn channels_are_recognised() {
        assert_eq!(parse_channel("D:reference line phi,rad  ! heading"), Ok(Channel::RefPhi));
        assert_eq!(parse_channel("D:long section at v = -1.250,m"), Ok(Channel::SectionAt(-1.25)));
        assert_eq!(parse_channel("d:LONG SECTION 12,m"), Ok(Channel::SectionIndex(12.0)));
        assert!(parse_channel("D:long section 3,kg").is_err());
        assert!(parse_channel("D:reference line z,m").is_err());
    }

    #[test]
    fn tags_and_lines() {
        assert_eq!(tag("$ROAD_CRG_OPTS ! x"), Some(Tag::Start(Section::Options)));
        assert_eq!(tag("$road_crg"), Some(Tag::Start(Section::Road)));
        assert_eq!(tag("$!*****"), Some(Tag::End));
        assert_eq!(tag("$$$$$$$$$0"), Some(Tag::Data));
        assert_eq!(tag("x"), None);
        let lines: Vec<_> = Lines::new(b"a\r\nb\n\nc").map(|l| latin1(l.bytes)).collect();
        assert_eq!(lines, ["a", "b", "", "c"]);
        assert_eq!(DataFormat::from_letters("LRFI  ! text"), Some(DataFormat::Lrfi));
        assert_eq!(DataFormat::from_letters("kdbi"), Some(DataFormat::Kdbi));
        assert_eq!(DataFormat::from_letters("XRBI"), None);
    }
}
