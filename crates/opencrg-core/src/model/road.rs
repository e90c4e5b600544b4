//! The road: reference line and elevation grid, built from a file's header and data.

use crate::base::compat::Compat;
use crate::base::settings::Settings;
use crate::model::georef::GlobalOrigin;
use crate::model::grid::{Grid, PrefetchHint};
use crate::model::header::{DataFormat, Header};
use crate::model::refline::{LineFinding, RefLine};
use crate::model::report::{Event, Statistics};
use crate::model::sample_index::SampleIndex;
use crate::model::tile_bounds::TileBounds;

/// A loaded road, ready for evaluation.
///
/// `Road` is immutable during evaluation and can be shared between threads (for
/// example in an `Arc`); each thread evaluates through its own
/// [`ContactPoint`](crate::ContactPoint).
#[derive(Debug, Clone)]
pub struct Road {
    pub(crate) header: Header,
    pub(crate) line: RefLine,
    pub(crate) grid: Grid,
    pub(crate) options: Settings,
    pub(crate) modifiers: Settings,
    pub(crate) index: SampleIndex,
    /// Where the local frame sits in the projected frame (kept by modifiers that move
    /// the road, so that its surface stays where it is on the earth).
    pub(crate) origin: GlobalOrigin,
    /// Reciprocals of the increments, for the cache prefetch of elevation lookups.
    pub(crate) prefetch_hint: PrefetchHint,
    /// Where the cells of each tile lie, for a grid read in place.
    pub(crate) tile_bounds: TileBounds,
    /// The reference behaviour the road follows.
    pub(crate) compat: Compat,
    /// Whether each preparation reports the road's statistics (a scan of the grid).
    pub(crate) report_statistics: bool,
    /// Events not yet taken by [`Road::take_events`].
    pub(crate) events: Vec<Event>,
}

/// How a road is loaded.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LoadOptions {
    /// The reference behaviour to follow.
    pub compat: Compat,
    /// Whether every preparation of the road (after loading, after modifiers that change
    /// its data) reports its statistics as an [`Event::Prepared`](crate::report::Event):
    /// a scan of the whole grid, so off unless someone reads them (a road read in place
    /// reports them without the scan: its lowest and highest elevation are NaN).
    pub report_statistics: bool,
    /// Whether a binary road's grid is read in place from its file (see
    /// [`Grid::is_in_place`](crate::grid::Grid::is_in_place)) or into memory.
    pub in_place: ReadInPlace,
    /// The most memory a road read in place keeps its decoded tiles in, in bytes; `None`:
    /// as the environment variable `OPENCRG_IN_PLACE_CACHE` says (a size such as `256M`),
    /// else [`DEFAULT_TILE_CACHE`].
    pub tile_cache: Option<u64>,
}

/// Binary roads of this many bytes and more are read in place unless told otherwise.
pub const DEFAULT_IN_PLACE_FROM: u64 = 1 << 30;

/// The memory a road read in place keeps its decoded tiles in unless told otherwise.
pub const DEFAULT_TILE_CACHE: u64 = 64 << 20;

/// When a binary road (KRBI, KDBI) is read in place: its header and reference line are
/// read on opening, its grid values where an evaluation reaches them, through the
/// system's file cache (which every process reading the file shares) into a cache of
/// decoded tiles of bounded size. Text roads are always read into memory.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum ReadInPlace {
    /// As the environment variable `OPENCRG_IN_PLACE` says (`never`, `always`, or a size
    /// such as `256M` from which on), else from [`DEFAULT_IN_PLACE_FROM`] on.
    #[default]
    Auto,
    /// Never: the grid is read into memory.
    Never,
    /// Every binary road.
    Always,
    /// Binary roads of this many bytes and more.
    From(u64),
}

impl ReadInPlace {
    /// The policy a text says: `never`, `always`, `auto`, or a size (`256M`, `2GiB`).
    pub fn parse(text: &str) -> std::result::Result<ReadInPlace, String> {
        match text.trim().to_ascii_lowercase().as_str() {
            "never" => Ok(ReadInPlace::Never),
            "always" => Ok(ReadInPlace::Always),
            "auto" => Ok(ReadInPlace::Auto),
            _ => crate::base::budget::parse_bytes(text)
                .map(ReadInPlace::From)
                .map_err(|_| format!("'{text}': expected never, always, auto or a size such as 256M")),
        }
    }

    /// Whether a binary file of `bytes` is read in place; `Auto` reads `OPENCRG_IN_PLACE`.
    pub(crate) fn applies(self, bytes: u64) -> crate::base::error::Result<bool> {
        let policy = match self {
            ReadInPlace::Auto => match std::env::var("OPENCRG_IN_PLACE") {
                Ok(text) if !text.trim().is_empty() => ReadInPlace::parse(&text)
                    .map_err(|e| crate::base::error::Error::out_of_range(format!("OPENCRG_IN_PLACE={e}")))?,
                _ => ReadInPlace::From(DEFAULT_IN_PLACE_FROM),
            },
            other => other,
        };
        Ok(match policy {
            ReadInPlace::Never => false,
            ReadInPlace::Always => true,
            ReadInPlace::From(limit) => bytes >= limit,
            ReadInPlace::Auto => bytes >= DEFAULT_IN_PLACE_FROM,
        })
    }
}

impl LoadOptions {
    /// The tile cache's size in bytes: the option, else `OPENCRG_IN_PLACE_CACHE`, else the default.
    pub(crate) fn tile_cache_bytes(&self) -> crate::base::error::Result<u64> {
        if let Some(bytes) = self.tile_cache {
            return Ok(bytes);
        }
        match std::env::var("OPENCRG_IN_PLACE_CACHE") {
            Ok(text) if !text.trim().is_empty() => crate::base::budget::parse_bytes(&text)
                .map_err(|e| crate::base::error::Error::out_of_range(format!("OPENCRG_IN_PLACE_CACHE={e}"))),
            _ => Ok(DEFAULT_TILE_CACHE),
        }
    }
}

impl From<Compat> for LoadOptions {
    fn from(compat: Compat) -> Self {
        LoadOptions { compat, ..LoadOptions::default() }
    }
}

/// Largest road accepted, in grid cells (guards against headers declaring absurd sizes):
/// 2^34 (64 GiB of heights) where addresses have 64 bits, 2^29 (2 GiB, half of what a
/// 32-bit address space holds, as WebAssembly's) where they have 32.
pub const MAX_CELLS: usize = if usize::BITS >= 64 { 1 << (usize::BITS / 2 + 2) } else { 1 << 29 };

impl Road {
    /// Computes everything derived from the channels: reference line x/y and z,
    /// closed-track data, and the search index. Runs after loading and after
    /// modifiers that change the data.
    pub(crate) fn prepare(&mut self) {
        if self.line.phi.is_some() {
            self.note(Event::LineFromHeading);
        }
        let mut findings = Vec::new();
        self.line.integrate_xy(self.compat, &mut findings);
        if self.line.defined.xy_channels {
            findings.push(LineFinding::XyChannelsNotUsed);
        }
        self.events.extend(findings.drain(..).map(Event::Line));
        if self.line.integrate_z(&mut findings) {
            self.note(Event::LineZFromSlope);
        }
        self.events.extend(findings.into_iter().map(Event::Line));
        self.grid.fold_mean();
        if self.report_statistics {
            let statistics = self.statistics();
            self.note(Event::Prepared(Box::new(statistics)));
        }
        self.line.update_utility();
        self.note(Event::ClosedTrack(self.line.closed));
        self.grid.build_v_table();
        self.line.update_caches();
        self.index = std::mem::take(&mut self.index).rebuilt(&self.line);
        self.prefetch_hint = PrefetchHint::new(self.line.u_inc, &self.grid);
        self.tile_bounds = TileBounds::new(&self.line, &self.grid);
    }

    /// The figures of the road as it is now.
    pub fn statistics(&self) -> Statistics {
        Statistics::of(&self.line, &self.grid)
    }

    /// The events since the last call, oldest first.
    pub fn take_events(&mut self) -> Vec<Event> {
        std::mem::take(&mut self.events)
    }

    pub(crate) fn note(&mut self, event: Event) {
        self.events.push(event);
    }

    /// Sets a modifier with a typed value (see [`Modifier`](crate::Modifier));
    /// it acts at the next [`Road::apply_modifiers`].
    pub fn set_modifier(&mut self, modifier: crate::base::setting_values::Modifier) -> crate::base::error::Result<()> {
        self.modifiers.set_modifier(modifier)
    }

    /// Starts loading the grid cells around (u, v) into the caches (see [`PrefetchHint`]).
    #[inline(always)]
    pub(crate) fn prefetch_cells(&self, u: f64, v: f64) {
        self.prefetch_hint.prefetch(&self.grid, self.line.u_first, u, v);
    }

    /// Whether later preparations (by modifiers) report the road's statistics; see
    /// [`LoadOptions::report_statistics`].
    pub fn set_report_statistics(&mut self, on: bool) {
        self.report_statistics = on;
    }

    /// The reference behaviour the road follows.
    pub fn compat(&self) -> Compat {
        self.compat
    }

    /// The header as read (comments, parameters, channels, options, modifiers).
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// The reference line.
    pub fn reference_line(&self) -> &RefLine {
        &self.line
    }

    /// The elevation grid.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// u range of the data: (first, last).
    pub fn u_range(&self) -> (f64, f64) {
        (self.line.u_first, self.line.u_last)
    }

    /// v range of the long sections: (rightmost, leftmost) position.
    pub fn v_range(&self) -> (f64, f64) {
        (self.grid.v[0], self.grid.v[self.grid.nv - 1])
    }

    /// u and v increments (v increment 0 when the long sections are uneven).
    pub fn increments(&self) -> (f64, f64) {
        (self.line.u_inc, self.grid.v_inc)
    }

    /// The u range over which the reference line can be closed, if it can.
    pub fn closed_track(&self) -> Option<(f64, f64)> {
        self.line.closed
    }

    /// The closed-track data as the classic API reports it: whether the line can be
    /// closed, and the u range found the last time it could be ((0, 0) if never), also
    /// when modifiers have since made it open.
    pub fn closed_track_report(&self) -> (bool, f64, f64) {
        let (a, b) = self.line.last_closed_range;
        (self.line.closed.is_some(), a, b)
    }

    /// Default options for new contact points (the file's options over the defaults).
    pub fn options(&self) -> &Settings {
        &self.options
    }

    /// Mutable access to the default options of new contact points.
    pub fn options_mut(&mut self) -> &mut Settings {
        &mut self.options
    }

    /// Modifiers to be applied by [`Road::apply_modifiers`].
    pub fn modifiers(&self) -> &Settings {
        &self.modifiers
    }

    /// Mutable access to the modifiers.
    pub fn modifiers_mut(&mut self) -> &mut Settings {
        &mut self.modifiers
    }

    /// Warnings collected while reading (ignored lines, refused values).
    pub fn warnings(&self) -> &[String] {
        &self.header.warnings
    }

    /// The global origin: how the local x/y/z frame sits in the projected east/north/height
    /// frame (`REFERENCE_LINE_OFFSET_*`, kept up to date by modifiers that move the road).
    pub fn global_origin(&self) -> GlobalOrigin {
        self.origin
    }

    /// Sets the global origin. This moves the global frame, not the road: local x/y/z
    /// answers stay as they are, east/north/height answers change.
    pub fn set_global_origin(&mut self, origin: GlobalOrigin) {
        self.origin = origin;
    }

    /// East, north and height of the local point (x, y, z).
    pub fn xyz_to_enh(&self, x: f64, y: f64, z: f64) -> [f64; 3] {
        self.origin.to_global((self.line.x_first, self.line.y_first), [x, y, z])
    }

    /// The local point (x, y, z) at east, north and height (e, n, h).
    pub fn enh_to_xyz(&self, e: f64, n: f64, h: f64) -> [f64; 3] {
        self.origin.to_local((self.line.x_first, self.line.y_first), [e, n, h])
    }

    /// The data format of the file that held the data.
    pub fn format(&self) -> DataFormat {
        self.header.format
    }
}
