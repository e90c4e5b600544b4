//! Pictures of a road: a top view in x/y coloured by elevation with hill shading, a
//! colour bar and a scale bar; and sections along u or across v as line plots.

use crate::canvas::{Canvas, Rgb, BLACK, NO_DATA};
use opencrg::{Budget, ContactPoint};

/// Room right of the map for the colour bar and its labels, and below it for the scale bar.
const BAR_ROOM: usize = 150;
const SCALE_ROOM: usize = 44;
const MARGIN: usize = 12;
/// The memory a pixel of the top view takes while it is made (elevation, slope, colour,
/// the encoded picture).
pub(crate) const PIXEL_BYTES: f64 = 32.0;
/// The longest side of a top view, in pixels.
pub const MAX_SIZE: usize = 20_000;

/// A few colours from deep blue through green to yellow, for low to high elevation.
const COLOUR_STOPS: [Rgb; 6] =
    [[48, 18, 59], [50, 101, 211], [27, 186, 161], [122, 221, 60], [233, 201, 40], [254, 247, 160]];

/// The colour of a value `t` in 0..1 along the colour stops.
fn colour(t: f64) -> Rgb {
    let t = t.clamp(0.0, 1.0) * (COLOUR_STOPS.len() - 1) as f64;
    let i = (t.floor() as usize).min(COLOUR_STOPS.len() - 2);
    let f = t - i as f64;
    let (a, b) = (COLOUR_STOPS[i], COLOUR_STOPS[i + 1]);
    [0, 1, 2].map(|k| (f64::from(a[k]) + f * (f64::from(b[k]) - f64::from(a[k]))).round() as u8)
}

fn shade(c: Rgb, light: f64) -> Rgb {
    c.map(|v| (f64::from(v) * light).round().clamp(0.0, 255.0) as u8)
}

/// A length of 1, 2 or 5 times a power of ten, at most `max`.
fn nice_length(max: f64) -> f64 {
    let p = 10f64.powf(max.log10().floor());
    [5.0, 2.0, 1.0].into_iter().map(|k| k * p).find(|&l| l <= max).unwrap_or(p)
}

/// A number for a label, with as many decimals as a range of `span` needs.
fn label_in(v: f64, span: f64) -> String {
    let decimals = if span > 0.0 { (2.0 - span.log10().floor()).clamp(0.0, 8.0) as usize } else { 4 };
    let text = format!("{v:.decimals$}");
    // No "-0.000".
    if text.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        text.trim_start_matches('-').to_string()
    } else {
        text
    }
}

/// A number for a label on its own.
fn label(v: f64) -> String {
    label_in(v, v.abs().max(1e-9) * 10.0)
}

/// The top view of the road evaluated through `cp`: at most `size` pixels on the longer
/// side of the map. `progress` is told each finished row.
pub fn top_view(cp: &mut ContactPoint, size: usize, budget: &Budget, progress: &dyn Fn(u64)) -> Result<Canvas, String> {
    let road = cp.road().clone();
    let (u0, u1) = road.u_range();
    let (v0, v1) = road.v_range();
    let n = road.grid().nu;
    // The road's extent: both borders at every cross section.
    let (mut xmin, mut xmax, mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    let step = (n / 2000).max(1);
    for i in (0..n).step_by(step).chain(std::iter::once(n - 1)) {
        let u = u0 + (u1 - u0) * i as f64 / (n - 1) as f64;
        for v in [v0, v1] {
            if let Ok((x, y)) = cp.uv_to_xy(u, v) {
                xmin = xmin.min(x);
                xmax = xmax.max(x);
                ymin = ymin.min(y);
                ymax = ymax.max(y);
            }
        }
    }
    let extent = (xmax - xmin).max(ymax - ymin).max(1e-9);
    let px = extent / size.max(1) as f64; // metres per pixel
    let mw = (((xmax - xmin) / px).ceil() as usize).max(1);
    let mh = (((ymax - ymin) / px).ceil() as usize).max(1);
    // Per pixel: its elevation, its slope for the shading, its colour, the PNG's bytes.
    let request = format!("a top view of {mw} x {mh} px");
    budget.admit(&request, mw as f64 * mh as f64, "pixels", PIXEL_BYTES).map_err(|e| e.to_string())?;

    // Elevation at every pixel centre inside the road (NaN: no data; None: off the road).
    let mut z: Vec<Option<f64>> = vec![None; mw * mh];
    for row in 0..mh {
        let y = ymax - (row as f64 + 0.5) * px;
        // Alternate the direction so the search history follows the scan.
        let cols: Box<dyn Iterator<Item = usize>> =
            if row % 2 == 0 { Box::new(0..mw) } else { Box::new((0..mw).rev()) };
        for col in cols {
            let x = xmin + (col as f64 + 0.5) * px;
            let Ok((u, v)) = cp.xy_to_uv(x, y) else { continue };
            if u < u0 || u > u1 || v < v0 || v > v1 {
                continue;
            }
            z[row * mw + col] = Some(cp.uv_to_z(u, v).unwrap_or(f64::NAN));
        }
        progress(row as u64 + 1);
    }
    // Roads narrower than a pixel (or pixels missed between two centres): sample the road
    // itself every half pixel along and across, and fill the pixels it covers.
    let du = (px / 2.0).min(u1 - u0);
    let dv = (px / 2.0).min((v1 - v0) / 2.0).max(1e-9);
    let (nu_s, nv_s) = (((u1 - u0) / du).ceil() as usize, ((v1 - v0) / dv).ceil() as usize);
    for i in 0..=nu_s {
        let u = (u0 + i as f64 * du).min(u1);
        for j in 0..=nv_s {
            let v = (v0 + j as f64 * dv).min(v1);
            let Ok((x, y)) = cp.uv_to_xy(u, v) else { continue };
            let (col, row) = (((x - xmin) / px).floor(), ((ymax - y) / px).floor());
            if col >= 0.0 && row >= 0.0 && (col as usize) < mw && (row as usize) < mh {
                let cell = &mut z[row as usize * mw + col as usize];
                if cell.is_none() {
                    *cell = Some(cp.uv_to_z(u, v).unwrap_or(f64::NAN));
                }
            }
        }
    }
    Ok(height_picture(&z, mw, mh, px))
}

/// The picture of heights `z` on a raster of `mw` x `mh` pixels of `px` metres each (row
/// by row from the north; `None` off the surface, NaN where it has no height): coloured
/// by height with hill shading, a colour bar in metres and a scale bar.
pub(crate) fn height_picture(z: &[Option<f64>], mw: usize, mh: usize, px: f64) -> Canvas {
    let finite = || z.iter().flatten().copied().filter(|v| v.is_finite());
    let (zmin, zmax) = finite().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    let zspan = if zmax > zmin { zmax - zmin } else { 1.0 };

    // Hill shading: the slope towards a light in the north-west, scaled by its 98th
    // percentile so the relief shows whatever the road's scale.
    let at = |r: usize, c: usize| z[r * mw + c].filter(|v| v.is_finite());
    let mut slopes: Vec<f64> = Vec::new();
    let slope_at = |r: usize, c: usize| -> Option<f64> {
        let here = at(r, c)?;
        let east = if c + 1 < mw { at(r, c + 1) } else { None }.unwrap_or(here);
        let west = if c > 0 { at(r, c - 1) } else { None }.unwrap_or(here);
        let north = if r > 0 { at(r - 1, c) } else { None }.unwrap_or(here);
        let south = if r + 1 < mh { at(r + 1, c) } else { None }.unwrap_or(here);
        // Rising towards the north-west faces the light.
        Some(((west - east) + (north - south)) / (2.0 * px))
    };
    for r in 0..mh {
        for c in 0..mw {
            if let Some(s) = slope_at(r, c) {
                slopes.push(s.abs());
            }
        }
    }
    slopes.sort_by(f64::total_cmp);
    let relief = slopes.get(slopes.len() * 98 / 100).copied().filter(|s| *s > 0.0).unwrap_or(1.0);

    let width = MARGIN + mw + BAR_ROOM;
    let height = MARGIN + mh.max(140) + SCALE_ROOM;
    let mut canvas = Canvas::new(width, height);
    for r in 0..mh {
        for c in 0..mw {
            let colour = match z[r * mw + c] {
                None => continue,
                Some(v) if !v.is_finite() => NO_DATA,
                Some(v) => {
                    let light = 0.75 + 0.25 * (slope_at(r, c).unwrap_or(0.0) / relief).clamp(-1.0, 1.0);
                    shade(colour((v - zmin) / zspan), light)
                }
            };
            canvas.set((MARGIN + c) as i64, (MARGIN + r) as i64, colour);
        }
    }

    // Colour bar with the elevation range in metres.
    let (bx, by, bh) = ((MARGIN + mw + 16) as i64, MARGIN as i64, 120i64);
    for k in 0..bh {
        canvas.fill(bx, by + k, 16, 1, colour(1.0 - k as f64 / (bh - 1) as f64));
    }
    for (value, y) in [(zmax, by), (0.5 * (zmin + zmax), by + bh / 2 - 4), (zmin, by + bh - 7)] {
        canvas.text(bx + 22, y, &format!("{} m", label_in(value, zspan)), 1, BLACK);
    }
    canvas.text(bx, by + bh + 8, "z", 1, BLACK);

    // Scale bar: a round length of at most a third of the map.
    let length = nice_length(mw as f64 * px / 3.0);
    let bar = (length / px).round() as i64;
    let (sx, sy) = (MARGIN as i64, (MARGIN + mh.max(140) + 16) as i64);
    canvas.fill(sx, sy, bar.max(1), 4, BLACK);
    canvas.fill(sx, sy - 4, 1, 12, BLACK);
    canvas.fill(sx + bar.max(1) - 1, sy - 4, 1, 12, BLACK);
    canvas.text(sx, sy + 10, &format!("{length} m"), 1, BLACK);
    canvas
}

/// Which section a profile shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Section {
    /// Across the road at this u.
    AtU(f64),
    /// Along the road at this v.
    AtV(f64),
}

/// A line plot of the elevation along a section.
pub fn profile(cp: &mut ContactPoint, section: Section) -> Canvas {
    let road = cp.road().clone();
    let (u0, u1) = road.u_range();
    let (v0, v1) = road.v_range();
    let (from, to, name) = match section {
        Section::AtU(_) => (v0, v1, "v"),
        Section::AtV(_) => (u0, u1, "u"),
    };
    let samples = 1000;
    let points: Vec<(f64, f64)> = (0..=samples)
        .map(|k| {
            let s = from + (to - from) * k as f64 / samples as f64;
            let (u, v) = match section {
                Section::AtU(u) => (u, s),
                Section::AtV(v) => (s, v),
            };
            (s, cp.uv_to_z(u, v).unwrap_or(f64::NAN))
        })
        .collect();
    let (zmin, zmax) = points
        .iter()
        .map(|p| p.1)
        .filter(|z| z.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), z| (a.min(z), b.max(z)));
    let (zmin, zmax) = if zmin.is_finite() { (zmin, zmax) } else { (0.0, 1.0) };
    let pad = if zmax > zmin { 0.05 * (zmax - zmin) } else { 0.5e-3 };
    let (zlo, zhi) = (zmin - pad, zmax + pad);

    let (w, h) = (900usize, 360usize);
    let (left, right, top, bottom) = (96i64, 24i64, 28i64, 48i64);
    let mut canvas = Canvas::new(w, h);
    let (pw, ph) = (w as i64 - left - right, h as i64 - top - bottom);
    let to_px = |s: f64, z: f64| {
        (left as f64 + (s - from) / (to - from) * pw as f64, top as f64 + (zhi - z) / (zhi - zlo) * ph as f64)
    };
    canvas.fill(left, top, pw, ph, [248, 248, 248]);
    for (a, b) in [((left, top), (left + pw, top)), ((left, top + ph), (left + pw, top + ph))] {
        canvas.line(a.0 as f64, a.1 as f64, b.0 as f64, b.1 as f64, BLACK);
    }
    canvas.line(left as f64, top as f64, left as f64, (top + ph) as f64, BLACK);
    canvas.line((left + pw) as f64, top as f64, (left + pw) as f64, (top + ph) as f64, BLACK);
    for pair in points.windows(2) {
        let ((s0, z0), (s1, z1)) = (pair[0], pair[1]);
        if z0.is_finite() && z1.is_finite() {
            let (a, b) = (to_px(s0, z0), to_px(s1, z1));
            canvas.line(a.0, a.1, b.0, b.1, [30, 90, 200]);
        }
    }
    let title = match section {
        Section::AtU(u) => format!("z across the road at u = {} m", label(u)),
        Section::AtV(v) => format!("z along the road at v = {} m", label(v)),
    };
    canvas.text(left, 8, &title, 1, BLACK);
    canvas.text(4, top, &format!("{} m", label_in(zhi, zhi - zlo)), 1, BLACK);
    canvas.text(4, top + ph - 7, &format!("{} m", label_in(zlo, zhi - zlo)), 1, BLACK);
    canvas.text(left, top + ph + 8, &format!("{} m", label_in(from, to - from)), 1, BLACK);
    let end = format!("{} m", label_in(to, to - from));
    canvas.text(left + pw - Canvas::text_width(&end, 1), top + ph + 8, &end, 1, BLACK);
    canvas.text(left + pw / 2 - 3, top + ph + 24, name, 2, BLACK);
    canvas
}
