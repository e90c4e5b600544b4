//! A road under construction: its reference line and grid as plain arrays, taken from
//! a road or made from scratch, then made into a new [`Road`] through the same
//! assembly a file's data takes. The road tools (`opencrg-tools`) each change a draft.

use crate::base::error::Result;
use crate::base::math;
use crate::model::georef::GlobalOrigin;
use crate::model::grid::{bank_v, Grid, GridPart, InPlace, Store, VLayout};
use crate::model::header::{Channel, EndsGiven, Header, RoadParams};
use crate::model::road::{LoadOptions, Road};
use crate::read::build::LineValues;
use std::f64::consts::TAU;

/// A road as arrays: one heading (and slope and banking, when it has them) per cross
/// section, the long sections' v, the elevations long section by long section
/// (`z[iv * nu + iu]`, relative to the reference line as in a file).
#[derive(Clone)]
pub struct Draft {
    /// The header the result keeps (comments, options, modifiers, map data).
    pub header: Header,
    /// u of the first cross section.
    pub u_first: f64,
    /// Distance between cross sections.
    pub u_inc: f64,
    /// x/y of the reference line's first point.
    pub start: (f64, f64),
    /// Elevation of the reference line's first point.
    pub z_start: f64,
    /// Heading per cross section; each one turns the step that ends there.
    pub phi: Vec<f64>,
    /// Slope per cross section (the first value is never used), if the line climbs.
    pub slope: Option<Vec<f64>>,
    /// Banking per cross section, if the road is banked.
    pub bank: Option<Vec<f64>>,
    /// v of the long sections, increasing.
    pub v: Vec<f64>,
    /// Whether the long sections are evenly spaced and written by number.
    pub regular: bool,
    /// The v range banking acts within (`LONG_SECTION_V_RIGHT`, `_LEFT`): beyond it, v
    /// counts as its border (a file without them has banking act at v = 0 only).
    pub bank_v: (f64, f64),
    /// Elevations relative to the reference line, long section by long section.
    pub z: Vec<f32>,
    /// The global origin, as it holds for a line starting at `origin_start`.
    pub origin: GlobalOrigin,
    /// The first point the origin was given for.
    pub origin_start: (f64, f64),
    /// Whether the line's ends moved (the file's WGS 84 end positions no longer hold).
    pub moved: bool,
    /// The behaviour profile of the source.
    pub load: LoadOptions,
}

/// The heading channel that puts a reference line's cross sections at `points` (one
/// increment apart): each value the direction of the step that ends there, kept
/// continuous (no jumps of a full turn); the first the same as the second.
pub fn headings_through(points: &[(f64, f64)]) -> Vec<f64> {
    let mut phi = vec![0.0; points.len()];
    for j in 1..points.len() {
        let p = math::atan2(points[j].1 - points[j - 1].1, points[j].0 - points[j - 1].0);
        phi[j] = if j == 1 { p } else { p - ((p - phi[j - 1]) / TAU).round() * TAU };
    }
    phi[0] = phi.get(1).copied().unwrap_or(0.0);
    phi
}

/// The slope channel that gives the reference line the elevations `z` at cross sections
/// `inc` apart (the first value, never used, the same as the second).
pub fn slopes_for(z: &[f64], inc: f64) -> Vec<f64> {
    let mut s: Vec<f64> = (0..z.len()).map(|i| if i == 0 { 0.0 } else { (z[i] - z[i - 1]) / inc }).collect();
    s[0] = s.get(1).copied().unwrap_or(0.0);
    s
}

/// The `$ROAD_CRG` keywords that state where the ends of the line lie on the earth.
fn is_end_position(key: &str) -> bool {
    let k = key.to_ascii_uppercase();
    ["REFERENCE_LINE_START_", "REFERENCE_LINE_END_"]
        .iter()
        .any(|p| k.strip_prefix(p).is_some_and(|rest| matches!(rest, "LAT" | "LON" | "ALT")))
}

impl Draft {
    /// The road's data as arrays (the road is not changed).
    pub fn of(road: &Road) -> Draft {
        Draft { z: road.grid.copied_values(), ..Draft::line_of(road) }
    }

    /// The road's data as arrays but its grid (`z` empty), for operations that make a
    /// new grid from the road's.
    pub fn line_of(road: &Road) -> Draft {
        let l = &road.line;
        let g = &road.grid;
        let n = l.n;
        let blended_xy = l.defined.x_end && l.defined.y_end && l.phi.is_some();
        // A line blended between both ends is taken as the points it went through.
        let phi = if blended_xy {
            let points: Vec<(f64, f64)> = l.x.iter().copied().zip(l.y.iter().copied()).collect();
            let mut phi = headings_through(&points);
            phi[0] = l.phi_first;
            phi
        } else {
            (0..n).map(|i| l.heading_at(i)).collect()
        };
        let slope = match (&l.slope, &l.z) {
            (Some(s), _) if !l.defined.z_end => Some(s.clone()),
            (_, Some(z)) => Some(slopes_for(z, l.u_inc)),
            _ => None,
        };
        let bank = l.has_bank.then(|| (0..n).map(|i| l.bank.as_ref().map_or(l.bank_first, |b| b[i])).collect());
        Draft {
            header: road.header.clone(),
            u_first: l.u_first,
            u_inc: l.u_inc,
            start: (l.x[0], l.y[0]),
            z_start: l.z_at(0),
            phi,
            slope,
            bank,
            v: g.v.clone(),
            regular: g.layout == VLayout::Indexed,
            bank_v: (g.v_first, g.v_last),
            z: Vec::new(),
            origin: road.origin,
            origin_start: (l.x_first, l.y_first),
            moved: false,
            load: LoadOptions { compat: road.compat, ..LoadOptions::default() },
        }
    }

    /// Number of cross sections.
    pub fn nu(&self) -> usize {
        self.phi.len()
    }

    /// Number of long sections.
    pub fn nv(&self) -> usize {
        self.v.len()
    }

    /// u of the last cross section.
    pub fn u_last(&self) -> f64 {
        self.u_first + (self.nu() - 1) as f64 * self.u_inc
    }

    /// The reference line's x/y at every cross section (the integration a file's
    /// heading channel gets when the road is read).
    pub fn line_xy(&self) -> (Vec<f64>, Vec<f64>) {
        let n = self.nu();
        let (mut x, mut y) = (vec![self.start.0; n], vec![self.start.1; n]);
        for i in 1..n {
            x[i] = x[i - 1] + self.u_inc * math::cos(self.phi[i]);
            y[i] = y[i - 1] + self.u_inc * math::sin(self.phi[i]);
        }
        (x, y)
    }

    /// The reference line's elevation at every cross section.
    pub fn line_z(&self) -> Vec<f64> {
        let mut z = vec![self.z_start; self.nu()];
        if let Some(s) = &self.slope {
            for i in 1..z.len() {
                z[i] = z[i - 1] + s[i] * self.u_inc;
            }
        }
        z
    }

    /// The banking's share of the surface at cross section `i` and `v`.
    pub fn bank_term(&self, i: usize, v: f64) -> f64 {
        self.bank.as_ref().map_or(0.0, |b| b[i] * bank_v(v, self.bank_v))
    }

    /// Makes banking act over the long sections' own range (what the file written says),
    /// each node keeping its surface.
    fn bank_over_sections(&mut self) {
        let sections = (self.v[0], self.v[self.nv() - 1]);
        if let Some(bank) = self.bank.as_ref().filter(|_| self.bank_v != sections) {
            let nu = self.nu();
            for (iv, &v) in self.v.iter().enumerate() {
                let shift = bank_v(v, self.bank_v) - bank_v(v, sections);
                for (z, b) in self.z[iv * nu..(iv + 1) * nu].iter_mut().zip(bank) {
                    *z = (f64::from(*z) + b * shift) as f32;
                }
            }
        }
        self.bank_v = sections;
    }

    /// The banking at every cross section (0 without banking).
    pub fn bank_at(&self, i: usize) -> f64 {
        self.bank.as_ref().map_or(0.0, |b| b[i])
    }

    /// A road with this draft's reference line and a flat grid of two long sections at
    /// `right` and `left`: where the nodes of the road being made lie.
    pub fn frame(&self, right: f64, left: f64) -> Result<Road> {
        let left = if left > right { left } else { right + 1.0 };
        let frame = Draft {
            header: self.header.clone(),
            phi: self.phi.clone(),
            slope: self.slope.clone(),
            bank: self.bank.clone(),
            v: vec![right, left],
            regular: false,
            z: vec![0.0; 2 * self.nu()],
            ..*self
        };
        frame.into_road("")
    }

    /// The new road, with `what` added to its comments. Its start heading is that of its
    /// first step (each heading turns the step that ends at its cross section, so a cut's
    /// first one would be that of the step before the part); its headings lie within
    /// [-pi, pi] (a full turn less or more changes nothing but the number); its banking
    /// acts over the long sections' range.
    pub fn into_road(mut self, what: &str) -> Result<Road> {
        if !self.z.is_empty() {
            self.bank_over_sections();
        }
        let z = Store::Memory(std::mem::take(&mut self.z));
        self.finish(what, z)
    }

    /// [`Draft::into_road`] with `grid` as its elevations (the draft's `z` left empty):
    /// the road reads them where they are asked for, from the file they lie in. (Where
    /// the banking must be shifted onto the draft's long sections, they are read first.)
    pub fn into_road_over(mut self, what: &str, grid: GridPart) -> Result<Road> {
        let sections = (self.v[0], self.v[self.nv() - 1]);
        if self.bank.is_some() && self.bank_v != sections {
            let part = Grid { store: Store::InPlace(InPlace::new(grid.tiles)), ..self.part_frame() };
            self.z = part.copied_values();
            return self.into_road(what);
        }
        self.finish(what, Store::InPlace(InPlace::new(grid.tiles)))
    }

    /// A grid of this draft's size to read a part through (its values come with the part).
    fn part_frame(&self) -> Grid {
        let nv = self.nv();
        Grid {
            nu: self.nu(),
            nv,
            store: Store::Memory(Vec::new()),
            mean: 0.0,
            v: self.v.clone(),
            v_first: self.v[0],
            v_last: self.v[nv - 1],
            v_inc: 0.0,
            layout: VLayout::Explicit,
            v_table: Vec::new(),
            last_frac: nv.saturating_sub(1) as f64,
        }
    }

    /// The road of this draft with its elevations `z`.
    fn finish(mut self, what: &str, z: Store) -> Result<Road> {
        if self.phi.len() > 1 {
            self.phi[0] = self.phi[1];
        }
        for p in &mut self.phi {
            *p -= (*p / TAU).round() * TAU;
        }
        let nu = self.nu();
        let nv = self.nv();
        let u_last = self.u_last();
        let mut header = self.header;
        header.comments.push(what.to_string());
        header.references.clear();
        header.warnings.clear();
        let origin = self.origin.for_start(self.origin_start, self.start);
        let had_origin = header.road.offset.iter().any(Option::is_some) || origin != GlobalOrigin::default();
        let mut extra = std::mem::take(&mut header.road.extra);
        if self.moved {
            extra.retain(|(k, _)| !is_end_position(k));
        }
        let v_inc = if nv > 1 { (self.v[nv - 1] - self.v[0]) / (nv - 1) as f64 } else { 0.0 };
        header.road = RoadParams {
            start_u: Some(self.u_first),
            end_u: Some(u_last),
            increment: Some(self.u_inc),
            start_x: Some(self.start.0),
            start_y: Some(self.start.1),
            start_z: Some(self.z_start),
            start_phi: Some(self.phi[0]),
            end_phi: Some(self.phi[nu - 1]),
            v_right: Some(self.v[0]),
            v_left: Some(self.v[nv - 1]),
            v_increment: self.regular.then_some(v_inc),
            offset: if had_origin { [origin.x, origin.y, origin.z, origin.phi].map(Some) } else { [None; 4] },
            extra,
            top_file_gives: EndsGiven { z_start: true, ..EndsGiven::default() },
            ..RoadParams::default()
        };
        let mut channels = vec![Channel::RefPhi];
        channels.extend(self.slope.is_some().then_some(Channel::RefSlope));
        channels.extend(self.bank.is_some().then_some(Channel::RefBank));
        for (i, &v) in self.v.iter().enumerate() {
            channels.push(if self.regular { Channel::SectionIndex((i + 1) as f64) } else { Channel::SectionAt(v) });
        }
        header.channels = channels;
        header.top_file_numbers_sections = self.regular;
        let line = LineValues { phi: self.phi, slope: self.slope, bank: self.bank };
        Road::assemble(header, line, z, self.load)
    }
}
