//! Pictures of a road: a top view in x/y coloured by elevation with hill shading, axes,
//! a colour bar and a scale bar; and sections along u or across v as line plots.

use crate::plot::{self, font, tick_label, Area, Figure, Image, LABEL, TITLE};
use opencrg_core::{Budget, ContactPoint};
use plotters::prelude::*;

/// The memory a pixel of the top view takes while it is made (elevation, slope and its
/// detail, the sums for the local mean, colour, the figure's pixels, the encoded picture
/// or SVG).
pub(crate) const PIXEL_BYTES: f64 = 72.0;
/// The longest side of a top view, in pixels.
pub const MAX_SIZE: usize = 20_000;

/// The grey of cells without data.
const NO_DATA: Rgb = [190, 190, 190];

type Rgb = [u8; 3];

/// The colour of a value `t` in 0..1: the drawing rules' elevation colours.
fn colour(t: f64) -> Rgb {
    opencrg_tools::drawing::elevation_colour(t)
}

fn shade(c: Rgb, light: f64) -> Rgb {
    c.map(|v| (f64::from(v) * light).round().clamp(0.0, 255.0) as u8)
}

/// The top view of the road evaluated through `cp`: at most `size` pixels on the longer
/// side of the map. `progress` is told each finished row.
pub fn top_view(
    cp: &mut ContactPoint,
    name: &str,
    size: usize,
    budget: &Budget,
    progress: &dyn Fn(u64),
) -> Result<Figure, String> {
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
    let RasterFrame { px, west: xmin, north: ymax, width: mw, height: mh } =
        RasterFrame::around([xmin, ymin, xmax, ymax], size);
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
    height_picture(&Raster { z: &z, width: mw, height: mh, px, west: xmin, north: ymax }, &format!("{name}: elevation"))
}

/// Pixels left free round the data inside a picture's frame, so that nothing drawn
/// touches it.
const MARGIN_PX: usize = 4;

/// Where a raster lies and how fine it is: the extent of what it shows, with a margin
/// of [`MARGIN_PX`] on every side inside a longer side of `size` pixels.
pub(crate) struct RasterFrame {
    /// Metres a pixel.
    pub px: f64,
    /// x of the raster's western edge, m.
    pub west: f64,
    /// y of the raster's northern edge, m.
    pub north: f64,
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
}

impl RasterFrame {
    /// The frame of a raster showing `[x0, y0, x1, y1]` with its longer side `size` pixels.
    pub(crate) fn around([x0, y0, x1, y1]: [f64; 4], size: usize) -> RasterFrame {
        let inner = size.saturating_sub(2 * MARGIN_PX).max(1);
        let px = (x1 - x0).max(y1 - y0).max(1e-9) / inner as f64;
        let pixels = |extent: f64| ((extent / px).ceil() as usize).max(1) + 2 * MARGIN_PX;
        let margin = MARGIN_PX as f64 * px;
        RasterFrame { px, west: x0 - margin, north: y1 + margin, width: pixels(x1 - x0), height: pixels(y1 - y0) }
    }
}

/// Heights on a raster: row by row from the north, `None` off the surface, NaN where it
/// has no height.
pub(crate) struct Raster<'a> {
    /// The heights, `width` x `height`.
    pub z: &'a [Option<f64>],
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Metres a pixel.
    pub px: f64,
    /// x of the raster's western edge, m.
    pub west: f64,
    /// y of the raster's northern edge, m.
    pub north: f64,
}

/// Room around the map of a top view: title above, tick labels and axis titles left
/// and below, the scale bar below them, the colour bar right.
const TOP: u32 = 44;
const LEFT: u32 = 84;
const BELOW: u32 = 52;
const SCALE_BAR: u32 = 48;
const COLOUR_BAR: u32 = 170;

/// The window over which the shading takes the surface's own grade away, in metres.
const GRADE_WINDOW: f64 = 2.0;
/// A slope whose variation exceeds this many times the relief is a step, left out of
/// the means.
const STEP_PER_RELIEF: f64 = 4.0;
/// Full light or shade at this many times the median of the slopes' variation.
const RELIEF_PER_MEDIAN: f64 = 1.5;
/// The least slope variation the shading shows at full strength: smoother surfaces stay
/// evenly lit instead of showing rounding.
const LEAST_RELIEF: f64 = 1e-3;

/// The pixels of the raster: coloured by height, with hill shading towards a light in the
/// north-west from the slopes less their mean over [`GRADE_WINDOW`] (the road's grade and
/// cross slope), scaled by the median of what is left, so that a CRG file's detail shows
/// on a sloped road at any scale; grey without data, transparent off the surface.
/// Also the height range.
fn shaded(r: &Raster) -> (Vec<u8>, Option<(f64, f64)>) {
    let (mw, mh, z) = (r.width, r.height, r.z);
    let finite = || z.iter().flatten().copied().filter(|v| v.is_finite());
    let (zmin, zmax) = finite().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    let range = zmin.is_finite().then_some((zmin, zmax));
    let zspan = if zmax > zmin { zmax - zmin } else { 1.0 };
    let light = lights(r);
    let mut rgba = vec![0u8; mw * mh * 4];
    for (k, cell) in z.iter().enumerate() {
        let colour = match cell {
            None => continue,
            Some(v) if !v.is_finite() => NO_DATA,
            Some(v) => shade(colour((v - zmin) / zspan), light[k]),
        };
        rgba[k * 4..k * 4 + 4].copy_from_slice(&[colour[0], colour[1], colour[2], 255]);
    }
    (rgba, range)
}

/// The light on each pixel, 0.5 (shade) to 1 (lit), 0.75 where it is flat or unknown.
fn lights(r: &Raster) -> Vec<f64> {
    let (mw, mh, z) = (r.width, r.height, r.z);
    let at = |r: usize, c: usize| z[r * mw + c].filter(|v| v.is_finite());
    // The rise towards the light along one axis from the neighbours either side:
    // centred where both are on the surface, one-sided at its edges.
    let rise = |before: Option<f64>, here: f64, after: Option<f64>| match (before, after) {
        (Some(b), Some(a)) => (b - a) / (2.0 * r.px),
        (Some(b), None) => (b - here) / r.px,
        (None, Some(a)) => (here - a) / r.px,
        (None, None) => 0.0,
    };
    let slope_at = |row: usize, c: usize| -> Option<f64> {
        let here = at(row, c)?;
        let east = if c + 1 < mw { at(row, c + 1) } else { None };
        let west = if c > 0 { at(row, c - 1) } else { None };
        let north = if row > 0 { at(row - 1, c) } else { None };
        let south = if row + 1 < mh { at(row + 1, c) } else { None };
        Some(rise(west, here, east) + rise(north, here, south))
    };
    let slopes: Vec<f64> = (0..mh).flat_map(|row| (0..mw).map(move |c| slope_at(row, c).unwrap_or(f64::NAN))).collect();
    let k = (GRADE_WINDOW / r.px).round().clamp(2.0, 64.0) as usize;
    // The median, not a high percentile: steps at a CRG record's edges are lines of few
    // pixels but can outweigh a whole road's texture at the top of the distribution.
    let relief_of = |detail: &[f64]| {
        let mut sizes: Vec<f64> = detail.iter().filter(|d| d.is_finite()).map(|d| d.abs()).collect();
        let middle = sizes.len() / 2;
        let median = if sizes.is_empty() { 0.0 } else { *sizes.select_nth_unstable_by(middle, f64::total_cmp).1 };
        (RELIEF_PER_MEDIAN * median).max(LEAST_RELIEF)
    };
    let first = detail(&slopes, mw, mh, k, |_| true);
    let relief = relief_of(&first);
    // Steps (far beyond the texture) are left out of the means, which they would shift
    // over a whole window around them.
    let detail = detail(&slopes, mw, mh, k, |i| first[i].abs() <= STEP_PER_RELIEF * relief);
    drop((slopes, first));
    let relief = relief_of(&detail);
    detail.iter().map(|&d| 0.75 + 0.25 * if d.is_finite() { (d / relief).clamp(-1.0, 1.0) } else { 0.0 }).collect()
}

/// Each slope less the mean of the slopes within `k` pixels of it that `counted` keeps (a
/// box, through sums over the rectangle from the corner); NaN where there is no slope.
fn detail(slopes: &[f64], mw: usize, mh: usize, k: usize, counted: impl Fn(usize) -> bool) -> Vec<f64> {
    let w = mw + 1;
    let mut sum = vec![0.0f64; w * (mh + 1)];
    let mut count = vec![0u32; w * (mh + 1)];
    for row in 0..mh {
        for c in 0..mw {
            let s = slopes[row * mw + c];
            let (v, n) = if s.is_finite() && counted(row * mw + c) { (s, 1) } else { (0.0, 0) };
            let i = (row + 1) * w + c + 1;
            sum[i] = v + sum[i - 1] + sum[i - w] - sum[i - w - 1];
            count[i] = n + count[i - 1] + count[i - w] - count[i - w - 1];
        }
    }
    let boxed = |values: &[f64], counts: &[u32], row: usize, c: usize| {
        let (r0, r1, c0, c1) = (row.saturating_sub(k), (row + k + 1).min(mh), c.saturating_sub(k), (c + k + 1).min(mw));
        let (a, b, cc, d) = (r0 * w + c0, r0 * w + c1, r1 * w + c0, r1 * w + c1);
        (values[d] - values[b] - values[cc] + values[a], counts[d] + counts[a] - counts[b] - counts[cc])
    };
    (0..mh)
        .flat_map(|row| (0..mw).map(move |c| (row, c)))
        .map(|(row, c)| {
            let (total, n) = boxed(&sum, &count, row, c);
            slopes[row * mw + c] - total / f64::from(n.max(1))
        })
        .collect()
}

/// The top view of heights on a raster: the map in x and y with ticks, a colour bar
/// with ticks in metres, a scale bar, cells without data marked.
pub(crate) fn height_picture(r: &Raster, title: &str) -> Result<Figure, String> {
    let (mw, mh) = (r.width as u32, r.height as u32);
    let (rgba, range) = shaded(r);
    let no_data = r.z.iter().flatten().any(|v| !v.is_finite());
    let map_height = mh.max(240);
    let (width, height) = (LEFT + mw + COLOUR_BAR, TOP + map_height + BELOW + SCALE_BAR);
    let image = Image { x: LEFT, y: TOP, width: mw, height: mh, rgba };
    Figure::draw(width, height, Some(image), |root| {
        root.draw_text(title, &font(TITLE), (LEFT as i32, 14)).map_err(plot::failed)?;
        let (x0, x1) = (r.west, r.west + mw as f64 * r.px);
        let (y0, y1) = (r.north - mh as f64 * r.px, r.north);
        let area = root.clone().shrink((0, TOP), (LEFT + mw, mh + BELOW));
        let mut chart = ChartBuilder::on(&area)
            .x_label_area_size(BELOW)
            .y_label_area_size(LEFT)
            .build_cartesian_2d(plot::ruled(x0, x1), plot::ruled(y0, y1))
            .map_err(plot::failed)?;
        plot::lettered(&mut chart.configure_mesh())
            .disable_mesh()
            .x_labels((mw as usize / 90).max(4))
            .y_labels((mh as usize / 50).max(4))
            .x_label_formatter(&|v| tick_label(*v))
            .y_label_formatter(&|v| tick_label(*v))
            .x_desc("x [m]")
            .y_desc("y [m]")
            .draw()
            .map_err(plot::failed)?;
        chart
            .plotting_area()
            .draw(&Rectangle::new([(x0, y0), (x1, y1)], BLACK.stroke_width(1)))
            .map_err(plot::failed)?;
        scale_bar(root, mw as f64 * r.px / 3.0, r.px, TOP + mh + BELOW + 12)?;
        let bar_height = map_height.min(360);
        colour_bar(root, (LEFT + mw + 24, TOP), bar_height, range, no_data)
    })
}

/// A bar `length` metres long (rounded down to 1, 2 or 5 times a power of ten) at the
/// height `y` of the figure, left-aligned with the map.
fn scale_bar(root: &Area, longest: f64, px: f64, y: u32) -> Result<(), String> {
    let length = plot::round_length(longest);
    let bar = ((length / px).round() as i32).max(1);
    let (x, y) = (LEFT as i32, y as i32);
    root.draw(&Rectangle::new([(x, y), (x + bar, y + 5)], BLACK.filled())).map_err(plot::failed)?;
    for end in [x, x + bar] {
        root.draw(&PathElement::new(vec![(end, y - 4), (end, y + 9)], BLACK.stroke_width(1))).map_err(plot::failed)?;
    }
    root.draw_text(&format!("{} m", tick_label(length)), &font(LABEL), (x + bar + 8, y - 4)).map_err(plot::failed)
}

/// The colour bar: the colours from low to high with ticks in metres and a title, and
/// the grey of cells without data when there are some.
fn colour_bar(
    root: &Area,
    at: (u32, u32),
    height: u32,
    range: Option<(f64, f64)>,
    no_data: bool,
) -> Result<(), String> {
    let area = root.clone().shrink(at, (110, height + 40));
    let (zmin, zmax) = range.unwrap_or((0.0, 1.0));
    let (lo, hi) = if zmax > zmin { (zmin, zmax) } else { (zmin - 0.5e-3, zmin + 0.5e-3) };
    let mut chart = ChartBuilder::on(&area)
        .margin_top(6)
        .margin_bottom(6)
        .right_y_label_area_size(72)
        .build_cartesian_2d(0.0..1.0, plot::ruled(lo, hi))
        .map_err(plot::failed)?;
    let steps = 128;
    chart
        .draw_series((0..steps).map(|k| {
            let (a, b) = (k as f64 / steps as f64, (k + 1) as f64 / steps as f64);
            let [red, green, blue] = colour(a + 0.5 / steps as f64);
            Rectangle::new([(0.0, lo + a * (hi - lo)), (1.0, lo + b * (hi - lo))], RGBColor(red, green, blue).filled())
        }))
        .map_err(plot::failed)?;
    plot::lettered(&mut chart.configure_mesh())
        .disable_mesh()
        .disable_x_axis()
        .y_labels(((height / 40) as usize).max(4))
        .y_label_formatter(&|v| tick_label(*v))
        .y_desc("z [m]")
        .draw()
        .map_err(plot::failed)?;
    chart.plotting_area().draw(&Rectangle::new([(0.0, lo), (1.0, hi)], BLACK.stroke_width(1))).map_err(plot::failed)?;
    if no_data {
        let (x, y) = (at.0 as i32, (at.1 + height + 24) as i32);
        let [red, green, blue] = NO_DATA;
        root.draw(&Rectangle::new([(x, y), (x + 16, y + 12)], RGBColor(red, green, blue).filled()))
            .map_err(plot::failed)?;
        root.draw_text("no data", &font(LABEL), (x + 22, y)).map_err(plot::failed)?;
    }
    Ok(())
}

/// Which section a profile shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Section {
    /// Across the road at this u.
    AtU(f64),
    /// Along the road at this v.
    AtV(f64),
}

/// The elevation along a section, with ticks at 1-2-5 steps on both axes, a grid and a
/// title naming the file and the section; gaps where the road has no elevation.
pub fn profile(cp: &mut ContactPoint, name: &str, section: Section) -> Result<Figure, String> {
    let road = cp.road().clone();
    let (u0, u1) = road.u_range();
    let (v0, v1) = road.v_range();
    let (from, to, along) = match section {
        Section::AtU(_) => (v0, v1, "v [m]"),
        Section::AtV(_) => (u0, u1, "u [m]"),
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
    let title = match section {
        Section::AtU(u) => format!("{name}: elevation across the road at u = {} m", tick_label(u)),
        Section::AtV(v) => format!("{name}: elevation along the road at v = {} m", tick_label(v)),
    };
    Figure::draw(900, 440, None, |root| {
        root.draw_text(&title, &font(TITLE), (LEFT as i32, 14)).map_err(plot::failed)?;
        let mut chart = ChartBuilder::on(root)
            .margin_top(TOP)
            .margin_right(28)
            .margin_bottom(8)
            .x_label_area_size(BELOW)
            .y_label_area_size(LEFT)
            .build_cartesian_2d(plot::ruled(from, to), plot::ruled(zlo, zhi))
            .map_err(plot::failed)?;
        plot::gridded(&mut chart.configure_mesh())
            .x_labels(10)
            .y_labels(8)
            .x_label_formatter(&|v| tick_label(*v))
            .y_label_formatter(&|v| tick_label(*v))
            .x_desc(along)
            .y_desc("z [m]")
            .draw()
            .map_err(plot::failed)?;
        let line = RGBColor(30, 90, 200).stroke_width(2);
        for run in points.split(|p| !p.1.is_finite()).filter(|run| run.len() > 1) {
            chart.draw_series(LineSeries::new(run.iter().copied(), line)).map_err(plot::failed)?;
        }
        chart
            .plotting_area()
            .draw(&Rectangle::new([(from, zlo), (to, zhi)], BLACK.stroke_width(1)))
            .map_err(plot::failed)?;
        Ok(())
    })
}

fn parse_profile(text: &str) -> Result<Section, String> {
    let bad = || format!("--profile '{text}': expected u=NUMBER or v=NUMBER");
    let (axis, value) = text.split_once('=').ok_or_else(bad)?;
    let value: f64 = value.trim().parse().map_err(|_| bad())?;
    match axis.trim() {
        "u" => Ok(Section::AtU(value)),
        "v" => Ok(Section::AtV(value)),
        _ => Err(bad()),
    }
}

/// `opencrg render`: the top view (with a progress bar), or the section `profile` names.
pub(crate) fn run(
    road: &std::path::Path,
    output: &std::path::Path,
    size: usize,
    profile: Option<&str>,
    options: &crate::eval_options::EvalOptions,
    budget: &Budget,
) -> Result<(), String> {
    let section = profile.map(parse_profile).transpose()?;
    let mut cp = crate::eval_options::contact_point(road, options)?;
    let ((u0, u1), (v0, v1)) = (cp.road().u_range(), cp.road().v_range());
    let outside = match section {
        Some(Section::AtU(u)) => (!(u0..=u1).contains(&u)).then_some(format!("u {u0} to {u1} m")),
        Some(Section::AtV(v)) => (!(v0..=v1).contains(&v)).then_some(format!("v {v0} to {v1} m")),
        None => None,
    };
    if let (Some(span), Some(text)) = (outside, profile) {
        return Err(format!("--profile {text}: outside the road, which spans {span}"));
    }
    if !(16..=MAX_SIZE).contains(&size) {
        return Err(format!("--size {size} px: the longer side of a picture takes 16 to {MAX_SIZE} px"));
    }
    let name = crate::files::file_name(road);
    let picture = match section {
        Some(s) => self::profile(&mut cp, &name, s).map_err(|e| format!("{}: {e}", road.display()))?,
        None => {
            let bar = indicatif::ProgressBar::new(0);
            bar.set_style(
                indicatif::ProgressStyle::with_template("rendering {bar:40} {pos}/{len} rows")
                    .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
            );
            let picture = top_view(&mut cp, &name, size, budget, &|row| {
                bar.set_length(bar.length().unwrap_or(0).max(row));
                bar.set_position(row);
            });
            bar.finish_and_clear();
            picture.map_err(|e| format!("{}: {e}", road.display()))?
        }
    };
    picture.write(output)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A road climbing 5 % with a cross slope of 3 %, bumps of 2 mm a metre apart across
    /// its western half (as a CRG record lays them on), a step of 5 cm along its middle.
    #[test]
    fn the_shading_shows_the_texture_on_a_graded_road_and_not_its_grade() {
        let (mw, mh, px) = (200, 60, 0.1);
        let z: Vec<Option<f64>> = (0..mh * mw)
            .map(|k| {
                let (x, y) = ((k % mw) as f64 * px, -((k / mw) as f64) * px);
                let bumps = if x < 10.0 { 0.002 * (2.0 * std::f64::consts::PI * x).sin() } else { 0.0 };
                let step = if k / mw >= mh / 2 { 0.05 } else { 0.0 };
                Some(0.05 * x + 0.03 * y + bumps + step)
            })
            .collect();
        let light = lights(&Raster { z: &z, width: mw, height: mh, px, west: 0.0, north: 0.0 });
        // Away from the step and from where the bumps end.
        let rows = (5..mh / 2 - 5).chain(mh / 2 + 5..mh - 5);
        let span = |cols: std::ops::Range<usize>| {
            let light = &light;
            let values: Vec<f64> = rows.clone().flat_map(|r| cols.clone().map(move |c| light[r * mw + c])).collect();
            values.iter().copied().fold(f64::NEG_INFINITY, f64::max)
                - values.iter().copied().fold(f64::INFINITY, f64::min)
        };
        let (bumps, plain) = (span(5..80), span(125..195));
        assert!(bumps > 0.3, "the bumps: lights from shade to lit, {bumps}");
        assert!(plain < 0.01, "the plain graded road: evenly lit, {plain}");
    }
}
