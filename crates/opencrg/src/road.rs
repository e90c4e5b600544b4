//! The road: reference line and elevation grid, built from a file's header and data.

use crate::compat::Compat;
use crate::error::{Error, Location, Result};
use crate::grid::{Grid, VLayout};
use crate::header::{Channel, DataFormat};
use crate::reader::{self, DataSource, Header};
use crate::records::{self, Truncated};
use crate::refline::{self, RefLine};
use crate::search::SampleIndex;
use crate::settings::Settings;
use std::path::Path;

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
    /// Reciprocals of the increments, for the cache prefetch of elevation lookups.
    pub(crate) prefetch: crate::eval::PrefetchHint,
    /// The reference behaviour the road follows.
    pub(crate) compat: Compat,
    /// Whether each preparation reports the road's statistics (a scan of the grid).
    report_statistics: bool,
    /// Events not yet taken by [`Road::take_events`].
    pub(crate) events: Vec<crate::report::Event>,
}

/// How a road is loaded.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LoadOptions {
    /// The reference behaviour to follow.
    pub compat: Compat,
    /// Whether every preparation of the road (after loading, after modifiers that change
    /// its data) reports its statistics as an [`Event::Prepared`](crate::report::Event):
    /// a scan of the whole grid, so off unless someone reads them.
    pub report_statistics: bool,
}

impl From<Compat> for LoadOptions {
    fn from(compat: Compat) -> Self {
        LoadOptions { compat, ..LoadOptions::default() }
    }
}

/// Largest road accepted, in grid cells (guards against headers declaring absurd sizes).
pub const MAX_CELLS: usize = 1 << 34;

impl Road {
    /// Reads a CRG file in any of the four formats, following file references.
    ///
    /// The road is prepared for evaluation; its modifiers (the file's, or the
    /// defaults) are not applied yet: call [`Road::apply_modifiers`] for that, as the
    /// classic API's `crgDataSetModifiersApply` does.
    pub fn load(path: impl AsRef<Path>) -> Result<Road> {
        Road::load_with(path, LoadOptions::default())
    }

    /// [`Road::load`] with options (a [`Compat`] alone will do).
    pub fn load_with(path: impl AsRef<Path>, options: impl Into<LoadOptions>) -> Result<Road> {
        let path = path.as_ref();
        let (header, data) = reader::read(path)?;
        let data = data.ok_or_else(|| {
            Error::format(
                path,
                Location::File,
                "data section",
                "no data section ($$$$ line) in the file or the files it references",
            )
        })?;
        Road::build(header, data, options.into())
    }

    /// Reads a CRG file held in memory. `name` stands for the file in messages;
    /// relative file references are looked up in the working folder and beside `name`.
    pub fn from_bytes(bytes: Vec<u8>, name: impl AsRef<Path>) -> Result<Road> {
        Road::from_bytes_with(bytes, name, LoadOptions::default())
    }

    /// [`Road::from_bytes`] with options (a [`Compat`] alone will do).
    pub fn from_bytes_with(bytes: Vec<u8>, name: impl AsRef<Path>, options: impl Into<LoadOptions>) -> Result<Road> {
        let name = name.as_ref();
        let (header, data) = reader::read_bytes(bytes, name)?;
        let data = data.ok_or_else(|| {
            Error::format(
                name,
                Location::File,
                "data section",
                "no data section ($$$$ line) in the file or the files it references",
            )
        })?;
        Road::build(header, data, options.into())
    }

    fn build(header: Header, data: DataSource, load: LoadOptions) -> Result<Road> {
        let path = data.path.clone();
        let err = |field: &str, msg: String| Error::format(&path, Location::File, field, msg);
        let p = &header.road;

        // --- long sections ---
        let mut sections: Vec<(f64, usize, bool)> = Vec::new();
        let mut cols = ColumnMap::default();
        for (col, ch) in header.channels.iter().enumerate() {
            match *ch {
                Channel::SectionAt(v) => sections.push((v, col, true)),
                Channel::SectionIndex(n) => sections.push((n, col, false)),
                Channel::RefX => cols.x = Some(col),
                Channel::RefY => cols.y = Some(col),
                Channel::RefU => cols.u = Some(col),
                Channel::RefPhi => cols.phi = Some(col),
                Channel::RefBank => cols.bank = Some(col),
                Channel::RefSlope => cols.slope = Some(col),
            }
        }
        if cols.x.is_some() != cols.y.is_some() {
            return Err(err("$KD_Definition", "reference line x and y channels must be defined together".into()));
        }
        if sections.len() < 2 {
            return Err(err(
                "$KD_Definition",
                format!("{} long section(s) defined, at least 2 are needed", sections.len()),
            ));
        }
        let explicit = sections[0].2;
        if sections.iter().any(|s| s.2 != explicit) {
            return Err(err("$KD_Definition", "long sections mix 'at v = X' and numbered definitions".into()));
        }
        sections.sort_by(|a, b| a.0.total_cmp(&b.0));
        let nv = sections.len();
        let mut v: Vec<f64> = sections.iter().map(|s| s.0).collect();
        let (v_first, v_last, v_inc, layout);
        if explicit {
            let gaps = v.windows(2).map(|w| w[1] - w[0]);
            let dv_min = gaps.clone().fold(f64::INFINITY, f64::min);
            let dv_max = gaps.fold(f64::NEG_INFINITY, f64::max);
            if dv_min < 1e-6 {
                return Err(err("$KD_Definition", "two long sections are at the same v (spacing below 1e-6 m)".into()));
            }
            let uniform = (dv_max - dv_min) / dv_min < 1e-3;
            v_inc = if uniform { (v[nv - 1] - v[0]) / (nv - 1) as f64 } else { p.v_increment.unwrap_or(0.01) };
            // The v borders are the header's values (0 when absent), as the reference
            // keeps them; only even spacing moves the right border to the first section.
            v_first = if uniform { v[0] } else { p.v_right.unwrap_or(0.0) };
            v_last = p.v_left.unwrap_or(0.0);
            layout = VLayout::Explicit;
        } else {
            if v.iter().enumerate().any(|(i, &n)| n != (i + 1) as f64) {
                return Err(err("$KD_Definition", format!("long sections must be numbered 1 to {nv}")));
            }
            v_inc = p.v_increment.unwrap_or(0.01);
            if !(v_inc > 0.0) {
                return Err(err("LONG_SECTION_V_INCREMENT", format!("increment {v_inc} must be positive")));
            }
            v_first = p.v_right.unwrap_or(0.0);
            for (i, x) in v.iter_mut().enumerate() {
                *x = v_first + i as f64 * v_inc;
            }
            v_last = p.v_left.unwrap_or(0.0);
            layout = if header.top_file_numbers_sections { VLayout::Indexed } else { VLayout::Explicit };
        }

        // --- u axis ---
        let u_first = p.start_u.unwrap_or(0.0);
        let u_inc = p.increment.unwrap_or(0.01);
        if !(u_inc > 0.0) {
            return Err(err("REFERENCE_LINE_INCREMENT", format!("increment {u_inc} must be positive")));
        }
        if let Some(end) = p.end_u {
            if end <= u_first {
                return Err(err("REFERENCE_LINE_END_U", format!("end u {end} is not after start u {u_first}")));
            }
        }

        // --- records ---
        let nch = header.channels.len();
        let bytes = &data.bytes[data.offset..];
        let format = header.format;
        let record_len = format.field_width() * nch;
        let max_records = if format.is_text() {
            usize::MAX
        } else {
            let declared = ((p.end_u.unwrap_or(u_first) - u_first) / u_inc + 0.5).floor() + 1.0;
            let available = bytes.len() / record_len.max(1);
            if declared > available as f64 {
                return Err(Error::format(
                    &path,
                    Location::File,
                    "data section",
                    format!("holds {available} records of {record_len} bytes, the header declares {declared}"),
                ));
            }
            declared as usize
        };
        let estimate = if format.is_text() { bytes.len() / (record_len + 1).max(1) } else { max_records };
        if estimate.saturating_mul(nv) > MAX_CELLS {
            return Err(err("data section", format!("{estimate} x {nv} cells exceed the supported size")));
        }
        let mut z: Vec<f32> = crate::memory::large_vec(estimate.saturating_mul(nv));
        let mut b = Builder::new(&cols, estimate);
        let section_cols: Vec<usize> = sections.iter().map(|s| s.1).collect();
        // Decoded pages of a mapped file are handed back as decoding advances, so the
        // file and the grid are never both resident.
        const RELEASE_STEP: usize = 8 << 20;
        let mut released = 0;
        let decoded = records::decode(format, nch, bytes, max_records, |i, rec, end| {
            z.extend(section_cols.iter().map(|&c| rec[c] as f32));
            if end - released >= RELEASE_STEP {
                data.bytes.release(data.offset + released, data.offset + end);
                released = end;
            }
            b.push(i, rec)
        })?;
        let nu = match decoded {
            Ok(n) => n,
            Err(Truncated { record, channels_read }) => {
                return Err(Error::format(
                    &path,
                    Location::Record { record, channel: Some(channels_read + 1) },
                    "data section",
                    format!("record ends after {channels_read} of {nch} channels"),
                ))
            }
        };
        if nu < 2 {
            return Err(err("data section", format!("{nu} cross section(s) found, at least 2 are needed")));
        }
        if let Some(bad) = b.first_nan_heading {
            return Err(Error::format(
                &path,
                Location::Record { record: bad + 1, channel: cols.phi.map(|c| c + 1) },
                "reference line phi",
                "heading is NaN",
            ));
        }
        // NaN in the slope or banking channel loads, as with the reference (PyOpenCRG writes
        // NaN as the first value, which the integration never reads); elsewhere it makes the
        // elevations around it NaN, which deserves a warning.
        let mut channel_warnings = Vec::new();
        if let (true, Some(end)) = (format.is_text(), p.end_u) {
            let declared = ((end - u_first) / u_inc + 0.5).floor() + 1.0;
            if (nu as f64) < declared {
                channel_warnings.push(format!(
                    "{}: data section: {nu} records where REFERENCE_LINE_END_U = {end} declares {declared}; \
                     the road ends at u = {}",
                    path.display(),
                    u_first + (nu - 1) as f64 * u_inc
                ));
            }
        }
        for (values, col, name) in [(&b.slope, cols.slope, "slope"), (&b.bank, cols.bank, "banking")] {
            if let Some(i) = values.iter().skip(1).position(|v| v.is_nan()) {
                channel_warnings.push(format!(
                    "{}: record {}, channel {}: reference line {name} is NaN; elevations there will be NaN",
                    path.display(),
                    i + 2,
                    col.map_or(0, |c| c + 1)
                ));
            }
        }
        let grid = Grid { nu, nv, z, mean: 0.0, v, v_first, v_last, v_inc, layout, v_table: Vec::new() };
        let line =
            refline::RefLine::from_records(p, &cols, b, nu, u_first, u_inc).map_err(|m| err("reference line", m))?;
        let mut header = header;
        header.warnings.extend(channel_warnings);
        let options = header.options.clone();
        let modifiers = header.modifiers.clone();
        let mut road = Road {
            header,
            line,
            grid,
            options,
            modifiers,
            index: SampleIndex::default(),
            prefetch: Default::default(),
            compat: load.compat,
            report_statistics: load.report_statistics,
            events: Vec::new(),
        };
        let imported: Vec<_> = road.header.references.clone();
        road.events.extend(imported.into_iter().map(crate::report::Event::FileImported));
        road.prepare();
        Ok(road)
    }

    /// Computes everything derived from the channels: reference line x/y and z,
    /// closed-track data, and the search index. Runs after loading and after
    /// modifiers that change the data.
    pub(crate) fn prepare(&mut self) {
        use crate::report::Event;
        if self.line.phi.is_some() {
            self.note(Event::LineFromHeading);
        }
        self.line.integrate_xy(self.compat);
        if self.line.integrate_z() {
            self.note(Event::LineZFromSlope);
        }
        self.grid.fold_mean();
        if self.report_statistics {
            let statistics = self.statistics();
            self.note(Event::Prepared(Box::new(statistics)));
        }
        self.line.update_utility();
        self.note(Event::ClosedTrack(self.line.closed));
        self.grid.build_v_table();
        self.line.update_caches();
        self.index = SampleIndex::build(&self.line);
        self.prefetch = crate::eval::PrefetchHint::new(&self.line, &self.grid);
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

    /// The data format of the file that held the data.
    pub fn format(&self) -> DataFormat {
        self.header.format
    }
}

/// Columns of the reference line channels in a record.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct ColumnMap {
    pub x: Option<usize>,
    pub y: Option<usize>,
    pub u: Option<usize>,
    pub phi: Option<usize>,
    pub bank: Option<usize>,
    pub slope: Option<usize>,
}

/// Collects the reference line channels record by record.
pub(crate) struct Builder {
    cols: ColumnMap,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub u: Vec<f64>,
    pub phi: Vec<f64>,
    pub bank: Vec<f64>,
    pub slope: Vec<f64>,
    pub first_nan_heading: Option<usize>,
}

impl Builder {
    fn new(cols: &ColumnMap, capacity: usize) -> Self {
        let cap = |c: Option<usize>| Vec::with_capacity(if c.is_some() { capacity } else { 0 });
        Builder {
            cols: *cols,
            x: cap(cols.x),
            y: cap(cols.y),
            u: cap(cols.u),
            phi: cap(cols.phi),
            bank: cap(cols.bank),
            slope: cap(cols.slope),
            first_nan_heading: None,
        }
    }

    fn push(&mut self, i: usize, rec: &[f64]) -> Result<()> {
        let c = self.cols;
        let put = |col: Option<usize>, v: &mut Vec<f64>| {
            if let Some(col) = col {
                v.push(rec[col]);
            }
        };
        put(c.x, &mut self.x);
        put(c.y, &mut self.y);
        put(c.u, &mut self.u);
        put(c.bank, &mut self.bank);
        put(c.slope, &mut self.slope);
        if let Some(col) = c.phi {
            if i > 0 && rec[col].is_nan() && self.first_nan_heading.is_none() {
                self.first_nan_heading = Some(i);
            }
            self.phi.push(rec[col]);
        }
        Ok(())
    }
}
