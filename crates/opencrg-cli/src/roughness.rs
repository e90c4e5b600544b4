//! `opencrg roughness`: the IRI and the ISO 8608 class of a road's wheel tracks, as a
//! table, as JSON, and as a figure (the densities on log-log axes among the class
//! bands, the IRI segment by segment along u).

use crate::plot::{self, font, tick_label, Figure, AXIS, TITLE};
use opencrg_tools::drawing::{REFERENCE_GREY, TRACK_COLOURS};
use opencrg_tools::psd::{CLASSES, CLASS_LIMITS, N0};
use opencrg_tools::roughness::Track;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use serde_json::{json, Value};

/// A number with `digits` decimals, or "-" for none.
fn fixed(x: Option<f64>, digits: usize) -> String {
    x.map_or_else(|| "-".into(), |x| format!("{x:.digits$}"))
}

/// The readable table.
pub fn text(tracks: &[Track], name: &str, segment: f64) -> String {
    let mut out = format!("{name}: roughness of {} tracks (IRI per {segment} m)\n\n", tracks.len());
    out.push_str("track v [m]  IRI [m/km]  Gd(n0) [m^3]  class  w (fitted)  skipped [m]\n");
    for t in tracks {
        out.push_str(&format!(
            "{:>11.3}  {:>10.3}  {:>13.3e}  {:>5}  {:>10.2}  {:>11.2}\n",
            t.v, t.iri, t.psd.gd_n0, t.psd.class, t.psd.w, t.skipped
        ));
    }
    if let Some(first) = tracks.first() {
        out.push_str("\nIRI [m/km] per segment\n");
        out.push_str(&format!("{:>10} {:>10}", "u from", "u to"));
        for t in tracks {
            out.push_str(&format!(" {:>12}", format!("v = {}", t.v)));
        }
        out.push('\n');
        for (k, s) in first.segments.iter().enumerate() {
            out.push_str(&format!("{:>10.1} {:>10.1}", s.u_start, s.u_end));
            for t in tracks {
                out.push_str(&format!(" {:>12}", fixed(t.segments.get(k).and_then(|s| s.iri), 3)));
            }
            out.push('\n');
        }
        let p = &first.psd;
        out.push_str(&format!(
            "\nPSD: Welch, {} segments of {} samples (Hann, half overlapping, linear trend removed), third-octave bands, fitted over {:.4}-{:.3} cycles/m\n",
            p.segments, p.segment_samples, p.fitted.0, p.fitted.1
        ));
    }
    out
}

/// The JSON form: IRI in m/km, Gd(n0) in m³.
pub fn json(tracks: &[Track], segment: f64) -> Value {
    let tracks: Vec<Value> = tracks
        .iter()
        .map(|t| {
            json!({
                "v": t.v,
                "iri": t.iri,
                "skipped_m": t.skipped,
                "segments": t.segments.iter().map(|s| json!({"u_start": s.u_start, "u_end": s.u_end, "iri": s.iri})).collect::<Vec<_>>(),
                "psd": {
                    "gd_n0": t.psd.gd_n0,
                    "w": t.psd.w,
                    "gd_n0_fitted_w": t.psd.gd_n0_free,
                    "class": t.psd.class.to_string(),
                    "n_fitted": [t.psd.fitted.0, t.psd.fitted.1],
                    "bands": t.psd.bands.iter().map(|(n, g)| json!([n, g])).collect::<Vec<_>>(),
                    "segment_samples": t.psd.segment_samples,
                    "segments": t.psd.segments,
                },
            })
        })
        .collect();
    json!({ "segment_m": segment, "tracks": tracks })
}

const CLASS_LINE: RGBColor = RGBColor(REFERENCE_GREY[0], REFERENCE_GREY[1], REFERENCE_GREY[2]);
/// The tracks' colours (the drawing rules'), in turn.
fn track_colours() -> impl Iterator<Item = RGBColor> {
    TRACK_COLOURS.iter().map(|&[r, g, b]| RGBColor(r, g, b)).cycle()
}

/// The spatial frequencies the density panel shows, cycles/m (a hair wider than three
/// decades, so that rounding keeps both ends' labels).
const N_RANGE: (f64, f64) = (0.01 * (1.0 - 1e-9), 10.0 * (1.0 + 1e-9));
/// The densities the panel shows at least (m³): every class band has room for its letter.
const GD_RANGE: (f64, f64) = (1e-9, 1e-1);
const LEFT: u32 = 92;

/// log10 of the class band's middle at n0: between its limits, half a band below A's
/// upper limit and above G's.
fn class_middle(k: usize) -> f64 {
    let half = 4f64.log10() / 2.0;
    match k {
        0 => CLASS_LIMITS[0].log10() - half,
        k if k == CLASS_LIMITS.len() => CLASS_LIMITS[k - 1].log10() + half,
        k => (CLASS_LIMITS[k - 1].log10() + CLASS_LIMITS[k].log10()) / 2.0,
    }
}

/// The line Gd(n) = Gd(n0) (n / n0)^-2 through log10 Gd(n0) = `at_n0`, cut to the panel.
fn class_line(at_n0: f64, (g_lo, g_hi): (f64, f64)) -> Option<[(f64, f64); 2]> {
    let n_at = |g: f64| 10f64.powf(N0.log10() + (at_n0 - g.log10()) / 2.0);
    let a = n_at(g_hi).max(N_RANGE.0);
    let b = n_at(g_lo).min(N_RANGE.1);
    let gd = |n: f64| 10f64.powf(at_n0 - 2.0 * (n.log10() - N0.log10()));
    (a < b).then(|| [(a, gd(a)), (b, gd(b))])
}

/// The figure: above, each track's displacement PSD on log-log axes among the ISO 8608
/// class bands, their letters along the bands; below, the IRI per segment as steps
/// along u. A legend names each track.
pub fn plot(tracks: &[Track], name: &str, segment: f64) -> Result<Figure, String> {
    let bands = tracks.iter().flat_map(|t| t.psd.bands.iter().map(|b| b.1)).filter(|g| *g > 0.0);
    let (g_min, g_max) = bands.fold(GD_RANGE, |(a, b), g| (a.min(g), b.max(g)));
    let g_range = (10f64.powf(g_min.log10().floor()) * (1.0 - 1e-9), 10f64.powf(g_max.log10().ceil()) * (1.0 + 1e-9));
    Figure::draw(900, 860, None, |root| {
        let (upper, lower) = root.split_vertically(520);
        plot_psd(&upper, tracks, name, g_range)?;
        plot_iri(&lower, tracks, segment)
    })
}

/// The upper panel: each track's displacement PSD over the ISO 8608 classes.
fn plot_psd(area: &plot::Area, tracks: &[Track], name: &str, g_range: (f64, f64)) -> Result<(), String> {
    area.draw_text(&format!("{name}: displacement PSD and ISO 8608 classes"), &font(TITLE), (LEFT as i32, 14))
        .map_err(plot::failed)?;
    let mut psd = ChartBuilder::on(area)
        .margin_top(44)
        .margin_right(28)
        .x_label_area_size(52)
        .y_label_area_size(LEFT)
        .build_cartesian_2d((N_RANGE.0..N_RANGE.1).log_scale(), (g_range.0..g_range.1).log_scale())
        .map_err(plot::failed)?;
    plot::gridded(&mut psd.configure_mesh())
        .x_labels(8)
        .y_labels(12)
        .x_label_formatter(&|n| plot::decade_label(*n))
        .y_label_formatter(&|g| plot::decade_label(*g))
        .x_desc("n [cycles/m]")
        .y_desc("Gd(n) [m³]")
        .draw()
        .map_err(plot::failed)?;
    let (g_lo, g_hi) = (g_range.0.log10(), g_range.1.log10());
    for limit in CLASS_LIMITS {
        if let Some(line) = class_line(limit.log10(), g_range) {
            psd.draw_series(LineSeries::new(line, CLASS_LINE.stroke_width(1))).map_err(plot::failed)?;
        }
    }
    // Each letter on its band's middle line, at the first of these frequencies (the
    // right half first, where the densities of roads tend to be low) where it lies
    // well inside the panel.
    for (k, letter) in CLASSES.iter().enumerate() {
        let middle = class_middle(k);
        let place = [2.0, 1.0, 5.0, 0.5, 0.2, 0.1, 0.05, 0.02].into_iter().find_map(|n: f64| {
            let g = middle - 2.0 * (n.log10() - N0.log10());
            (g > g_lo + 0.3 && g < g_hi - 0.3).then(|| (n, 10f64.powf(g)))
        });
        if let Some(at) = place {
            psd.draw_series(std::iter::once(Text::new(
                letter.to_string(),
                at,
                font(AXIS).color(&CLASS_LINE).pos(Pos::new(HPos::Center, VPos::Center)),
            )))
            .map_err(plot::failed)?;
        }
    }
    for (t, colour) in tracks.iter().zip(track_colours()) {
        let points: Vec<(f64, f64)> = t.psd.bands.iter().filter(|b| b.1 > 0.0).copied().collect();
        let style = colour.stroke_width(2);
        psd.draw_series(LineSeries::new(points.iter().copied(), style))
            .map_err(plot::failed)?
            .label(format!("v = {} m (class {})", tick_label(t.v), t.psd.class))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
        psd.draw_series(points.iter().map(|&p| Circle::new(p, 3, colour.filled()))).map_err(plot::failed)?;
    }
    plot::legend(&mut psd)?;
    Ok(())
}

/// The lower panel: the IRI per segment, steps along u.
fn plot_iri(area: &plot::Area, tracks: &[Track], segment: f64) -> Result<(), String> {
    let segments = tracks.iter().flat_map(|t| t.segments.iter());
    let (u0, u1, i_max) = segments.fold((f64::INFINITY, f64::NEG_INFINITY, 0.0f64), |(a, b, m), s| {
        (a.min(s.u_start), b.max(s.u_end), m.max(s.iri.unwrap_or(0.0)))
    });
    let (u0, u1) = if u1 > u0 { (u0, u1) } else { (0.0, 1.0) };
    let i_hi = if i_max > 0.0 { i_max * 1.15 } else { 1.0 };
    area.draw_text(&format!("IRI per {} m segment", tick_label(segment)), &font(TITLE), (LEFT as i32, 8))
        .map_err(plot::failed)?;
    let mut iri = ChartBuilder::on(area)
        .margin_top(36)
        .margin_right(28)
        .margin_bottom(8)
        .x_label_area_size(52)
        .y_label_area_size(LEFT)
        .build_cartesian_2d(plot::ruled(u0, u1), plot::ruled(0.0, i_hi))
        .map_err(plot::failed)?;
    plot::gridded(&mut iri.configure_mesh())
        .x_labels(10)
        .y_labels(6)
        .x_label_formatter(&|v| tick_label(*v))
        .y_label_formatter(&|v| tick_label(*v))
        .x_desc("u [m]")
        .y_desc("IRI [m/km]")
        .draw()
        .map_err(plot::failed)?;
    for (t, colour) in tracks.iter().zip(track_colours()) {
        let style = colour.stroke_width(2);
        // Consecutive segments with an IRI join into one stepped line.
        let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
        for s in &t.segments {
            match s.iri {
                Some(v) => runs.last_mut().map_or((), |run| run.extend([(s.u_start, v), (s.u_end, v)])),
                None => runs.push(Vec::new()),
            }
        }
        let mut first = true;
        for run in runs.into_iter().filter(|r| !r.is_empty()) {
            let drawn = iri.draw_series(LineSeries::new(run, style)).map_err(plot::failed)?;
            if std::mem::take(&mut first) {
                drawn
                    .label(format!("v = {} m", tick_label(t.v)))
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
            }
        }
    }
    plot::legend(&mut iri)?;
    Ok(())
}

/// `opencrg roughness`: the road's wheel tracks (`tracks`, or the default three) as text
/// or JSON, and a figure where `plot` names one.
pub(crate) fn run(
    road: &std::path::Path,
    tracks: Vec<f64>,
    segment: f64,
    json: bool,
    plot: Option<&std::path::Path>,
) -> Result<(), String> {
    let mut r = crate::files::load(road)?;
    if let Err(e) = r.check() {
        eprintln!("opencrg: warning: {}: {e}", road.display());
    }
    r.apply_modifiers();
    let tracks = if tracks.is_empty() { opencrg_tools::roughness::DEFAULT_TRACKS.to_vec() } else { tracks };
    let found = opencrg_tools::roughness::roughness(&std::sync::Arc::new(r), &tracks, segment)
        .map_err(|e| format!("{}: {e}", road.display()))?;
    for t in found.iter().filter(|t| t.skipped > 0.0) {
        eprintln!("opencrg: warning: track at v = {} m: {:.2} m without elevation left out", t.v, t.skipped);
    }
    if json {
        println!("{}", serde_json::to_string_pretty(&self::json(&found, segment)).map_err(|e| e.to_string())?);
    } else {
        print!("{}", text(&found, &road.display().to_string(), segment));
    }
    if let Some(out) = plot {
        self::plot(&found, &crate::files::file_name(road), segment).and_then(|figure| figure.write(out))?;
    }
    Ok(())
}
