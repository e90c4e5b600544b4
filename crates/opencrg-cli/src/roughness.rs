//! `opencrg roughness`: the IRI and the ISO 8608 class of a road's wheel tracks, as a
//! table, as JSON, and as a picture (the densities on log-log axes among the class
//! bands, the IRI segment by segment along u).

use crate::canvas::{Canvas, Rgb, BLACK};
use opencrg::psd::{CLASSES, CLASS_LIMITS, N0};
use opencrg::roughness::Track;
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

const COLOURS: [Rgb; 6] = [[30, 90, 200], [200, 60, 40], [40, 150, 60], [150, 60, 170], [220, 140, 20], [0, 0, 0]];
const GREY: Rgb = [170, 170, 170];

/// A panel's frame and its pixel area: (left, top, width, height).
fn frame(canvas: &mut Canvas, left: i64, top: i64, w: i64, h: i64) {
    canvas.fill(left, top, w, h, [248, 248, 248]);
    let (l, t, r, b) = (left as f64, top as f64, (left + w) as f64, (top + h) as f64);
    for (x0, y0, x1, y1) in [(l, t, r, t), (l, b, r, b), (l, t, l, b), (r, t, r, b)] {
        canvas.line(x0, y0, x1, y1, BLACK);
    }
}

/// The picture: densities and class bands above, IRI along u below.
pub fn plot(tracks: &[Track]) -> Canvas {
    let (w, h) = (900usize, 760usize);
    let mut canvas = Canvas::new(w, h);
    let (left, pw) = (96i64, w as i64 - 96 - 24);
    // The density panel: log10 n across, log10 Gd up.
    let (top, ph) = (28i64, 380i64);
    frame(&mut canvas, left, top, pw, ph);
    let (n_lo, n_hi) = (-2.0f64, 1.0f64);
    let bands = tracks.iter().flat_map(|t| t.psd.bands.iter().map(|b| b.1.log10()));
    let (g_min, g_max) = bands.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), g| (a.min(g), b.max(g)));
    let (g_lo, g_hi) = if g_min.is_finite() { (g_min.floor() - 1.0, g_max.ceil() + 1.0) } else { (-10.0, -2.0) };
    let px = |n: f64, g: f64| {
        (left as f64 + (n - n_lo) / (n_hi - n_lo) * pw as f64, top as f64 + (g_hi - g) / (g_hi - g_lo) * ph as f64)
    };
    let inside = |p: (f64, f64)| p.1 >= top as f64 && p.1 <= (top + ph) as f64;
    // Class limits: Gd(n) = limit · (n / n0)^-2, with the letters between them at n0.
    for (k, limit) in CLASS_LIMITS.iter().enumerate() {
        let line = |n: f64| px(n, limit.log10() - 2.0 * (n - N0.log10()));
        let steps = 60;
        for s in 0..steps {
            let (a, b) =
                (n_lo + (n_hi - n_lo) * s as f64 / steps as f64, n_lo + (n_hi - n_lo) * (s + 1) as f64 / steps as f64);
            let (p, q) = (line(a), line(b));
            if inside(p) && inside(q) {
                canvas.line(p.0, p.1, q.0, q.1, GREY);
            }
        }
        let mid = if k == 0 { limit.log10() - 0.3 } else { (limit.log10() + CLASS_LIMITS[k - 1].log10()) / 2.0 };
        let p = px(N0.log10(), mid);
        if inside(p) {
            canvas.text(p.0 as i64 - 2, p.1 as i64 - 3, &CLASSES[k].to_string(), 1, GREY);
        }
    }
    for (t, colour) in tracks.iter().zip(COLOURS.iter().cycle()) {
        let points: Vec<(f64, f64)> =
            t.psd.bands.iter().filter(|b| b.1 > 0.0).map(|b| px(b.0.log10(), b.1.log10())).collect();
        for pair in points.windows(2) {
            canvas.line(pair[0].0, pair[0].1, pair[1].0, pair[1].1, *colour);
        }
        for p in &points {
            canvas.fill(p.0 as i64 - 2, p.1 as i64 - 2, 5, 5, *colour);
        }
    }
    canvas.text(left, 8, "displacement PSD Gd(n) [m^3] and the ISO 8608 classes", 1, BLACK);
    for (n, label) in [(-2.0, "0.01"), (-1.0, "0.1"), (0.0, "1"), (1.0, "10")] {
        let p = px(n, g_lo);
        canvas.text(p.0 as i64 - 8, top + ph + 6, label, 1, BLACK);
    }
    canvas.text(left + pw / 2 - 60, top + ph + 20, "n [cycles/m]", 1, BLACK);
    canvas.text(4, top, &format!("1e{}", g_hi as i64), 1, BLACK);
    canvas.text(4, top + ph - 7, &format!("1e{}", g_lo as i64), 1, BLACK);

    // The IRI panel: u across, IRI up, one step line per track.
    let (top2, ph2) = (top + ph + 64, 220i64);
    frame(&mut canvas, left, top2, pw, ph2);
    let segments = tracks.iter().flat_map(|t| t.segments.iter());
    let (u0, u1, i_max) = segments.fold((f64::INFINITY, f64::NEG_INFINITY, 0.0f64), |(a, b, m), s| {
        (a.min(s.u_start), b.max(s.u_end), m.max(s.iri.unwrap_or(0.0)))
    });
    let i_hi = if i_max > 0.0 { i_max * 1.1 } else { 1.0 };
    let span = if u1 > u0 { u1 - u0 } else { 1.0 };
    let px2 =
        |u: f64, iri: f64| (left as f64 + (u - u0) / span * pw as f64, top2 as f64 + (i_hi - iri) / i_hi * ph2 as f64);
    for (t, colour) in tracks.iter().zip(COLOURS.iter().cycle()) {
        for s in &t.segments {
            if let Some(iri) = s.iri {
                let (a, b) = (px2(s.u_start, iri), px2(s.u_end, iri));
                canvas.line(a.0, a.1, b.0, b.1, *colour);
                canvas.line(a.0, a.1 + 1.0, b.0, b.1 + 1.0, *colour);
            }
        }
    }
    canvas.text(left, top2 - 16, "IRI [m/km] per segment along u", 1, BLACK);
    canvas.text(4, top2, &format!("{i_hi:.2}"), 1, BLACK);
    canvas.text(4, top2 + ph2 - 7, "0", 1, BLACK);
    canvas.text(left, top2 + ph2 + 6, &format!("{u0:.0} m"), 1, BLACK);
    let end = format!("{u1:.0} m");
    canvas.text(left + pw - Canvas::text_width(&end, 1), top2 + ph2 + 6, &end, 1, BLACK);
    // The legend: one colour per track.
    let mut x = left;
    for (t, colour) in tracks.iter().zip(COLOURS.iter().cycle()) {
        let label = format!("v = {} m", t.v);
        canvas.fill(x, h as i64 - 18, 10, 7, *colour);
        canvas.text(x + 14, h as i64 - 18, &label, 1, BLACK);
        x += Canvas::text_width(&label, 1) + 40;
    }
    canvas
}
