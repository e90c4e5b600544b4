//! The contact point options the evaluating commands take (`eval`, `render`, `export`,
//! `view`), and the road they evaluate prepared as the classic C API prepares it.

use crate::files::{load, Failure};
use clap::ValueEnum;
use opencrg_core::settings;
use opencrg_core::{ContactPoint, Continuation, CpOption};
use std::path::Path;
use std::sync::Arc;

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum BorderMode {
    None,
    Zero,
    Keep,
    Repeat,
    Reflect,
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum CurvMode {
    Lateral,
    Refline,
}

/// Evaluation options, as the contact point options of the C API.
#[derive(clap::Args)]
pub(crate) struct EvalOptions {
    /// Border mode beyond the ends of the road.
    #[arg(long, value_enum)]
    border_mode_u: Option<BorderMode>,
    /// Border mode beyond the sides of the road.
    #[arg(long, value_enum)]
    border_mode_v: Option<BorderMode>,
    /// z offset beyond the ends.
    #[arg(long)]
    border_offset_u: Option<f64>,
    /// z offset beyond the sides.
    #[arg(long)]
    border_offset_v: Option<f64>,
    /// Length of the smoothing zone at the start [m].
    #[arg(long)]
    smooth_begin: Option<f64>,
    /// Length of the smoothing zone at the end [m].
    #[arg(long)]
    smooth_end: Option<f64>,
    /// Curvature of the reference line, or of the parallel at v (lateral, the default).
    #[arg(long, value_enum)]
    curv_mode: Option<CurvMode>,
    /// Continue a closed reference line around the track.
    #[arg(long)]
    close_track: bool,
    /// Evaluate the road as read, without crgCheck and the file's modifiers.
    #[arg(long)]
    raw: bool,
}

/// The road prepared as the classic C API prepares it (check, modifiers), and a
/// contact point with the options asked for.
pub(crate) fn contact_point(path: &Path, o: &EvalOptions) -> Result<ContactPoint, Failure> {
    let mut road = load(path)?;
    if !o.raw {
        if let Err(e) = road.check() {
            eprintln!("opencrg: warning: {}: {e}", path.display());
        }
        road.apply_modifiers();
    }
    let mut cp = ContactPoint::new(Arc::new(road));
    let mode = |m: BorderMode| match m {
        BorderMode::None => settings::BorderMode::None,
        BorderMode::Zero => settings::BorderMode::ExZero,
        BorderMode::Keep => settings::BorderMode::ExKeep,
        BorderMode::Repeat => settings::BorderMode::Repeat,
        BorderMode::Reflect => settings::BorderMode::Reflect,
    };
    let options = [
        o.border_mode_u.map(|m| CpOption::BorderModeU(mode(m))),
        o.border_mode_v.map(|m| CpOption::BorderModeV(mode(m))),
        o.border_offset_u.map(CpOption::BorderOffsetU),
        o.border_offset_v.map(CpOption::BorderOffsetV),
        o.smooth_begin.map(CpOption::SmoothUBegin),
        o.smooth_end.map(CpOption::SmoothUEnd),
        o.curv_mode.map(|c| {
            CpOption::CurvMode(match c {
                CurvMode::Lateral => opencrg_core::CurvMode::Lateral,
                CurvMode::Refline => opencrg_core::CurvMode::RefLine,
            })
        }),
        o.close_track.then_some(CpOption::RefLineContinue(Continuation::CloseTrack)),
    ];
    for option in options.into_iter().flatten() {
        cp.set_option(option).map_err(|e| e.to_string())?;
    }
    Ok(cp)
}
