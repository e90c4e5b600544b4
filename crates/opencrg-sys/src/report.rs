//! The messages that tell what the library did: the core's events (files imported,
//! how the reference line was built, the statistics block, closed-track data, defaults
//! completed, NaN handling: NOTICE; what the reference line's construction found
//! inconsistent or incomplete: WARNING; the relocation: DEBUG) in words, at the levels
//! the reference uses.

use crate::entry::Call;
use crate::msg::{self, DEBUG, NOTICE, WARN};
use opencrg_core::report::{Event, Statistics};

/// Sends one message per event (and per line of the statistics block), in order, each
/// naming the export `call` answers.
pub(crate) fn send(call: &Call, events: Vec<Event>) {
    let func = call.name();
    let send = |level, text: &str| call.send(level, text);
    for event in events {
        match event {
            Event::FileImported(path) => {
                send(NOTICE, &format!("{func}: read the file referenced as <{}>", path.display()))
            }
            Event::LineFromHeading => send(NOTICE, &format!("{func}: reference line x/y integrated from the heading channel")),
            Event::LineZFromSlope => send(NOTICE, &format!("{func}: reference line z integrated from the slope")),
            Event::Line(finding) => send(WARN, &format!("{func}: {finding}")),
            Event::Prepared(s) => statistics(call, &s),
            Event::ClosedTrack(Some((a, b))) => {
                send(NOTICE, &format!("{func}: the reference line can be closed, over u = {a:.3} .. {b:.3}"))
            }
            Event::ClosedTrack(None) => send(NOTICE, &format!("{func}: the reference line cannot be closed")),
            Event::ModifierDefaulted { id, value } => send(
                NOTICE,
                &format!("{func}: {} not given, set to its default {value:.1}", opencrg_core::settings::name(id)),
            ),
            Event::NansHandled(0) => send(NOTICE, &format!("{func}: no NaN in the elevation grid")),
            Event::NansHandled(n) => send(NOTICE, &format!("{func}: {n} NaN cells at the grid borders handled")),
            Event::NansHandledWhereRead => {
                send(NOTICE, &format!("{func}: NaN cells at the grid borders are handled where the grid is read (read in place)"))
            }
            Event::Relocated { center, angle, shift } => send(
                DEBUG,
                &format!(
                    "{func}: road moved: rotated by {angle:.6} rad around ({:.3}, {:.3}), shifted by ({:.3}, {:.3}, {:.3})",
                    center.0, center.1, shift.0, shift.1, shift.2
                ),
            ),
        }
    }
}

/// A line of the lowest or highest elevation (not scanned for a grid read in place).
fn extreme(what: &str, z: f64) -> String {
    if z.is_nan() {
        format!("        {what}               [m]: not scanned (the grid is read in place)")
    } else {
        format!("        {what}               [m]: {z:10.4}")
    }
}

/// The statistics block: the reference's figures in its order, one line a message.
fn statistics(call: &Call, s: &Statistics) {
    if NOTICE > msg::level() {
        return;
    }
    let func = call.name();
    let mut lines = vec![
        String::new(),
        format!("{func}: road statistics"),
        "    elevation of the grid".to_string(),
        format!("        mean at the start     [m]: {:10.4}", s.z_mean_start),
        format!("        mean at the end       [m]: {:10.4}", s.z_mean_end),
        extreme("lowest ", s.z_min),
        extreme("highest", s.z_max),
        "    reference line".to_string(),
        format!("        first u               [m]: {:10.4}", s.u_first),
        format!("        last u                [m]: {:10.4}", s.u_last),
        format!("        start x               [m]: {:10.4}", s.start.0),
        format!("        start y               [m]: {:10.4}", s.start.1),
        format!("        start heading       [rad]: {:10.4}", s.start.2),
        format!("        end x                 [m]: {:10.4}", s.end.0),
        format!("        end y                 [m]: {:10.4}", s.end.1),
        format!("        end heading         [rad]: {:10.4}", s.end.2),
        "    v range".to_string(),
        format!("        right border v        [m]: {:10.4}", s.v_first),
        format!("        left border v         [m]: {:10.4}", s.v_last),
        "    curvature of the reference line".to_string(),
        format!("        tightest right      [1/m]: {:10.4}", s.curvature_right),
        format!("        tightest left       [1/m]: {:10.4}", s.curvature_left),
    ];
    if let Some((first, last)) = s.banking {
        lines.push("    banking".to_string());
        lines.push(format!("        at the start        [m/m]: {first:10.4}"));
        lines.push(format!("        at the end          [m/m]: {last:10.4}"));
    }
    lines.push("    elevation of the reference line".to_string());
    lines.push(format!("        at the start          [m]: {:10.4}", s.z_line.0));
    lines.push(format!("        at the end            [m]: {:10.4}", s.z_line.1));
    lines.push(format!("{func}: end of road statistics"));
    lines.push(String::new());
    for line in lines {
        call.send(NOTICE, &line);
    }
}
