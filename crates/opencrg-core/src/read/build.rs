//! Building a road from what the reader found: the long sections and channels of the
//! header, the records of the data section, the reference line from its channels.

use crate::base::error::{Error, Location, Result};
use crate::base::math;
use crate::model::grid::{Grid, GridValues, InPlace, Store, VLayout};
use crate::model::header::{Channel, Header, RoadParams};
use crate::model::in_place::Records;
use crate::model::refline::{self, Defined, RefLine, Trig};
use crate::model::road::{LoadOptions, Road, MAX_CELLS};
use crate::model::sample_index::SampleIndex;
use crate::model::tiles::Tiles;
use crate::read::reader::{self, DataSource, FileBytes};
use crate::read::records::{self, Truncated};
use std::path::Path;

impl Road {
    /// Reads a CRG file in any of the four formats, following file references.
    ///
    /// The road is prepared for evaluation; its modifiers (the file's, or the
    /// defaults) are not applied yet: call [`Road::apply_modifiers`] for that, as the
    /// classic API's `crgDataSetModifiersApply` does.
    pub fn load(path: impl AsRef<Path>) -> Result<Road> {
        Road::load_with(path, LoadOptions::default())
    }

    /// [`Road::load`] with options (a [`Compat`](crate::Compat) alone will do).
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

    /// [`Road::from_bytes`] with options (a [`Compat`](crate::Compat) alone will do).
    pub fn from_bytes_with(bytes: Vec<u8>, name: impl AsRef<Path>, options: impl Into<LoadOptions>) -> Result<Road> {
        Road::from_bytes_and_files(bytes, name.as_ref(), None, options.into())
    }

    /// [`Road::from_bytes_with`] whose file references are read from `files` (name and
    /// content) instead of the disk: a reference takes the file named as its path beside
    /// `name`, else as written, else the one of the same last path component. For roads
    /// where there is no file system (WebAssembly) or whose files are held in memory.
    pub fn from_bytes_with_files(
        bytes: Vec<u8>,
        name: impl AsRef<Path>,
        files: &[(String, Vec<u8>)],
        options: impl Into<LoadOptions>,
    ) -> Result<Road> {
        Road::from_bytes_and_files(bytes, name.as_ref(), Some(files), options.into())
    }

    fn from_bytes_and_files(
        bytes: Vec<u8>,
        name: &Path,
        files: Option<&[(String, Vec<u8>)]>,
        options: LoadOptions,
    ) -> Result<Road> {
        let (header, data) = reader::read_bytes(bytes, name, files)?;
        let data = data.ok_or_else(|| {
            Error::format(
                name,
                Location::File,
                "data section",
                "no data section ($$$$ line) in the file or the files it references",
            )
        })?;
        Road::build(header, data, options)
    }

    /// A road from a header and its data: the layout of the channels, the u axis, the
    /// records, the reference line, then what is derived from them.
    fn build(header: Header, data: DataSource, load: LoadOptions) -> Result<Road> {
        let path = data.path.clone();
        let err = |field: &str, msg: String| Error::format(&path, Location::File, field, msg);
        let (cols, sections) = channel_layout(&header, &err)?;
        let (u_first, u_inc) = u_axis(&header.road, &err)?;
        let in_place = match &data.bytes {
            FileBytes::Mapped(map) if !header.format.is_text() => load.in_place.applies(map.bytes().len() as u64)?,
            _ => false,
        };
        let (z, b, nu) = if in_place {
            read_in_place(&header, &data, &cols, &sections, u_first, u_inc, load.tile_cache_bytes()?)?
        } else {
            let (z, b, nu) = read_records(&header, &data, &cols, &sections, u_first, u_inc)?;
            (Store::Memory(z), b, nu)
        };
        let warnings = channel_warnings(&header, &path, &cols, &b, nu, u_first, u_inc);
        let mut header = header;
        header.warnings.extend(warnings);
        Road::finish(header, &path, Parts { cols, sections, z, b, nu, u_first, u_inc }, load)
    }

    /// A road from a header and the values its channels hold, as if read from a file
    /// with that header: `line` holds the reference line channels the header's `D:`
    /// lines name (heading, slope, banking; one value per cross section), `z` the
    /// elevations long section by long section. The way new roads are made from old ones.
    pub(crate) fn assemble(header: Header, line: LineValues, z: Store, load: LoadOptions) -> Result<Road> {
        let path = header.path.clone();
        let err = |field: &str, msg: String| Error::format(&path, Location::File, field, msg);
        let (cols, sections) = channel_layout(&header, &err)?;
        let (u_first, u_inc) = u_axis(&header.road, &err)?;
        let nv = sections.v.len();
        let len = z_len(&z, nv);
        let nu = len / nv;
        if nu < 2 || nu * nv != len || line.phi.len() != nu {
            return Err(err("data section", format!("{len} values do not make {nv} long sections")));
        }
        if nu.saturating_mul(nv) > MAX_CELLS {
            return Err(err("data section", format!("{nu} x {nv} cells exceed the supported size")));
        }
        let b = Builder {
            cols,
            x: Vec::new(),
            y: Vec::new(),
            u: Vec::new(),
            phi: line.phi,
            bank: line.bank.unwrap_or_default(),
            slope: line.slope.unwrap_or_default(),
            first_nan_heading: None,
        };
        Road::finish(header, &path, Parts { cols, sections, z, b, nu, u_first, u_inc }, load)
    }

    /// The grid and the reference line from the decoded parts, then what is derived.
    fn finish(header: Header, path: &Path, parts: Parts, load: LoadOptions) -> Result<Road> {
        let err = |field: &str, msg: String| Error::format(path, Location::File, field, msg);
        let Parts { cols, sections, z, b, nu, u_first, u_inc } = parts;
        let LongSections { v, v_first, v_last, v_inc, layout, .. } = sections;
        let nv = v.len();
        let grid = Grid {
            nu,
            nv,
            store: z,
            mean: 0.0,
            v,
            v_first,
            v_last,
            v_inc,
            layout,
            v_table: Vec::new(),
            last_frac: nv.saturating_sub(1) as i64 as f64,
        };
        let line = refline::RefLine::from_records(&header.road, &cols, b, nu, u_first, u_inc)
            .map_err(|m| err("reference line", m))?;
        let options = header.options.clone();
        let modifiers = header.modifiers.clone();
        let [x, y, z, phi] = header.road.offset.map(|v| v.unwrap_or(0.0));
        let mut road = Road {
            origin: crate::model::georef::GlobalOrigin { x, y, z, phi },
            header,
            line,
            grid,
            options,
            modifiers,
            index: SampleIndex::default(),
            prefetch_hint: Default::default(),
            tile_bounds: Default::default(),
            compat: load.compat,
            report_statistics: load.report_statistics,
            events: Vec::new(),
        };
        let imported: Vec<_> = road.header.references.clone();
        road.events.extend(imported.into_iter().map(crate::model::report::Event::FileImported));
        road.prepare();
        // What building the reference line found is part of reading the file: a warning
        // naming the file (after modifiers, an event only).
        let warnings = &mut road.header.warnings;
        road.events.retain(|event| match event {
            crate::model::report::Event::Line(finding) => {
                warnings.push(format!("{}: {finding}", path.display()));
                false
            }
            _ => true,
        });
        Ok(road)
    }
}

/// The reference line channels of a road being assembled, one value per cross section.
pub(crate) struct LineValues {
    /// Heading (the first value is the header's start heading).
    pub phi: Vec<f64>,
    /// Slope, when the header names a slope channel.
    pub slope: Option<Vec<f64>>,
    /// Banking, when the header names a banking channel.
    pub bank: Option<Vec<f64>>,
}

/// The number of values a grid holds (in memory, or records of `nv` read in place).
fn z_len(z: &Store, nv: usize) -> usize {
    match z {
        Store::Memory(z) => z.len(),
        Store::InPlace(p) if p.tiles.records().nv() == nv => p.tiles.records().nu() * nv,
        Store::InPlace(_) => 0,
    }
}

/// What a road is finished from: the channel layout, the grid and line values, the u axis.
struct Parts {
    cols: ColumnMap,
    sections: LongSections,
    z: Store,
    b: Builder,
    nu: usize,
    u_first: f64,
    u_inc: f64,
}

/// The long sections of a file: their columns and v positions, in v order.
struct LongSections {
    columns: Vec<usize>,
    v: Vec<f64>,
    v_first: f64,
    v_last: f64,
    v_inc: f64,
    layout: VLayout,
}

/// Where each channel is in a record, and the long sections' layout.
fn channel_layout(header: &Header, err: &impl Fn(&str, String) -> Error) -> Result<(ColumnMap, LongSections)> {
    let p = &header.road;
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
    let columns = sections.iter().map(|s| s.1).collect();
    Ok((cols, LongSections { columns, v, v_first, v_last, v_inc, layout }))
}

/// First u and u increment.
fn u_axis(p: &RoadParams, err: &impl Fn(&str, String) -> Error) -> Result<(f64, f64)> {
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
    Ok((u_first, u_inc))
}

/// Decodes the records: the grid (see [`GridValues`]), the reference line
/// channels, and the number of cross sections.
fn read_records(
    header: &Header,
    data: &DataSource,
    cols: &ColumnMap,
    sections: &LongSections,
    u_first: f64,
    u_inc: f64,
) -> Result<(Vec<f32>, Builder, usize)> {
    let path = &data.path;
    let err = |field: &str, msg: String| Error::format(path, Location::File, field, msg);
    let p = &header.road;
    let nv = sections.v.len();
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
            return Err(err(
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
    let mut z = GridValues::new(nv, estimate);
    let mut b = Builder::new(cols, estimate);
    // Decoded pages of a mapped file are handed back as decoding advances, so the
    // file and the grid are never both resident.
    const RELEASE_STEP: usize = 8 << 20;
    let mut released = 0;
    let decoded = records::decode(format, nch, bytes, max_records, |i, rec, end| {
        z.push(sections.columns.iter().map(|&c| rec[c] as f32));
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
                path,
                Location::Record { record, channel: Some(channels_read + 1) },
                "data section",
                format!("record ends after {channels_read} of {nch} channels"),
            ))
        }
    };
    data.bytes.check(path)?;
    if nu < 2 {
        return Err(err("data section", format!("{nu} cross section(s) found, at least 2 are needed")));
    }
    if let Some(bad) = b.first_nan_heading {
        return Err(Error::format(
            path,
            Location::Record { record: bad + 1, channel: cols.phi.map(|c| c + 1) },
            "reference line phi",
            "heading is NaN",
        ));
    }
    Ok((z.finish().0, b, nu))
}

/// Reads a binary road in place: its reference line channels from every record (and
/// nothing else of them), its grid as records of the file the tile pool reads from where
/// evaluation asks.
fn read_in_place(
    header: &Header,
    data: &DataSource,
    cols: &ColumnMap,
    sections: &LongSections,
    u_first: f64,
    u_inc: f64,
    tile_cache: u64,
) -> Result<(Store, Builder, usize)> {
    let path = &data.path;
    let err = |field: &str, msg: String| Error::format(path, Location::File, field, msg);
    let FileBytes::Mapped(map) = &data.bytes else {
        return Err(err("data section", "a road read in place needs its file mapped".into()));
    };
    let nv = sections.v.len();
    let nch = header.channels.len();
    let width = header.format.field_width();
    let record_len = width * nch;
    let available = (map.bytes().len() - data.offset) / record_len.max(1);
    let declared = ((header.road.end_u.unwrap_or(u_first) - u_first) / u_inc + 0.5).floor() + 1.0;
    if declared > available as f64 {
        return Err(err(
            "data section",
            format!("holds {available} records of {record_len} bytes, the header declares {declared}"),
        ));
    }
    let nu = declared as usize;
    if nu.saturating_mul(nv) > MAX_CELLS {
        return Err(err("data section", format!("{nu} x {nv} cells exceed the supported size")));
    }
    if nu < 2 {
        return Err(err("data section", format!("{nu} cross section(s) found, at least 2 are needed")));
    }
    let records = Records::new(map.clone(), path, data.offset, (record_len, width), &sections.columns, nu)
        .ok_or_else(|| err("data section", format!("{nu} records of {record_len} bytes do not fit the file")))?;
    let mut b = Builder::new(cols, nu);
    let wanted: Vec<usize> = [cols.x, cols.y, cols.u, cols.phi, cols.bank, cols.slope].into_iter().flatten().collect();
    if !wanted.is_empty() {
        // The reference line channels of every record: a pass over the file reading one
        // or two cache lines of each record, the pages handed back as it goes.
        const BATCH: usize = 1 << 14;
        let mut rec = vec![0.0f64; nch];
        for start in (0..nu).step_by(BATCH) {
            let end = (start + BATCH).min(nu);
            for i in start..end {
                crate::base::memory::prefetch(records.record((i + 16).min(nu - 1)));
                for &c in &wanted {
                    rec[c] = records.channel(i, c);
                }
                b.push(i, &rec)?;
            }
            records.release(start, end);
        }
    }
    records.check().map_err(|f| Error::reading(path, f.into_io()))?;
    if let Some(bad) = b.first_nan_heading {
        return Err(Error::format(
            path,
            Location::Record { record: bad + 1, channel: cols.phi.map(|c| c + 1) },
            "reference line phi",
            "heading is NaN",
        ));
    }
    let cache = usize::try_from(tile_cache).unwrap_or(usize::MAX);
    let store = Store::InPlace(InPlace::new(Tiles::new(std::sync::Arc::new(records), Vec::new(), cache)));
    Ok((store, b, nu))
}

/// Warnings about the records that do not stop the load: text data ending before the
/// declared end, NaN in the slope or banking channel. NaN there loads, as with the
/// reference (PyOpenCRG writes NaN as the first value, which the integration never
/// reads); elsewhere it makes the elevations around it NaN.
fn channel_warnings(
    header: &Header,
    path: &Path,
    cols: &ColumnMap,
    b: &Builder,
    nu: usize,
    u_first: f64,
    u_inc: f64,
) -> Vec<String> {
    let mut warnings = Vec::new();
    if let (true, Some(end)) = (header.format.is_text(), header.road.end_u) {
        let declared = ((end - u_first) / u_inc + 0.5).floor() + 1.0;
        if (nu as f64) < declared {
            warnings.push(format!(
                "{}: data section: {nu} records where REFERENCE_LINE_END_U = {end} declares {declared}; \
                 the road ends at u = {}",
                path.display(),
                u_first + (nu - 1) as f64 * u_inc
            ));
        }
    }
    for (values, col, name) in [(&b.slope, cols.slope, "slope"), (&b.bank, cols.bank, "banking")] {
        if let Some(i) = values.iter().skip(1).position(|v| v.is_nan()) {
            warnings.push(format!(
                "{}: record {}, channel {}: reference line {name} is NaN; elevations there will be NaN",
                path.display(),
                i + 2,
                col.map_or(0, |c| c + 1)
            ));
        }
    }
    warnings
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

fn spacing(values: impl Iterator<Item = f64>) -> (f64, f64, f64) {
    let (mut min, mut max, mut sum) = (f64::INFINITY, f64::NEG_INFINITY, 0.0);
    for d in values {
        min = min.min(d);
        max = max.max(d);
        sum += d;
    }
    (min, max, sum)
}

impl RefLine {
    pub(crate) fn from_records(
        p: &RoadParams,
        cols: &ColumnMap,
        b: Builder,
        n: usize,
        mut u_first: f64,
        mut u_inc: f64,
    ) -> Result<RefLine, String> {
        let u_last;
        if cols.x.is_some() {
            let (min, max, total) =
                spacing(b.x.windows(2).zip(b.y.windows(2)).map(|(x, y)| math::hypot(x[1] - x[0], y[1] - y[0])));
            if !(min >= 1e-6) {
                return Err("reference line x/y points are closer than 1e-6 m".into());
            }
            if (max - min) / min > 3e-2 {
                return Err("reference line x/y points are not evenly spaced".into());
            }
            u_inc = total / (n - 1) as f64;
            u_last = total;
        } else if cols.u.is_some() {
            let (min, max, _) = spacing(b.u.windows(2).map(|w| w[1] - w[0]));
            if !(min >= 1e-6) {
                return Err("reference line u values do not increase".into());
            }
            if (max - min) / min > 3e-2 {
                return Err("reference line u values are not evenly spaced".into());
            }
            u_first = b.u[0];
            u_last = b.u[n - 1];
            u_inc = (u_last - u_first) / (n - 1) as f64;
        } else {
            u_last = u_first + u_inc * (n - 1) as f64;
        }
        let phi_first = p.start_phi.unwrap_or(0.0);
        let phi = cols.phi.map(|_| {
            let mut phi = b.phi;
            phi[0] = phi_first;
            phi
        });
        let slope_first = p.start_slope.unwrap_or(0.0);
        let bank_first = p.start_bank.unwrap_or(0.0);
        let bank_last = p.end_bank.unwrap_or(0.0);
        let has_bank = cols.bank.is_some() || bank_first != 0.0 || bank_last != 0.0;
        let (x, y) = if cols.x.is_some() { (b.x, b.y) } else { (vec![0.0; n], vec![0.0; n]) };
        Ok(RefLine {
            u_first,
            u_last,
            u_inc,
            n,
            x,
            y,
            x_first: p.start_x.unwrap_or(0.0),
            y_first: p.start_y.unwrap_or(0.0),
            x_last: p.end_x.unwrap_or(0.0),
            y_last: p.end_y.unwrap_or(0.0),
            phi,
            phi_first,
            phi_last: p.end_phi.unwrap_or(0.0),
            slope: cols.slope.map(|_| b.slope),
            slope_first,
            slope_last: p.end_slope.unwrap_or(0.0),
            bank: cols.bank.map(|_| b.bank),
            bank_first,
            bank_last,
            has_bank,
            z: None,
            z_first: p.start_z.unwrap_or(0.0),
            z_last: p.end_z.unwrap_or(0.0),
            defined: Defined {
                x_end: p.top_file_gives.x_end,
                y_end: p.top_file_gives.y_end,
                z_start: p.top_file_gives.z_start,
                z_end: p.top_file_gives.z_end,
                xy_channels: cols.x.is_some(),
            },
            trig: Trig::default(),
            closed: None,
            last_closed_range: (0.0, 0.0),
            normals: Vec::new(),
            seg_len: Vec::new(),
            search: Vec::new(),
            last_frac: n.saturating_sub(1) as i64 as f64,
            curvature: Vec::new(),
            curv_step: 1,
        })
    }
}
