//! Reading points: text tables (CSV, XYZ: columns x, y and z by name or position),
//! PLY (text or binary) and LAS/LAZ (`las_points`, with the `point-clouds` feature).

use super::generate::Points;
use opencrg_core::{Error, Location, Result};
use std::path::Path;

/// The points of a file, by its extension: `.las`/`.laz`, `.ply`, anything else a
/// text table. Text tables give z when they have a third column (or one named z).
pub fn read_points(path: &Path) -> Result<Points> {
    if is_las(path) {
        return super::las_points::read_file(path);
    }
    let bytes = std::fs::read(path).map_err(|source| Error::reading(path, source))?;
    parse_points(&bytes, path)
}

/// The points of `bytes`, read as [`read_points`] reads a file called `name`.
pub fn parse_points(bytes: &[u8], name: &Path) -> Result<Points> {
    let ext = name.extension().map(|e| e.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
    if is_las(name) {
        super::las_points::read_bytes(bytes, name)
    } else if ext == "ply" || bytes.starts_with(b"ply\n") || bytes.starts_with(b"ply\r\n") {
        read_ply(name, bytes)
    } else {
        read_table(name, bytes)
    }
}

/// Whether the name says LAS or LAZ.
fn is_las(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("las") || e.eq_ignore_ascii_case("laz"))
}

pub(crate) fn bad(path: &Path, line: usize, field: &str, message: impl Into<String>) -> Error {
    Error::format(path, if line == 0 { Location::File } else { Location::Line(line) }, field, message)
}

/// A text table: fields split by commas, semicolons or blanks; `#` lines skipped; a
/// first line with words names the columns (x, y, z in any case), otherwise the
/// first three columns are x, y and z.
fn read_table(path: &Path, bytes: &[u8]) -> Result<Points> {
    let text = std::str::from_utf8(bytes).map_err(|e| bad(path, 0, "text", format!("not UTF-8 text ({e})")))?;
    fn split(line: &str) -> Vec<&str> {
        line.split(|c: char| c == ',' || c == ';' || c.is_whitespace()).filter(|s| !s.is_empty()).collect()
    }
    let mut lines = text.lines().enumerate().filter(|(_, l)| {
        let t = l.trim();
        !t.is_empty() && !t.starts_with('#')
    });
    let mut columns: Option<[Option<usize>; 3]> = None;
    let mut points = Points::default();
    let mut z = Vec::new();
    let mut first = true;
    for (k, line) in lines.by_ref() {
        let fields = split(line);
        if first {
            first = false;
            if fields.iter().any(|f| f.parse::<f64>().is_err()) {
                let names: Vec<String> =
                    fields.iter().map(|f| f.trim_matches(|c| c == '"' || c == '\'').to_ascii_lowercase()).collect();
                let find = |n: &str| names.iter().position(|f| f == n);
                let (Some(x), Some(y)) = (find("x"), find("y")) else {
                    return Err(bad(
                        path,
                        k + 1,
                        "header",
                        format!("no columns named x and y (found {})", names.join(", ")),
                    ));
                };
                columns = Some([Some(x), Some(y), find("z")]);
                continue;
            }
        }
        let cols = *columns.get_or_insert_with(|| [Some(0), Some(1), (fields.len() >= 3).then_some(2)]);
        let need = cols.iter().flatten().max().map_or(0, |m| m + 1);
        if fields.len() < need.max(2) {
            return Err(bad(path, k + 1, "values", format!("{} field(s), {} needed", fields.len(), need.max(2))));
        }
        let value = |c: usize, name: &str| {
            fields[c].parse::<f64>().map_err(|_| bad(path, k + 1, name, format!("'{}' is not a number", fields[c])))
        };
        points.x.push(value(cols[0].unwrap_or(0), "x")?);
        points.y.push(value(cols[1].unwrap_or(1), "y")?);
        if let Some(c) = cols[2] {
            z.push(value(c, "z")?);
        }
    }
    if points.is_empty() {
        return Err(bad(path, 0, "values", "no points"));
    }
    if z.len() == points.len() {
        points.z = Some(z);
    }
    Ok(points)
}

/// The scalar types of PLY properties: their size in bytes.
fn ply_size(kind: &str) -> Option<usize> {
    Some(match kind {
        "char" | "uchar" | "int8" | "uint8" => 1,
        "short" | "ushort" | "int16" | "uint16" => 2,
        "int" | "uint" | "int32" | "uint32" | "float" | "float32" => 4,
        "double" | "float64" => 8,
        _ => return None,
    })
}

fn ply_value(kind: &str, b: &[u8], little: bool) -> f64 {
    macro_rules! num {
        ($t:ty, $n:expr) => {{
            let a: [u8; $n] = b[..$n].try_into().unwrap_or([0; $n]);
            (if little { <$t>::from_le_bytes(a) } else { <$t>::from_be_bytes(a) }) as f64
        }};
    }
    match kind {
        "char" | "int8" => num!(i8, 1),
        "uchar" | "uint8" => num!(u8, 1),
        "short" | "int16" => num!(i16, 2),
        "ushort" | "uint16" => num!(u16, 2),
        "int" | "int32" => num!(i32, 4),
        "uint" | "uint32" => num!(u32, 4),
        "float" | "float32" => num!(f32, 4),
        _ => num!(f64, 8),
    }
}

/// A PLY element: its name, count, scalar properties (type, name), and whether it has
/// list properties.
struct PlyElement {
    name: String,
    count: usize,
    props: Vec<(String, String)>,
    lists: bool,
}

/// PLY: the vertex element's x, y and z (it must come first, or after elements of
/// fixed size).
fn read_ply(path: &Path, bytes: &[u8]) -> Result<Points> {
    let end = bytes
        .windows(10)
        .position(|w| w == b"end_header")
        .ok_or_else(|| bad(path, 0, "header", "no end_header line"))?;
    let body_start = bytes[end..].iter().position(|&b| b == b'\n').map_or(bytes.len(), |p| end + p + 1);
    let header = String::from_utf8_lossy(&bytes[..end]);
    let (format, elements) = ply_header(path, &header)?;
    let little = match format {
        "ascii" => None,
        "binary_little_endian" => Some(true),
        "binary_big_endian" => Some(false),
        other => return Err(bad(path, 0, "format", format!("'{other}' is not a PLY format"))),
    };
    let at =
        elements.iter().position(|e| e.name == "vertex").ok_or_else(|| bad(path, 0, "element", "no vertex element"))?;
    if elements[..=at].iter().any(|e| e.lists) {
        return Err(bad(path, 0, "element", "list properties before or in the vertex element are not read"));
    }
    let PlyElement { count: n, props, .. } = &elements[at];
    let find = |name: &str| props.iter().position(|p| p.1 == name);
    let (Some(ix), Some(iy), iz) = (find("x"), find("y"), find("z")) else {
        return Err(bad(path, 0, "vertex", "no x and y properties"));
    };
    // Room for what the file can hold at most (a vertex takes a byte at least), not for
    // what its header claims.
    let room = (*n).min(bytes.len());
    let mut points = Points { x: Vec::with_capacity(room), y: Vec::with_capacity(room), z: None };
    let mut z = Vec::with_capacity(room);
    match little {
        None => {
            let text = String::from_utf8_lossy(&bytes[body_start..]);
            let skip = elements[..at].iter().fold(0usize, |sum, e| sum.saturating_add(e.count));
            let mut lines = text.lines().skip(skip);
            for i in 0..*n {
                let line = lines.next().ok_or_else(|| bad(path, 0, "vertex", format!("{i} of {n} vertices found")))?;
                let w: Vec<f64> = line.split_whitespace().filter_map(|s| s.parse().ok()).collect();
                if w.len() < props.len() {
                    return Err(bad(
                        path,
                        0,
                        "vertex",
                        format!("vertex {} has {} of {} values", i + 1, w.len(), props.len()),
                    ));
                }
                points.x.push(w[ix]);
                points.y.push(w[iy]);
                if let Some(c) = iz {
                    z.push(w[c]);
                }
            }
        }
        Some(little) => {
            let size = |e: &PlyElement| -> usize { e.props.iter().map(|p| ply_size(&p.0).unwrap_or(0)).sum() };
            let too_big = || bad(path, 0, "element", "the header's element counts exceed any file");
            let before = elements[..at]
                .iter()
                .try_fold(0usize, |sum, e| e.count.checked_mul(size(e)).and_then(|b| sum.checked_add(b)))
                .ok_or_else(too_big)?;
            let start = body_start.checked_add(before).ok_or_else(too_big)?;
            let stride = size(&elements[at]);
            let end = n.checked_mul(stride).and_then(|b| b.checked_add(start)).ok_or_else(too_big)?;
            let offsets: Vec<usize> = props
                .iter()
                .scan(0, |o, p| {
                    let here = *o;
                    *o += ply_size(&p.0).unwrap_or(0);
                    Some(here)
                })
                .collect();
            let body =
                bytes.get(start..end).ok_or_else(|| bad(path, 0, "vertex", "the file ends before its vertices do"))?;
            for rec in body.chunks_exact(stride) {
                let get = |c: usize| ply_value(&props[c].0, &rec[offsets[c]..], little);
                points.x.push(get(ix));
                points.y.push(get(iy));
                if let Some(c) = iz {
                    z.push(get(c));
                }
            }
        }
    }
    if iz.is_some() {
        points.z = Some(z);
    }
    Ok(points)
}

/// A PLY header's format and elements (name, count, properties: type and name; whether
/// it has list properties).
fn ply_header<'a>(path: &Path, header: &'a str) -> Result<(&'a str, Vec<PlyElement>)> {
    let mut format = "";
    // Elements: name, count, properties (type, name; lists refused).
    let mut elements: Vec<PlyElement> = Vec::new();
    for (k, line) in header.lines().enumerate() {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w.as_slice() {
            ["format", f, ..] => format = f,
            ["element", name, n] => {
                let n = n.parse().map_err(|_| bad(path, k + 1, "element", format!("count '{n}' is not a number")))?;
                elements.push(PlyElement { name: name.to_string(), count: n, props: Vec::new(), lists: false });
            }
            ["property", "list", ..] => {
                if let Some(e) = elements.last_mut() {
                    e.lists = true;
                }
            }
            ["property", kind, name] => {
                if ply_size(kind).is_none() {
                    return Err(bad(path, k + 1, "property", format!("unknown type '{kind}'")));
                }
                if let Some(e) = elements.last_mut() {
                    e.props.push((kind.to_string(), name.to_string()));
                }
            }
            _ => {}
        }
    }
    Ok((format, elements))
}
