//! Contact points: a road, a set of options and a search history.

use crate::base::error::{Error, Result};
use crate::base::settings::{opt, Settings};
use crate::model::road::Road;
use crate::model::tiles::{Pin, Tiles};
use crate::query::eval::{self, EvalOptions};
use crate::query::plain::{near_tile_end, CellTerms, PlainCell, PlainGrid, WINDOWS};
use crate::query::search::{self, History, DEFAULT_HISTORY};
use std::sync::Arc;

/// Close and far search distances a new contact point starts with.
const DEFAULT_CLOSE: f64 = 0.3;
const DEFAULT_FAR: f64 = 2.2;

/// A contact point's x/y search history, to carry it elsewhere (a copy of the contact
/// point in another process, say): the ring's size, the squared close and far distances,
/// and the entries, newest first (each an earlier point and the reference line point its
/// search ended at).
#[derive(Debug, Clone, PartialEq)]
pub struct SearchHistory {
    /// How many entries the ring holds.
    pub size: usize,
    /// The squared distance under which an entry is a close hit.
    pub close_squared: f64,
    /// The squared distance under which an entry is a far hit.
    pub far_squared: f64,
    /// (x, y, reference line point index), newest first.
    pub entries: Vec<(f64, f64, usize)>,
}

/// The tiles of a road read in place that a contact point keeps pinned, window `k` of its
/// [`PlainGrid`] the tile `pins[k]`, the one entered last first, and the pool they are
/// pinned in (kept alive by it until they are handed back). A copy pins nothing.
#[derive(Debug, Default)]
struct Windows {
    tiles: Option<Arc<Tiles>>,
    pins: [Option<Pin>; WINDOWS],
}

impl Clone for Windows {
    fn clone(&self) -> Self {
        Windows::default()
    }
}

impl Windows {
    /// Hands every pin back.
    fn release(&mut self) {
        if let Some(tiles) = &self.tiles {
            for pin in self.pins.iter_mut().filter_map(Option::take) {
                tiles.unpin(pin);
            }
        }
    }
}

impl Drop for Windows {
    fn drop(&mut self) {
        self.release();
    }
}

/// Evaluates a road with its own options and x/y search history.
///
/// Contact points are cheap; give each thread (or each wheel) its own. The road is
/// shared and never changed by evaluation.
#[derive(Debug)]
pub struct ContactPoint {
    road: Arc<Road>,
    options: Settings,
    eval: EvalOptions,
    /// The common case of the elevation lookup, from `road` and `eval` (for a road read in
    /// place, with the window of `windows`).
    plain: PlainGrid,
    /// The tiles pinned for `plain`'s window, for a road read in place.
    windows: Windows,
    /// The terms of the cell the last lookup of the common case read (through
    /// [`ContactPoint::uv_to_z_plain`] or [`ContactPoint::z_of_found`]), from `road`.
    last: CellTerms,
    history: History,
}

/// An elevation, or the error of a border mode that refuses.
#[inline(always)]
fn elevation(z: Option<f64>) -> Result<f64> {
    // A match, not `ok_or`: building (and dropping) an unused error costs in this hot path.
    match z {
        Some(z) => Ok(z),
        None => Err(Error::OutOfRange(std::borrow::Cow::Borrowed(
            "evaluation refused: outside the road with border mode none",
        ))),
    }
}

#[inline]
fn finite(a: f64, b: f64) -> Result<()> {
    if a.is_nan() || b.is_nan() {
        Err(Error::OutOfRange(std::borrow::Cow::Borrowed("evaluation refused: NaN input")))
    } else {
        Ok(())
    }
}

impl Clone for ContactPoint {
    /// A contact point with the same road, options and history (and no tile pinned).
    fn clone(&self) -> Self {
        let mut plain = self.plain;
        plain.clear_windows();
        ContactPoint {
            road: self.road.clone(),
            options: self.options.clone(),
            eval: self.eval,
            plain,
            windows: Windows::default(),
            last: self.last,
            history: self.history.clone(),
        }
    }
}

impl ContactPoint {
    /// A contact point on `road`, starting with the road's default options.
    pub fn new(road: Arc<Road>) -> Self {
        let options = road.options().clone();
        let history = History::new(DEFAULT_HISTORY, DEFAULT_CLOSE * DEFAULT_CLOSE, DEFAULT_FAR * DEFAULT_FAR);
        let eval = EvalOptions::from(&options);
        let plain = PlainGrid::new(&road, &eval);
        ContactPoint { road, options, eval, plain, windows: Windows::default(), last: CellTerms::NONE, history }
    }

    /// The road evaluated.
    pub fn road(&self) -> &Arc<Road> {
        &self.road
    }

    /// Evaluates another road (for example the same data after modifiers were
    /// applied); options and history are kept.
    pub fn set_road(&mut self, road: Arc<Road>) {
        self.plain = PlainGrid::new(&road, &self.eval);
        self.windows = Windows::default();
        self.last = CellTerms::NONE;
        self.road = road;
    }

    /// The options in force.
    pub fn options(&self) -> &Settings {
        &self.options
    }

    /// Changes the options through `f` and refreshes what evaluation reads from them:
    /// the one way options change, so the two never disagree.
    fn edit_options<R>(&mut self, f: impl FnOnce(&mut Settings) -> R) -> R {
        let r = f(&mut self.options);
        self.eval = EvalOptions::from(&self.options);
        self.plain = PlainGrid::new(&self.road, &self.eval);
        self.windows = Windows::default();
        self.last = CellTerms::NONE;
        r
    }

    /// Sets an integer option; refused: an integer that is not one of the option's
    /// choices ([`settings::check`](crate::settings::check)).
    pub fn set_option_int(&mut self, id: u32, value: i32) -> Result<()> {
        crate::base::settings::check(id, crate::base::settings::Value::Int(value))?;
        self.set_option_int_as_reference(id, value)
    }

    /// Sets an integer option as the reference library sets it: any integer, a choice
    /// out of range then evaluating as the reference's evaluation takes it (the C API's
    /// setter, for the programs written for the reference).
    pub fn set_option_int_as_reference(&mut self, id: u32, value: i32) -> Result<()> {
        Ok(self.edit_options(|o| o.set_int(id, value))?)
    }

    /// Sets a double option. The search options act at once: `REFLINE_SEARCH_U` and
    /// `REFLINE_SEARCH_U_FRAC` preload the history, the close and far distances
    /// change the history's criteria.
    pub fn set_option_double(&mut self, id: u32, value: f64) -> Result<()> {
        let line = &self.road.line;
        match id {
            opt::REFLINE_SEARCH_U => self.history.preload(line, value),
            opt::REFLINE_SEARCH_U_FRAC if (0.0..=1.0).contains(&value) => {
                self.history.preload(line, line.u_first + value * (line.u_last - line.u_first))
            }
            opt::REFLINE_CLOSE => self.history.set_close(value),
            opt::REFLINE_FAR => self.history.set_far(value),
            _ => {}
        }
        Ok(self.edit_options(|o| o.set_double(id, value))?)
    }

    /// Sets an option with a typed value (see [`CpOption`](crate::CpOption)),
    /// with the effects of [`ContactPoint::set_option_int`] and
    /// [`ContactPoint::set_option_double`]; a check switched off is removed.
    pub fn set_option(&mut self, option: crate::base::setting_values::CpOption) -> Result<()> {
        match option.entry() {
            (id, Some(value)) => self.set_option_value(id, value),
            (id, None) => {
                self.remove_option(id);
                Ok(())
            }
        }
    }

    /// Sets an option by identifier: [`ContactPoint::set_option_int`] or
    /// [`ContactPoint::set_option_double`] as the value's type says.
    pub fn set_option_value(&mut self, id: u32, value: crate::base::settings::Value) -> Result<()> {
        match value {
            crate::base::settings::Value::Int(i) => self.set_option_int(id, i),
            crate::base::settings::Value::Double(d) => self.set_option_double(id, d),
        }
    }

    /// Removes one option (the evaluation then behaves as with the option absent).
    pub fn remove_option(&mut self, id: u32) -> bool {
        self.edit_options(|o| o.remove(id))
    }

    /// Removes every option.
    pub fn clear_options(&mut self) {
        self.edit_options(Settings::clear);
    }

    /// Restores the library's default options and search distances.
    pub fn reset_options(&mut self) {
        self.edit_options(Settings::reset_options);
        let _ = self.set_option_double(opt::REFLINE_CLOSE, DEFAULT_CLOSE);
        let _ = self.set_option_double(opt::REFLINE_FAR, DEFAULT_FAR);
    }

    /// Gives the history `size` entries (emptied). The close and far distances stay:
    /// the reference meant to reset them to 10 and 100 u increments, but its test for
    /// that never passes, and its answers follow what it does.
    pub fn set_history(&mut self, size: usize) -> Result<()> {
        if self.history.resize(size) {
            Ok(())
        } else {
            Err(crate::base::error::Error::out_of_range(format!(
                "a search history of {size} entries: the system refused the memory; the history is unchanged"
            )))
        }
    }

    /// The x/y search history as it stands.
    pub fn search_history(&self) -> SearchHistory {
        let (size, close_squared, far_squared, entries) = self.history.state();
        SearchHistory { size, close_squared, far_squared, entries }
    }

    /// Replaces the x/y search history (as another contact point's
    /// [`ContactPoint::search_history`] gave it): the searches that follow start as that
    /// contact point's would.
    pub fn set_search_history(&mut self, h: &SearchHistory) {
        self.history = History::from_state(h.size, h.close_squared, h.far_squared, &h.entries);
    }

    /// x/y of (u, v).
    #[inline]
    pub fn uv_to_xy(&self, u: f64, v: f64) -> Result<(f64, f64)> {
        finite(u, v)?;
        Ok(eval::uv_to_xy(&self.road, &self.eval, u, v))
    }

    /// Elevation at (u, v); an error where a border mode of none refuses.
    #[inline(always)]
    pub fn uv_to_z(&self, u: f64, v: f64) -> Result<f64> {
        self.road.prefetch_cells(u, v);
        self.uv_to_z_fetched(u, v)
    }

    /// [`ContactPoint::uv_to_z`] without starting the grid's memory fetch (the caller
    /// started it earlier).
    #[inline]
    fn uv_to_z_fetched(&self, u: f64, v: f64) -> Result<f64> {
        // The common case's lean path first (the same answers; measured 5-10 % faster
        // than the general path's own check for it), the general one for the rest.
        match self.plain.cell(u, v) {
            Some(cell) => Ok(self.plain_elevation(&cell)),
            None => self.uv_to_z_other(u, v),
        }
    }

    /// The elevation at a cell of the common case, read from the road's grid in memory or
    /// the window's pinned tile.
    #[inline(always)]
    pub(crate) fn plain_elevation(&self, cell: &PlainCell) -> f64 {
        // SAFETY: `plain` was made from `road`, which the contact point holds (the two
        // change together), its window's tile is pinned by `windows`, and the contact
        // point's cells come from `plain`.
        unsafe { self.plain.elevation(&self.plain.terms(cell), cell) }
    }

    /// [`ContactPoint::uv_to_z`] outside the common case's window: a cell of a grid read in
    /// place (its tile read where it is), else the path that handles every case.
    #[inline(never)]
    pub(crate) fn uv_to_z_other(&self, u: f64, v: f64) -> Result<f64> {
        if let Some(cell) = self.plain.road_cell(u, v).filter(|_| self.plain.in_place()) {
            // SAFETY: `plain` was made from `road`, which the contact point holds, and
            // `cell` from `plain`.
            if let Some(terms) = unsafe { self.plain.tile_terms(&cell) } {
                // SAFETY: as above.
                return Ok(unsafe { self.plain.elevation(&terms, &cell) });
            }
        }
        self.uv_to_z_general(u, v)
    }

    /// [`ContactPoint::uv_to_z`] through the path that handles every case.
    #[inline]
    pub(crate) fn uv_to_z_general(&self, u: f64, v: f64) -> Result<f64> {
        finite(u, v)?;
        self.read(elevation(eval::uv_to_z(&self.road, &self.eval, u, v)))
    }

    /// An elevation answered NaN by a road read in place that could not read its file
    /// becomes the error naming the file.
    #[inline(always)]
    fn read(&self, z: Result<f64>) -> Result<f64> {
        match z {
            Ok(z) if z.is_nan() => match self.road.grid.fault() {
                Some(e) => Err(e),
                None => Ok(z),
            },
            other => other,
        }
    }

    /// Asks the processor to start loading a cell of the common case into the
    /// second-level cache (see `PlainGrid::prefetch_far`).
    #[inline(always)]
    pub(crate) fn plain_prefetch_far(&self, cell: &PlainCell) {
        self.plain.prefetch_far(cell);
    }

    /// The grid cell of (u, v) when the point is of the common case the elevation
    /// lookup's lean path handles (see [`PlainCell`]).
    #[inline(always)]
    pub(crate) fn plain_cell(&self, u: f64, v: f64) -> Option<PlainCell> {
        self.plain.cell(u, v)
    }

    /// A real-time call: the elevation at (u, v) for the common case only (inside an
    /// evenly spaced grid held in memory or in a window of a road read in place, no
    /// smoothing zone), `None` for every other case, where [`ContactPoint::uv_to_z`] (or
    /// [`ContactPoint::z_of_found`]) answers with the same bits. Also asks for the grid
    /// a wheel moving on will read next. Never panics, allocates or calls anything: the
    /// C library's `crgEvaluv2z` starts with it.
    #[inline(always)]
    pub fn uv_to_z_plain(&mut self, u: f64, v: f64) -> Option<f64> {
        let cell = self.plain.cell(u, v)?;
        Some(self.plain_on(&cell))
    }

    /// The elevation at `cell` of the common case (inside the window), keeping its terms.
    #[inline(always)]
    fn plain_on(&mut self, cell: &PlainCell) -> f64 {
        if self.last.of(cell) {
            // SAFETY: as in `plain_elevation`.
            return unsafe { self.plain.elevation(&self.last, cell) };
        }
        self.plain.prefetch_path(cell);
        // SAFETY: as in `plain_elevation`.
        let terms = unsafe { self.plain.terms(cell) };
        // SAFETY: as in `plain_elevation`.
        let z = unsafe { self.plain.elevation(&terms, cell) };
        self.last = terms;
        z
    }

    /// A real-time call: [`ContactPoint::uv_to_z_plain`] for a road read in place whose
    /// point lies outside the windows: a window moves to the tile of the point's cell (a
    /// present tile, pinned now) and the common case answers. `None` for every other
    /// case, also where the tile must first be read from the file
    /// ([`ContactPoint::uv_to_z`] and [`ContactPoint::z_of_found`] do that). Nothing in
    /// it can panic or take a lock.
    #[inline(never)]
    pub fn uv_to_z_placed(&mut self, u: f64, v: f64) -> Option<f64> {
        let cell = self.plain.road_cell(u, v)?;
        let (iu, iv) = cell.indices();
        // A window that left out the end of its tile: the wheel comes near the next.
        if let Some(c) = self.plain.widen_window(cell, u, v) {
            self.ask_for_next_tile(iu, iv);
            return Some(self.plain_on(&c));
        }
        self.enter_window(iu, iv)?;
        if near_tile_end(iu) {
            self.ask_for_next_tile(iu, iv);
        }
        let cell = self.plain.in_first_window(cell, u, v)?;
        Some(self.plain_on(&cell))
    }

    /// Makes the tile of the cell (`iu`, `iv`) a window: a present tile pinned now, the
    /// first window (the one a lookup tests first: a wheel's next points lie on the tile
    /// it entered last), the others moved one on and the one entered longest ago
    /// unpinned; `None` where the tile, or the cell's half of it, is not present.
    fn enter_window(&mut self, iu: usize, iv: usize) -> Option<()> {
        let tiles = self.road.grid.tiles()?;
        let (pin, values, halves) = tiles.pin(iu, iv)?;
        let w = &mut self.windows;
        // The pool is kept from the first tile entered on (a new road makes new windows,
        // so another pool here would be a contact point's mistake: its pins go back first).
        if !w.tiles.as_ref().is_some_and(|t| Arc::ptr_eq(t, tiles)) {
            w.release();
            self.plain.clear_windows();
            w.tiles = Some(tiles.clone());
        }
        if let Some(gone) = self.plain.enter_window((iu, iv), pin, values, halves, &mut w.pins) {
            tiles.unpin(gone);
        }
        Some(())
    }

    /// Asks the processor for the values a wheel at the cell (`iu`, `iv`) reads first in
    /// the next tile along ([`Tiles::ask_for_next_along`]).
    fn ask_for_next_tile(&self, iu: usize, iv: usize) {
        if let Some(tiles) = self.road.grid.tiles() {
            tiles.ask_for_next_along(iu, iv);
        }
    }

    /// [`ContactPoint::uv_to_z_placed`], reading the cell's tile from the file where it
    /// is not present; `None` where it does not apply or the file cannot be read.
    fn uv_to_z_placed_read(&mut self, u: f64, v: f64) -> Option<f64> {
        if let Some(z) = self.uv_to_z_placed(u, v) {
            return Some(z);
        }
        let cell = self.plain.road_cell(u, v)?;
        // SAFETY: `plain` was made from `road`, which the contact point holds, and `cell`
        // from `plain`.
        let terms = unsafe { self.plain.tile_terms(&cell) }?;
        if let Some(z) = self.uv_to_z_placed(u, v) {
            return Some(z);
        }
        // (The pool had no slot to pin: the values read are answered from.)
        // SAFETY: as above.
        Some(unsafe { self.plain.elevation(&terms, &cell) })
    }

    /// A real-time call: (u, v) of (x, y) when the lean search applies (a recent query
    /// lies within reach and the walk stays between the line's ends), with the history
    /// updated as [`ContactPoint::xy_to_uv`] updates it; `None`, with nothing changed,
    /// otherwise (then [`ContactPoint::xy_to_uv_general`] answers). Never panics; the C
    /// library's x/y calls start with it.
    #[inline(always)]
    pub fn xy_to_uv_lean(&mut self, x: f64, y: f64) -> Option<(f64, f64)> {
        if x.is_nan() || y.is_nan() {
            return None;
        }
        let road = &*self.road;
        search::xy_to_uv_lean(&road.line, self.eval.closed_search, &mut self.history, x, y)
    }

    /// Heading and curvature at (u, v).
    #[inline(always)]
    pub fn uv_to_pk(&self, u: f64, v: f64) -> Result<(f64, f64)> {
        finite(u, v)?;
        Ok(eval::uv_to_pk(&self.road, &self.eval, u, v))
    }

    /// (u, v) of the point (x, y).
    #[inline]
    pub fn xy_to_uv(&mut self, x: f64, y: f64) -> Result<(f64, f64)> {
        match self.xy_to_uv_lean(x, y) {
            Some(found) => Ok(found),
            None => self.xy_to_uv_general(x, y),
        }
    }

    /// [`ContactPoint::xy_to_uv`] without trying the lean search first: for a caller
    /// whose [`ContactPoint::xy_to_uv_lean`] just declined.
    pub fn xy_to_uv_general(&mut self, x: f64, y: f64) -> Result<(f64, f64)> {
        finite(x, y)?;
        let road = &*self.road;
        Ok(search::xy_to_uv(&road.line, &road.index, self.eval.closed_search, &mut self.history, x, y))
    }

    /// Elevation and the upward unit normal (x, y, z components) of the evaluated
    /// surface at (u, v): the analytic gradient of the interpolation (see the
    /// module notes of `normal.rs` for cell edges and borders).
    pub fn uv_to_normal(&self, u: f64, v: f64) -> Result<(f64, [f64; 3])> {
        finite(u, v)?;
        match crate::query::normal::uv_normal(&self.road, &self.eval, u, v) {
            Some((z, normal)) => Ok((self.read(Ok(z))?, normal)),
            None => Err(Error::OutOfRange(std::borrow::Cow::Borrowed(
                "evaluation refused: outside the road with border mode none",
            ))),
        }
    }

    /// Elevation and the upward unit normal at the point (x, y): those at its (u, v).
    pub fn xy_to_normal(&mut self, x: f64, y: f64) -> Result<(f64, [f64; 3])> {
        let (u, v) = self.xy_to_uv(x, y)?;
        self.uv_to_normal(u, v)
    }

    /// Elevation at the point (x, y).
    #[inline]
    pub fn xy_to_z(&mut self, x: f64, y: f64) -> Result<f64> {
        let (u, v) = self.xy_to_uv(x, y)?;
        self.z_of_found(u, v)
    }

    /// The elevation [`ContactPoint::xy_to_z`] gives at the (u, v) its search found (no
    /// check of u and v: the search's answer is taken as it is), for a caller that
    /// searched with [`ContactPoint::xy_to_uv_lean`] or [`ContactPoint::xy_to_uv`] and
    /// needs the elevation there too.
    #[inline]
    pub fn z_of_found(&mut self, u: f64, v: f64) -> Result<f64> {
        match self.uv_to_z_plain(u, v) {
            Some(z) => Ok(z),
            None => self.z_of_found_other(u, v),
        }
    }

    /// [`ContactPoint::z_of_found`] where the common case of a grid in memory does not
    /// apply.
    #[inline(never)]
    fn z_of_found_other(&mut self, u: f64, v: f64) -> Result<f64> {
        match self.uv_to_z_placed_read(u, v) {
            Some(z) => Ok(z),
            None => self.read(elevation(eval::uv_to_z(&self.road, &self.eval, u, v))),
        }
    }

    /// Heading and curvature at the point (x, y).
    pub fn xy_to_pk(&mut self, x: f64, y: f64) -> Result<(f64, f64)> {
        let (u, v) = self.xy_to_uv(x, y)?;
        self.uv_to_pk(u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::RoadSpec;

    /// A straight road `length` long with slope, banking and an uneven surface.
    fn road(length: f64, slope: f64) -> Arc<Road> {
        let spec = RoadSpec::straight(length, 2.0, 0.5, 0.25)
            .with_slope(move |_| slope)
            .with_bank(|u| 0.01 * u)
            .with_elevation(|u, v| (1.7 * u).sin() + 0.3 * v);
        Arc::new(spec.build().unwrap())
    }

    /// How many points over `u` in 0..=length (and v across the road and beyond) the
    /// common case answers, each checked against the general path bit for bit, asked
    /// twice and after a point of the same cell (its kept terms) and of another.
    fn plain_answers(c: &mut ContactPoint, length: f64) -> usize {
        let mut answered = 0;
        for i in -10..=410 {
            for j in -12..=12 {
                let (u, v) = (length * f64::from(i) / 400.0, f64::from(j) / 10.0);
                let first = c.uv_to_z_plain(u, v);
                let same_cell = c.uv_to_z_plain(u + 1e-9, v - 1e-9);
                let again = c.uv_to_z_plain(u, v);
                assert_eq!(first, again, "at ({u}, {v})");
                if let Some(z) = first {
                    let general = c.uv_to_z_general(u, v).unwrap();
                    assert_eq!(z.to_bits(), general.to_bits(), "at ({u}, {v})");
                    if let Some(z) = same_cell {
                        let general = c.uv_to_z_general(u + 1e-9, v - 1e-9).unwrap();
                        assert_eq!(z.to_bits(), general.to_bits(), "near ({u}, {v})");
                    }
                    answered += 1;
                }
            }
        }
        answered
    }

    /// The common case reads a copy of the road's geometry and the options, and keeps
    /// the terms of its last cell: it must follow both when they change. It answers
    /// inside the grid but not on its last cross and long section (the general path
    /// does there).
    #[test]
    fn the_common_case_follows_the_road_and_the_options() {
        let mut c = ContactPoint::new(road(10.0, 0.1));
        // Inside: u over 400 of the 421 steps, v over 20 of the 25.
        assert_eq!(plain_answers(&mut c, 10.0), 400 * 20);
        assert_eq!(c.uv_to_z_plain(15.0, 0.0), None, "beyond the first road");
        c.set_road(road(20.0, -0.2));
        assert_eq!(plain_answers(&mut c, 20.0), 400 * 20);
        c.set_option_double(opt::SMOOTH_U_BEGIN, 2.0).unwrap();
        assert_eq!(plain_answers(&mut c, 20.0), 0, "a smoothing zone takes the general path");
        c.remove_option(opt::SMOOTH_U_BEGIN);
        assert_eq!(plain_answers(&mut c, 20.0), 400 * 20);
    }

    /// On a road read in place through the smallest pool (16 tiles of the road's 48), each
    /// contact point pins at most its windows' tiles, hands back the one it leaves, and
    /// hands back all when it changes road or goes: two wheels weaving along the road
    /// and back answer as the road in memory does, which needs the pool's slots refilled.
    #[test]
    fn contact_points_hand_their_tiles_back() {
        use crate::model::road::{LoadOptions, ReadInPlace};
        use crate::model::tiles::TILE_U;
        // 16 tiles along, 3 across.
        let steps = 16 * TILE_U as u32;
        let length = 0.05 * f64::from(steps);
        let spec = RoadSpec::straight(length, 4.0, 0.05, 0.1).with_elevation(|u, v| 0.01 * (1.3 * u).sin() + 0.005 * v);
        let path = std::env::temp_dir().join(format!("opencrg-pins-{}.crg", std::process::id()));
        crate::write(&spec.build().unwrap(), &path, crate::DataFormat::Krbi).unwrap();
        let load = |in_place| {
            let options = LoadOptions { in_place, tile_cache: Some(1), ..LoadOptions::default() };
            Arc::new(Road::load_with(&path, options).unwrap())
        };
        let (placed, memory) = (load(ReadInPlace::Always), load(ReadInPlace::Never));
        let tiles = placed.grid.tiles().unwrap().clone();
        let mut wheels: Vec<ContactPoint> = (0..2).map(|_| ContactPoint::new(placed.clone())).collect();
        let expected = ContactPoint::new(memory.clone());
        for lap in 0..2 {
            for step in 0..steps - 10 {
                for (k, wheel) in wheels.iter_mut().enumerate() {
                    // Forward, then back: windows entered from either side.
                    let u = 0.05 * f64::from(if lap == 0 { step } else { steps - 11 - step }) + 0.013;
                    // About four and a half weaves over the road, whatever its length.
                    let v = -1.7 + 1.6 * k as f64 + 0.3 * (28.6 * u / length + f64::from(lap)).sin();
                    let z = wheel.uv_to_z_plain(u, v).or_else(|| wheel.z_of_found(u, v).ok());
                    assert_eq!(z.map(f64::to_bits), expected.uv_to_z(u, v).ok().map(f64::to_bits), "({u}, {v})");
                }
                assert!(tiles.pinned() <= 2 * WINDOWS, "{} pins", tiles.pinned());
            }
        }
        let slots = tiles.capacity() / crate::model::tiles::TILE_BYTES;
        assert!(tiles.fills() > slots, "the slots were filled again ({} fills, {slots} slots)", tiles.fills());
        wheels[0].set_road(memory);
        assert!(tiles.pinned() <= WINDOWS);
        drop(wheels);
        assert_eq!(tiles.pinned(), 0);
        std::fs::remove_file(&path).ok();
    }

    /// One contact point for the four wheels of a car driving along a road read in place
    /// (a pool holding the whole road): each wheel's tile has a window of its own, which
    /// the wheel reaches the end of (where the window widens) while other wheels' windows
    /// were entered after it; every answer is the road in memory's, bit for bit.
    #[test]
    fn a_contact_point_shared_by_four_wheels_answers_across_tile_ends() {
        use crate::model::road::{LoadOptions, ReadInPlace};
        use crate::model::tiles::TILE_U;
        let steps = 6 * TILE_U as u32;
        let length = 0.01 * f64::from(steps);
        let spec =
            RoadSpec::straight(length, 2.0, 0.01, 0.01).with_elevation(|u, v| 0.01 * (1.3 * u).sin() + 0.005 * v);
        let path = std::env::temp_dir().join(format!("opencrg-shared-{}.crg", std::process::id()));
        crate::write(&spec.build().unwrap(), &path, crate::DataFormat::Krbi).unwrap();
        let load =
            |in_place| Arc::new(Road::load_with(&path, LoadOptions { in_place, ..LoadOptions::default() }).unwrap());
        let (placed, memory) = (load(ReadInPlace::Always), load(ReadInPlace::Never));
        let mut car = ContactPoint::new(placed);
        let expected = ContactPoint::new(memory);
        // Rear axle from 0.1 m on, 3 cm a step, front axle 1.3 m ahead, weaving 4 cm.
        for step in 0..(length / 0.03) as u32 - 50 {
            let rear = 0.1 + 0.03 * f64::from(step);
            for (u, side) in [(rear + 1.3, 1.0), (rear + 1.3, -1.0), (rear, 1.0), (rear, -1.0)] {
                let v = side * 0.7 + 0.04 * (u / 1.7).sin();
                let z = car.uv_to_z_plain(u, v).or_else(|| car.z_of_found(u, v).ok());
                assert_eq!(z.map(f64::to_bits), expected.uv_to_z(u, v).ok().map(f64::to_bits), "({u}, {v})");
            }
        }
        std::fs::remove_file(&path).ok();
    }
}
