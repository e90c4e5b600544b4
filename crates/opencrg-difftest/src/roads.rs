//! Random roads: all four data formats, straight and integrated reference lines
//! (closed and almost closed tracks among them), slope and banking as channels or
//! header constants (NaN as the first channel value, as PyOpenCRG writes), numbered,
//! even, uneven and unsorted long sections, v ranges given only by their increment,
//! NaN cells and NaN borders, u starting far from 0, options and modifiers in the file,
//! and file references carrying them.

use crate::rng::Rng;
use std::f64::consts::PI;
use std::fmt::Write as _;

/// The files of one generated road.
pub struct RoadFiles {
    /// Name and content of every file; the first is the one to load.
    pub files: Vec<(String, Vec<u8>)>,
    /// The road's features, for reports.
    pub summary: String,
}

#[derive(Clone, Copy, PartialEq)]
enum Format {
    Lrfi,
    Ldfi,
    Krbi,
    Kdbi,
}

impl Format {
    fn name(self) -> &'static str {
        match self {
            Format::Lrfi => "LRFI",
            Format::Ldfi => "LDFI",
            Format::Krbi => "KRBI",
            Format::Kdbi => "KDBI",
        }
    }
}

/// How the heading channel runs along u.
#[derive(Clone, Copy)]
enum Heading {
    None,
    Constant,
    Curving(f64),
    Wavy(f64, f64),
    Loop(f64),
}

impl Heading {
    /// A random heading for a line of `nu` cross sections over `length` (loops need 8).
    fn draw(rng: &mut Rng, nu: usize, length: f64) -> Heading {
        match rng.int(0, 19) {
            0..=6 => Heading::None,
            7 | 8 => Heading::Constant,
            9..=13 => Heading::Curving(rng.range(-1.0, 1.0) * (PI / length).min(0.3)),
            14 | 15 => Heading::Wavy(rng.range(0.05, 0.6), rng.range(0.3, 1.5) * length),
            16 | 17 if nu >= 8 => Heading::Loop(1.0),
            _ if nu >= 8 => Heading::Loop(rng.pick(&[0.97, 0.995, 1.02])),
            _ => Heading::None,
        }
    }

    /// The heading's kind and parameters, for reports.
    fn describe(self) -> String {
        match self {
            Heading::None => "straight".to_string(),
            Heading::Constant => "phi constant".to_string(),
            Heading::Curving(k) => format!("curving k={k:.4}"),
            Heading::Wavy(a, p) => format!("wavy a={a:.3} p={p:.2}"),
            Heading::Loop(t) => format!("loop {t}"),
        }
    }
}

/// Option keywords of `$ROAD_CRG_OPTS` with the values the generator draws from.
const OPTION_LINES: [(&str, &[f64]); 9] = [
    ("BORDER_MODE_U", &[0.0, 1.0, 2.0, 3.0, 4.0]),
    ("BORDER_MODE_V", &[0.0, 1.0, 2.0, 3.0, 4.0]),
    ("BORDER_OFFSET_U", &[0.0, -0.5, 1.25]),
    ("BORDER_OFFSET_V", &[0.0, 0.3, -2.0]),
    ("BORDER_SMOOTH_UBEG", &[0.0, 0.5, 2.0]),
    ("BORDER_SMOOTH_UEND", &[0.0, 1.0, 3.0]),
    ("REFLINE_CONTINUATION", &[0.0, 1.0]),
    ("REFLINE_SEARCH_FAR", &[1.5, 0.5, 10.0]),
    ("REFLINE_SEARCH_CLOSE", &[0.3, 0.1, 2.0]),
];

/// Modifier keywords of `$ROAD_CRG_MODS`, in groups that make sense together.
const SCALE_LINES: [(&str, &[f64]); 6] = [
    ("SCALE_Z_GRID", &[2.0, 0.5, -1.0]),
    ("SCALE_SLOPE", &[2.0, 0.0]),
    ("SCALE_BANKING", &[3.0, -1.0]),
    ("SCALE_LENGTH", &[2.0, 0.5]),
    ("SCALE_WIDTH", &[1.5, 0.25]),
    ("SCALE_CURVATURE", &[2.0, 0.5, -1.0]),
];
const NAN_LINES: [(&str, &[f64]); 2] = [("GRID_NAN_MODE", &[0.0, 1.0, 2.0]), ("GRID_NAN_OFFSET", &[0.0, 0.1])];
const REFPOINT_LINES: [(&str, &[f64]); 10] = [
    ("REFPOINT_U_FRACTION", &[0.0, 0.5, 1.0]),
    ("REFPOINT_U_OFFSET", &[0.0, 1.0]),
    ("REFPOINT_U", &[0.0, 3.0]),
    ("REFPOINT_V_FRACTION", &[0.0, 0.5, 1.0]),
    ("REFPOINT_V_OFFSET", &[0.0, -0.5]),
    ("REFPOINT_V", &[0.0, 1.0]),
    ("REFPOINT_X", &[0.0, 100.0, -20.0]),
    ("REFPOINT_Y", &[0.0, 50.0]),
    ("REFPOINT_Z", &[0.0, 2.0]),
    ("REFPOINT_PHI", &[0.0, 1.0, -2.5]),
];
const OFFSET_LINES: [(&str, &[f64]); 6] = [
    ("REFLINE_OFFSET_X", &[0.0, 10.0]),
    ("REFLINE_OFFSET_Y", &[0.0, -5.0]),
    ("REFLINE_OFFSET_Z", &[0.0, 1.0]),
    ("REFLINE_OFFSET_PHI", &[0.0, 0.5, 3.0]),
    ("REFLINE_ROTCENTER_X", &[0.0, 5.0]),
    ("REFLINE_ROTCENTER_Y", &[0.0, -3.0]),
];

/// A few lines of `table`, each with one of its values.
fn some_lines(rng: &mut Rng, table: &[(&str, &[f64])], p: f64) -> String {
    let mut out = String::new();
    for (name, values) in table {
        if rng.chance(p) {
            let _ = writeln!(out, "  {name} = {:?}", rng.pick(values));
        }
    }
    out
}

/// Random `$ROAD_CRG_OPTS` and `$ROAD_CRG_MODS` sections (either may be empty).
fn settings_sections(rng: &mut Rng) -> (String, String) {
    let opts = if rng.chance(0.3) { some_lines(rng, &OPTION_LINES, 0.35) } else { String::new() };
    let mut mods = String::new();
    if rng.chance(0.3) {
        mods += &some_lines(rng, &SCALE_LINES, 0.3);
        mods += &some_lines(rng, &NAN_LINES, 0.4);
        if rng.chance(0.5) {
            mods += &some_lines(rng, &REFPOINT_LINES, 0.3);
        } else {
            mods += &some_lines(rng, &OFFSET_LINES, 0.4);
        }
    }
    (opts, mods)
}

fn section(name: &str, body: &str) -> String {
    if body.is_empty() && name != "$ROAD_CRG_MODS" {
        return String::new();
    }
    format!("{name}\n{body}$\n")
}

/// One random road, named after `index`.
pub fn generate(rng: &mut Rng, index: usize) -> RoadFiles {
    let format = rng.pick(&[Format::Lrfi, Format::Ldfi, Format::Krbi, Format::Kdbi]);
    let nu = if rng.chance(0.1) { rng.int(2, 5) } else { rng.int(8, 60) } as usize;
    let u_inc = rng.pick(&[0.01, 0.1, 0.2, 0.25, 0.5, 1.0, 2.5]);
    let u_start = u_start(rng);
    let u_end = u_start + (nu - 1) as f64 * u_inc;
    let length = u_end - u_start;
    let mut summary = vec![format!("{} nu={nu} du={u_inc} u0={u_start}", format.name())];

    // --- reference line ---
    let heading = Heading::draw(rng, nu, length);
    let phi0_given = rng.chance(0.5);
    let any_phi = rng.range(-PI, PI);
    let phi0 = if phi0_given { rng.pick(&[any_phi, 0.0, 7.0]) } else { 0.0 };
    let phi_at = |i: usize| -> f64 {
        let s = i as f64 * u_inc;
        match heading {
            Heading::None | Heading::Constant => phi0,
            Heading::Curving(k) => phi0 + k * s,
            Heading::Wavy(a, p) => phi0 + a * (2.0 * PI * s / p).sin(),
            Heading::Loop(turns) => phi0 + 2.0 * PI * turns * i as f64 / (nu - 1) as f64,
        }
    };
    let xy0_given = rng.chance(0.6);
    let (x0, y0) = if xy0_given { start_point(rng) } else { (0.0, 0.0) };
    summary.push(heading.describe());

    let mut h = String::new();
    let _ = writeln!(h, "$CT\ndifftest road {index}\n$");
    let _ = writeln!(h, "$ROAD_CRG");
    kv(&mut h, "REFERENCE_LINE_START_U", u_start);
    if !(format == Format::Lrfi || format == Format::Ldfi) || rng.chance(0.8) {
        kv(&mut h, "REFERENCE_LINE_END_U", u_end);
    }
    kv(&mut h, "REFERENCE_LINE_INCREMENT", u_inc);
    if xy0_given {
        kv(&mut h, "REFERENCE_LINE_START_X", x0);
        kv(&mut h, "REFERENCE_LINE_START_Y", y0);
    }
    if phi0_given {
        kv(&mut h, "REFERENCE_LINE_START_PHI", phi0);
    }
    let has_phi = !matches!(heading, Heading::None);
    if has_phi && rng.chance(0.5) {
        kv(&mut h, "REFERENCE_LINE_END_PHI", phi_at(nu - 1));
    } else if !has_phi && rng.chance(0.1) {
        kv(&mut h, "REFERENCE_LINE_END_PHI", phi0 + 0.3);
        summary.push("end phi differs".into());
    }
    if rng.chance(0.25) {
        end_point(rng, &mut h, (x0, y0), nu, u_inc, length, &phi_at);
        summary.push("end x/y".into());
    }

    // --- slope and banking: none, header constants, or channels ---
    let mut channel_kinds: Vec<(&str, &str)> = Vec::new();
    let mut channel_fns: Vec<Channel> = Vec::new();
    if has_phi {
        channel_kinds.push(("phi", "rad"));
        channel_fns.push(Box::new(phi_at));
    }
    slope_and_banking(rng, &mut h, &mut summary, &mut channel_kinds, &mut channel_fns);
    if rng.chance(0.3) {
        kv(&mut h, "REFERENCE_LINE_START_Z", rng.range(-10.0, 300.0));
        if rng.chance(0.4) {
            kv(&mut h, "REFERENCE_LINE_END_Z", rng.range(-10.0, 300.0));
        }
    }

    // --- long sections ---
    let sections = long_sections(rng, &mut h, &mut summary);
    let _ = writeln!(h, "$");

    // --- elevation ---
    let grid = elevation(rng, nu, u_inc, &sections, &mut summary);

    // --- settings in the file ---
    let (opts, mods) = settings_sections(rng);
    let by_reference = rng.chance(0.15);
    let (own_opts, own_mods) = if by_reference { settings_sections(rng) } else { (opts.clone(), mods.clone()) };
    h += &section("$ROAD_CRG_OPTS", &own_opts);
    if !own_mods.is_empty() || rng.chance(0.1) {
        h += &section("$ROAD_CRG_MODS", &own_mods);
    }
    if !opts.is_empty() || !mods.is_empty() {
        summary.push("settings in file".into());
    }

    // --- data definition and data ---
    let data = data_records(h, format, &channel_kinds, &channel_fns, &sections, &grid);
    if by_reference {
        summary.push("file reference".into());
    }
    RoadFiles { files: files(index, by_reference, &opts, &mods, data), summary: summary.join(", ") }
}

/// The header's end point: where forward steps along the heading lead, sometimes a
/// little off.
fn end_point(
    rng: &mut Rng,
    h: &mut String,
    start: (f64, f64),
    nu: usize,
    u_inc: f64,
    length: f64,
    phi_at: &dyn Fn(usize) -> f64,
) {
    // The end point: where forward steps along the heading lead, sometimes a little off.
    let (mut x, mut y) = start;
    for i in 1..nu {
        x += u_inc * phi_at(i).cos();
        y += u_inc * phi_at(i).sin();
    }
    if rng.chance(0.5) {
        // A little off, as rounding in files leaves it (far off, the line folds back
        // and the reference's x/y search can loop forever).
        x += rng.range(-0.01, 0.01) * length;
        y += rng.range(-0.01, 0.01) * length;
    }
    kv(h, "REFERENCE_LINE_END_X", x);
    kv(h, "REFERENCE_LINE_END_Y", y);
}

/// The data definition after the header `h`, then the records in the file's format.
fn data_records(
    mut h: String,
    format: Format,
    channel_kinds: &[(&str, &str)],
    channel_fns: &[Channel],
    sections: &[(String, f64)],
    grid: &[f64],
) -> Vec<u8> {
    let (nv, nu) = (sections.len(), grid.len() / sections.len());
    let _ = writeln!(h, "$KD_Definition\n#:{}", format.name());
    for (name, unit) in channel_kinds {
        let _ = writeln!(h, "D:reference line {name},{unit}");
    }
    for (def, _) in sections {
        let _ = writeln!(h, "{def}");
    }
    let _ = writeln!(h, "$\n{}", "$".repeat(80));
    let mut data = h.into_bytes();
    let mut record = Vec::with_capacity(channel_fns.len() + nv);
    for i in 0..nu {
        record.clear();
        record.extend(channel_fns.iter().map(|f| f(i)));
        record.extend_from_slice(&grid[i * nv..(i + 1) * nv]);
        write_record(&mut data, format, &record);
    }
    data
}

/// The road's files: the data alone, or a main file naming it with the settings.
fn files(index: usize, by_reference: bool, opts: &str, mods: &str, data: Vec<u8>) -> Vec<(String, Vec<u8>)> {
    let mut files = Vec::new();
    if by_reference {
        let mut main = String::new();
        let _ = writeln!(main, "$CT\ndifftest road {index}, data by reference\n$");
        let _ = writeln!(main, "$ROAD_CRG_FILE\n  data.crg   ! the data\n$");
        main += &section("$ROAD_CRG_OPTS", opts);
        main += &section("$ROAD_CRG_MODS", mods);
        files.push(("road.crg".to_string(), main.into_bytes()));
        files.push(("data.crg".to_string(), data));
    } else {
        files.push(("road.crg".to_string(), data));
    }
    files
}

/// The first u: 0 mostly, a quarter metre near it, or far from it either way.
fn u_start(rng: &mut Rng) -> f64 {
    match rng.int(0, 9) {
        0..=5 => 0.0,
        6 | 7 => (rng.range(-30.0, 30.0) * 4.0).round() / 4.0,
        _ => (rng.range(1e3, 1e5) * if rng.chance(0.5) { 1.0 } else { -1.0 }).round(),
    }
}

/// A start point given in the header: near the origin, or far off in whole metres.
fn start_point(rng: &mut Rng) -> (f64, f64) {
    if rng.chance(0.15) {
        (rng.range(-2e5, 2e5).round(), rng.range(-2e5, 2e5).round())
    } else {
        (rng.range(-500.0, 500.0), rng.range(-500.0, 500.0))
    }
}

/// A channel's value by cross section.
type Channel<'a> = Box<dyn Fn(usize) -> f64 + 'a>;

/// Writes a header line `k = v` (the value as Rust prints it: it reads back the same).
fn kv(h: &mut String, k: &str, v: f64) {
    let _ = writeln!(h, "{k} = {v:?}");
}

/// Slope and banking: none, header constants, or channels (their names and units, and
/// their values by cross section).
fn slope_and_banking<'a>(
    rng: &mut Rng,
    h: &mut String,
    summary: &mut Vec<String>,
    channel_kinds: &mut Vec<(&'static str, &'static str)>,
    channel_fns: &mut Vec<Channel<'a>>,
) {
    for (name, keyword) in [("slope", "S"), ("banking", "B")] {
        match rng.int(0, 9) {
            0..=4 => {}
            5 | 6 => {
                kv(h, &format!("REFERENCE_LINE_START_{keyword}"), rng.range(-0.08, 0.08));
                if rng.chance(0.5) {
                    kv(h, &format!("REFERENCE_LINE_END_{keyword}"), rng.range(-0.08, 0.08));
                }
                summary.push(format!("{name} header"));
            }
            _ => {
                let (a, w, c) = (rng.range(-0.05, 0.05), rng.range(0.1, 2.0), rng.range(-0.03, 0.03));
                let nan_first = rng.chance(0.35);
                channel_kinds.push((name, "m/m"));
                channel_fns.push(Box::new(move |i: usize| {
                    if nan_first && i == 0 {
                        f64::NAN
                    } else {
                        c + a * (w * i as f64 * 0.37).sin()
                    }
                }));
                summary.push(format!("{name} channel{}", if nan_first { " NaN first" } else { "" }));
            }
        }
    }
}

/// The long sections: their definition lines and v, numbered (with the header's v range
/// in one of three ways) or at given v (even, uneven, unsorted).
fn long_sections(rng: &mut Rng, h: &mut String, summary: &mut Vec<String>) -> Vec<(String, f64)> {
    let nv = rng.int(2, 10) as usize;
    let mut sections: Vec<(String, f64)> = Vec::new();
    if rng.chance(0.5) {
        let v_inc = rng.pick(&[0.01, 0.1, 0.25, 0.5, 1.0]);
        let any_right = rng.range(-3.0, 1.0);
        let v_right = rng.pick(&[-((nv - 1) as f64) * v_inc / 2.0, 0.0, -1.0, any_right]);
        let v_left = v_right + (nv - 1) as f64 * v_inc;
        match rng.int(0, 5) {
            0 => summary.push("numbered, increment only".into()),
            1 => {
                kv(h, "LONG_SECTION_V_RIGHT", v_right);
                summary.push("numbered, right border only".into());
            }
            _ => {
                kv(h, "LONG_SECTION_V_RIGHT", v_right);
                kv(h, "LONG_SECTION_V_LEFT", v_left);
                summary.push("numbered".into());
            }
        }
        if rng.chance(0.9) {
            kv(h, "LONG_SECTION_V_INCREMENT", v_inc);
        } else {
            summary.push("no v increment".into());
        }
        for i in 0..nv {
            sections.push((format!("D:long section {},m", i + 1), v_right + i as f64 * v_inc));
        }
    } else {
        let even = rng.chance(0.5);
        let mut v = rng.range(-3.0, 0.5);
        let step = rng.pick(&[0.1, 0.25, 0.5]);
        let mut vs = Vec::new();
        for _ in 0..nv {
            vs.push((v * 1000.0).round() / 1000.0);
            v += if even { step } else { step * rng.range(0.3, 2.5) };
        }
        if rng.chance(0.5) {
            kv(h, "LONG_SECTION_V_RIGHT", vs[0]);
            kv(h, "LONG_SECTION_V_LEFT", vs[nv - 1]);
        }
        if rng.chance(0.2) {
            kv(h, "LONG_SECTION_V_INCREMENT", step);
        }
        let mut order: Vec<usize> = (0..nv).collect();
        let shuffled = rng.chance(0.2);
        if shuffled {
            for i in (1..nv).rev() {
                order.swap(i, rng.int(0, i as i64) as usize);
            }
        }
        for i in order {
            sections.push((format!("D:long section at v = {:?},m", vs[i]), vs[i]));
        }
        summary.push(format!(
            "at v, {}{}",
            if even { "even" } else { "uneven" },
            if shuffled { ", unsorted" } else { "" }
        ));
    }
    sections
}

/// The elevation grid, cross section by cross section: smooth waves with NaN cells,
/// borders or a first row now and then.
fn elevation(rng: &mut Rng, nu: usize, u_inc: f64, sections: &[(String, f64)], summary: &mut Vec<String>) -> Vec<f64> {
    let nv = sections.len();
    let (a, w1, b, c, w2) = (
        rng.range(-0.05, 0.05),
        rng.range(0.2, 3.0),
        rng.range(-0.05, 0.05),
        rng.range(-0.02, 0.02),
        rng.range(0.5, 4.0),
    );
    let nan_cells = if rng.chance(0.2) { rng.range(0.02, 0.2) } else { 0.0 };
    let nan_border = rng.chance(0.15);
    let nan_row = rng.chance(0.05);
    if nan_cells > 0.0 {
        summary.push(format!("NaN cells {nan_cells:.2}"));
    }
    if nan_border {
        summary.push("NaN borders".into());
    }
    if nan_row {
        summary.push("NaN first row".into());
    }
    let mut grid = vec![0.0f64; nu * nv];
    for i in 0..nu {
        let u = i as f64 * u_inc;
        for (j, (_, v)) in sections.iter().enumerate() {
            let edge = j == 0 || j == nv - 1;
            let nan =
                rng.chance(nan_cells) || (nan_border && edge && (i < nu / 3 || i > 2 * nu / 3)) || (nan_row && i == 0);
            grid[i * nv + j] =
                if nan { f64::NAN } else { a * (w1 * u).sin() + b * v + c * (w2 * v).cos() + 0.001 * j as f64 };
        }
    }
    grid
}

/// Appends one record in the file's data format.
fn write_record(out: &mut Vec<u8>, format: Format, values: &[f64]) {
    match format {
        Format::Krbi => values.iter().for_each(|v| out.extend_from_slice(&(*v as f32).to_be_bytes())),
        Format::Kdbi => values.iter().for_each(|v| out.extend_from_slice(&v.to_be_bytes())),
        Format::Lrfi | Format::Ldfi => {
            let width = if format == Format::Lrfi { 10 } else { 20 };
            let mut line = String::new();
            for (k, v) in values.iter().enumerate() {
                if k > 0 && k % (80 / width) == 0 {
                    line.push('\n');
                }
                let _ = write!(line, "{:>width$}", field(*v, width));
            }
            line.push('\n');
            out.extend_from_slice(line.as_bytes());
        }
    }
}

/// `v` with as many decimals as fit in `width` characters (the values drawn here need
/// no exponent), or `NaN`.
fn field(v: f64, width: usize) -> String {
    if v.is_nan() {
        return "NaN".into();
    }
    (0..width).rev().map(|p| format!("{v:.p$}")).find(|s| s.len() <= width).unwrap_or_else(|| "NaN".into())
}
