//! Evaluation at a (u, v) position: x/y, elevation z, heading and curvature.
//!
//! These functions take the road and a set of options; [`ContactPoint`](crate::ContactPoint)
//! wraps them with its own options and search history.

use crate::base::compat::Compat;
use crate::base::settings::{opt, BorderMode, Settings};
use crate::model::grid::VLayout;
use crate::model::refline::RefLine;
use crate::model::road::Road;
use crate::query::interpolation::{bilinear, corner_terms, lerp_at, lerp_terms};

// Border modes as the options store them: raw integers, since an application may set
// any integer (values outside these act as none of them).
const NONE: i32 = BorderMode::None as i32;
const EX_ZERO: i32 = BorderMode::ExZero as i32;
const EX_KEEP: i32 = BorderMode::ExKeep as i32;
const REPEAT: i32 = BorderMode::Repeat as i32;
const REFLECT: i32 = BorderMode::Reflect as i32;

/// Tolerance within which a v just outside an uneven grid counts as on its border.
pub(crate) const V_BORDER_SNAP: f64 = 1e-8;

/// The options evaluation reads, taken out of a settings table once so that the
/// hot path reads plain fields.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct EvalOptions {
    border_u: i32,
    border_v: i32,
    offset_u: f64,
    offset_v: f64,
    smooth_begin: Option<f64>,
    smooth_end: Option<f64>,
    /// Neither smoothing zone is set.
    no_smoothing: bool,
    curv_lateral: bool,
    close_track: bool,
    /// The reference library's x/y search tests option id 1 (the u border mode) for
    /// the value 1 to choose its closed-track branch; kept for the same answers.
    pub(crate) closed_search: bool,
}

impl EvalOptions {
    /// Whether neither smoothing zone is set.
    pub(crate) fn no_smoothing(&self) -> bool {
        self.no_smoothing
    }
}

impl From<&Settings> for EvalOptions {
    fn from(o: &Settings) -> Self {
        let (smooth_begin, smooth_end) = (o.get_double(opt::SMOOTH_U_BEGIN), o.get_double(opt::SMOOTH_U_END));
        EvalOptions {
            border_u: o.get_int(opt::BORDER_MODE_U).unwrap_or(NONE),
            border_v: o.get_int(opt::BORDER_MODE_V).unwrap_or(EX_KEEP),
            offset_u: o.get_double(opt::BORDER_OFFSET_U).unwrap_or(0.0),
            offset_v: o.get_double(opt::BORDER_OFFSET_V).unwrap_or(0.0),
            smooth_begin,
            smooth_end,
            no_smoothing: smooth_begin.is_none() && smooth_end.is_none(),
            curv_lateral: o.has_int(opt::CURV_MODE, 0),
            close_track: o.has_int(opt::REFLINE_CONTINUE, 1),
            closed_search: o.has_int(opt::BORDER_MODE_U, 1),
        }
    }
}

/// Maps u into the closed-track range when the line can be closed and the option
/// `REFLINE_CONTINUATION` asks for it.
#[inline]
pub(crate) fn wrap_closed_u(line: &RefLine, options: &EvalOptions, u: f64) -> f64 {
    if let Some((min, max)) = line.closed {
        if (u < min || u > max) && options.close_track {
            let w = (u - min) % (max - min);
            return if w > 0.0 { w + min } else { w + max };
        }
    }
    u
}

/// x/y of the point at (u, v). Beyond the ends the line continues straight along
/// the end headings; inside, v is measured along normals blended between the
/// neighbouring segments.
pub(crate) fn uv_to_xy(road: &Road, options: &EvalOptions, u: f64, v: f64) -> (f64, f64) {
    let l = &road.line;
    let u = wrap_closed_u(l, options, u);
    let (i, frac) = l.interval(u);
    let t = &l.trig;
    if frac < 0.0 {
        let du = frac * l.u_inc;
        return (l.x_first + du * t.first_cos - v * t.first_sin, l.y_first + du * t.first_sin + v * t.first_cos);
    }
    if frac > 1.0 {
        let du = (frac - 1.0) * l.u_inc;
        return (l.x_last + du * t.last_cos - v * t.last_sin, l.y_last + du * t.last_sin + v * t.last_cos);
    }
    let [n1x, n1y, n2x, n2y] = l.normals[i];
    let a = (l.x[i] + v * n1x, l.y[i] + v * n1y);
    let b = (l.x[i + 1] + v * n2x, l.y[i + 1] + v * n2y);
    (a.0 + frac * (b.0 - a.0), a.1 + frac * (b.1 - a.1))
}

/// Where u lies after its border mode is applied.
pub(crate) struct UPlace {
    /// Interval index and fraction in the grid.
    pub index: usize,
    pub frac: f64,
    /// u, moved into the data by the repeat and reflect modes.
    pub u: f64,
    /// Whether u is inside the data (after moving).
    pub in_core: bool,
    /// The border mode that applied (`NONE` inside the data).
    pub mode: i32,
    /// Whether grid values and banking count (not with border mode zero).
    pub with_values: bool,
    /// Which end the smoothing base comes from: 0 none, 1 begin, 2 end.
    pub smooth_end: u8,
    /// The u border offset, when u was outside the data.
    pub offset: f64,
    /// d frac / d u: how the grid fraction moves with u (0 where a border mode holds
    /// it, negative where reflect mirrors it).
    pub dfrac: f64,
    /// d (moved u) / d u: -1 where reflect mirrors u, else 1.
    pub du: f64,
}

/// Resolves u against the border mode; `None` when the mode refuses.
#[inline]
fn resolve_u(l: &RefLine, options: &EvalOptions, mut u: f64) -> Option<UPlace> {
    let mut frac = (u - l.u_first) / l.u_inc;
    let mut mode = NONE;
    let mut in_core = true;
    let mut with_values = true;
    let mut smooth_end = 0u8;
    let mut offset = 0.0;
    let mut index_from_frac = true;
    let mut dfrac = 1.0 / l.u_inc;
    let mut du = 1.0;
    if u < l.u_first || u > l.u_last {
        in_core = false;
        mode = options.border_u;
        let size = l.u_last - l.u_first;
        let max_frac = size / l.u_inc;
        match mode {
            NONE => return None,
            EX_KEEP => {
                dfrac = 0.0;
                if frac < 0.0 {
                    frac = 0.0;
                    index_from_frac = false;
                    smooth_end = 1;
                } else {
                    smooth_end = 2;
                }
            }
            EX_ZERO => {
                with_values = false;
                smooth_end = if frac < 0.0 { 1 } else { 2 };
            }
            REPEAT | REFLECT => {
                if mode == REPEAT {
                    frac = repeat(frac, max_frac);
                } else {
                    du = reflect_slope(frac, (u - l.u_first) / size);
                    dfrac *= du;
                    frac = reflect(frac, (u - l.u_first) / size, max_frac);
                }
                in_core = true;
                u = l.u_first + frac * l.u_inc;
            }
            _ => {}
        }
        offset = options.offset_u;
    }
    let index = if index_from_frac { clamp_index_sloped(&mut frac, l.n, &mut dfrac) } else { 0 };
    Some(UPlace { index, frac, u, in_core, mode, with_values, smooth_end, offset, dfrac, du })
}

/// Maps a grid fraction into one period of the data (border mode repeat).
#[inline]
fn repeat(frac: f64, max_frac: f64) -> f64 {
    let f = frac % max_frac;
    if f < 0.0 {
        f + max_frac
    } else {
        f
    }
}

/// The C conversion `(int) x` as the reference library gets it on x86-64: truncation
/// toward zero, and `i32::MIN` for NaN and for values outside the `int` range. A road
/// of zero width (v borders both 0, as when only `LONG_SECTION_V_INCREMENT` is given)
/// sends infinities and NaN through it, and its answers depend on this value.
#[inline]
fn c_int(x: f64) -> i32 {
    if x > -2_147_483_649.0 && x < 2_147_483_648.0 {
        x as i32
    } else {
        i32::MIN
    }
}

/// Whether C's `abs(n) % 2` is 1 (`abs(INT_MIN)` stays `INT_MIN`, which is even).
#[inline]
fn c_abs_is_odd(n: i32) -> bool {
    n.wrapping_abs() % 2 != 0
}

/// Reflects a grid fraction into the data (border mode reflect); `periods` is how
/// many data lengths the coordinate lies from the start.
#[inline]
fn reflect(frac: f64, periods: f64, max_frac: f64) -> f64 {
    let rep = c_int(periods);
    let f = frac.abs() - f64::from(rep.wrapping_abs()) * max_frac;
    if c_abs_is_odd(rep) {
        max_frac - f
    } else {
        f
    }
}

/// How a reflected fraction moves with the original one: +1 or -1 (the sign of the
/// fraction, mirrored again in every odd period).
#[inline]
fn reflect_slope(frac: f64, periods: f64) -> f64 {
    let sign = if frac < 0.0 { -1.0 } else { 1.0 };
    if c_abs_is_odd(c_int(periods)) {
        -sign
    } else {
        sign
    }
}

/// [`clamp_index`], and a slope of 0 where the fraction was clamped (the grid holds
/// the surface there).
#[inline]
fn clamp_index_sloped(frac: &mut f64, n: usize, slope: &mut f64) -> usize {
    if !(0.0..=(n - 1) as f64).contains(frac) {
        *slope = 0.0;
    }
    clamp_index(frac, n)
}

/// Splits a non-negative grid fraction into an interval index (at most `n - 2`) and
/// the fraction within it.
#[inline]
fn clamp_index(frac: &mut f64, n: usize) -> usize {
    clamp_index_to(frac, n, n.saturating_sub(1) as i64 as f64)
}

/// [`clamp_index`] with its bound `last` (`n - 1` as a double) computed beforehand.
#[inline(always)]
fn clamp_index_to(frac: &mut f64, n: usize, last: f64) -> usize {
    if *frac < 0.0 {
        *frac = 0.0;
    }
    upper_clamped_index(frac, n, last)
}

/// [`clamp_index_to`] for a fraction that is not negative: the same index and fraction
/// without the lower clamp. NaN takes the clamping branch.
#[inline(always)]
fn upper_clamped_index(frac: &mut f64, n: usize, last: f64) -> usize {
    // Indices stay far below 2^63, so i64 conversions are exact.
    if *frac < last {
        // SAFETY: 0 <= frac < n - 1 here (the caller's promise and the test): finite and
        // within i64.
        let i = unsafe { frac.to_int_unchecked::<i64>() };
        *frac -= i as f64;
        i as usize
    } else {
        *frac = 1.0;
        n.saturating_sub(2)
    }
}

/// The surface at interval (iu, fu) x (iv, fv): grid value (when `with_values`),
/// reference line z, and banking times `v_bank`; the reference line terms take `fu`
/// clamped to the cell (`FU_IN_CELL`: the caller knows it lies there). Never panics:
/// `None` where an index would leave the data (which the callers' index arithmetic rules
/// out).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn surface<const FU_IN_CELL: bool>(
    road: &Road,
    iu: usize,
    fu: f64,
    iv: usize,
    fv: f64,
    v_bank: f64,
    with_values: bool,
    with_bank: bool,
) -> Option<f64> {
    let (l, g) = (&road.line, &road.grid);
    let mut z = 0.0;
    if with_values {
        // The four corners: (iu, iv), (iu + 1, iv), and the same on the next long section.
        let [c00, c10, c01, c11] = g.corners(iu, iv)?;
        z = bilinear(&corner_terms(c00, c10, c01, c11), fu, fv);
        z += g.mean;
    }
    let fu = if FU_IN_CELL { fu } else { fu.clamp(0.0, 1.0) };
    z += match &l.z {
        Some(rz) => lerp(rz, iu, fu)?,
        None => l.z_first,
    };
    if l.has_bank && with_bank {
        let bank = match &l.bank {
            Some(b) => lerp(b, iu, fu)?,
            None => l.bank_first,
        };
        z += bank * v_bank;
    }
    Some(z)
}

/// The value a fraction `f` of the way from `values[i]` to `values[i + 1]`.
#[inline(always)]
fn lerp(values: &[f64], i: usize, f: f64) -> Option<f64> {
    let &[a, b] = values.get(i..)?.first_chunk::<2>()?;
    Some(lerp_at(lerp_terms(a, b), f))
}

/// The v interval of an uneven grid holding `pos`, and the fraction within it.
#[inline(always)]
fn explicit_v(g: &crate::model::grid::Grid, pos: f64) -> (usize, f64) {
    let i = g.v_interval(pos);
    (i, ((pos - g.v[i]) / (g.v[i + 1] - g.v[i])).clamp(0.0, 1.0))
}

/// Whether (u, v) lies inside the data with no smoothing zone set: then no option
/// matters (and u inside the data is inside any closed-track range).
#[inline(always)]
fn plain_inside(road: &Road, options: &EvalOptions, u: f64, v: f64) -> bool {
    let (l, g) = (&road.line, &road.grid);
    options.no_smoothing && u >= l.u_first && u <= l.u_last && v >= g.v_first && v <= g.v_last
}

/// The u interval index and fraction of a u inside the data.
#[inline(always)]
fn u_cell(l: &RefLine, u: f64) -> (usize, f64) {
    let mut fu = (u - l.u_first) / l.u_inc;
    (clamp_index_to(&mut fu, l.n, l.last_frac), fu)
}

/// The v interval index and fraction of a v inside an evenly spaced grid.
#[inline(always)]
fn v_cell(g: &crate::model::grid::Grid, v: f64) -> (usize, f64) {
    let mut fv = (v - g.v_first) / g.v_inc;
    (clamp_index_to(&mut fv, g.nv, g.last_frac), fv)
}

/// Elevation at (u, v) with the given options; `None` when a border mode refuses.
#[inline(always)]
pub(crate) fn uv_to_z(road: &Road, options: &EvalOptions, u: f64, v: f64) -> Option<f64> {
    let g = &road.grid;
    if plain_inside(road, options, u, v) {
        let (iu, fu) = u_cell(&road.line, u);
        let (iv, fv) = match g.layout {
            VLayout::Indexed => v_cell(g, v),
            VLayout::Explicit => explicit_v(g, v),
        };
        return surface::<true>(road, iu, fu, iv, fv, v, true, true);
    }
    uv_to_z_borders(road, options, u, v)
}

/// Where v lies after its border mode is applied.
pub(crate) struct VPlace {
    /// Interval index and fraction in the grid.
    pub index: usize,
    pub frac: f64,
    /// d frac / d v (0 where a border mode holds the fraction).
    pub dfrac: f64,
    /// v for the banking, moved into the data where the mode moves it.
    pub v: f64,
    /// d v / d (original v).
    pub dv: f64,
    /// Whether v is inside the data (after moving).
    pub in_core: bool,
    /// The border mode that applied (`EX_KEEP` inside).
    pub mode: i32,
    /// Whether grid values count (not with border mode zero).
    pub with_values: bool,
    /// The v border offset, when v was outside the data.
    pub offset: f64,
}

/// Resolves v against the border mode; `None` when the mode refuses.
#[inline]
pub(crate) fn resolve_v(g: &crate::model::grid::Grid, options: &EvalOptions, v: f64) -> Option<VPlace> {
    let mut v = v;
    let mut dv = 1.0;
    let mut with_values = true;
    let mut offset = 0.0;
    let mut v_in_core = true;
    let mut v_mode = EX_KEEP;
    let (iv, fv, dfrac);
    match g.layout {
        VLayout::Indexed => {
            let mut frac = (v - g.v_first) / g.v_inc;
            let mut slope = 1.0 / g.v_inc;
            let mut index_from_frac = true;
            if v < g.v_first || v > g.v_last {
                v_in_core = false;
                v_mode = options.border_v;
                let size = g.v_last - g.v_first;
                let max_frac = size / g.v_inc;
                match v_mode {
                    NONE => return None,
                    EX_KEEP if frac < 0.0 => {
                        frac = 0.0;
                        index_from_frac = false;
                        slope = 0.0;
                    }
                    EX_ZERO => with_values = false,
                    REPEAT | REFLECT => {
                        if v_mode == REPEAT {
                            frac = repeat(frac, max_frac);
                        } else {
                            let turn = reflect_slope(frac, (v - g.v_first) / size);
                            slope *= turn;
                            dv = turn;
                            frac = reflect(frac, (v - g.v_first) / size, max_frac);
                        }
                        v_in_core = true;
                        v = g.v_first + frac * g.v_inc;
                    }
                    _ => {}
                }
                offset = options.offset_v;
            }
            iv = if index_from_frac { clamp_index_sloped(&mut frac, g.nv, &mut slope) } else { 0 };
            fv = frac;
            dfrac = slope;
        }
        VLayout::Explicit => {
            let mut pos = v;
            let mut dpos = 1.0;
            if pos < g.v_first || pos > g.v_last {
                v_in_core = false;
                if (pos - g.v_first).abs() < V_BORDER_SNAP {
                    pos = g.v_first;
                    dpos = 0.0;
                } else if (pos - g.v_last).abs() < V_BORDER_SNAP {
                    pos = g.v_last;
                    dpos = 0.0;
                } else {
                    v_mode = options.border_v;
                    match v_mode {
                        NONE => return None,
                        EX_ZERO => with_values = false,
                        _ => {}
                    }
                }
                let range = g.v_last - g.v_first;
                if v_mode == REPEAT {
                    if pos > g.v_last {
                        pos = g.v_first + (pos - g.v_last) % range;
                    } else if pos < g.v_first {
                        pos = g.v_last + (pos - g.v_first) % range;
                    }
                    v_in_core = true;
                    if (pos - g.v_first).abs() < V_BORDER_SNAP {
                        pos = g.v_first;
                    } else if (pos - g.v_last).abs() < V_BORDER_SNAP {
                        pos = g.v_last;
                    }
                } else if v_mode == REFLECT {
                    if pos > g.v_last {
                        let rem = (pos - g.v_last) % range;
                        let rep = c_int((pos - g.v_last) / range);
                        (pos, dpos) = if c_abs_is_odd(rep) { (g.v_first + rem, 1.0) } else { (g.v_last - rem, -1.0) };
                    } else if pos < g.v_first {
                        let rem = (pos - g.v_first) % range;
                        let rep = c_int((pos - g.v_first) / range);
                        (pos, dpos) = if c_abs_is_odd(rep) { (g.v_last + rem, 1.0) } else { (g.v_first - rem, -1.0) };
                    }
                    v_in_core = true;
                }
                offset = options.offset_v;
            }
            (iv, fv) = explicit_v(g, pos);
            let width = g.v[iv + 1] - g.v[iv];
            let inside = pos >= g.v[iv] && pos <= g.v[iv + 1];
            dfrac = if inside { dpos / width } else { 0.0 };
        }
    }
    Some(VPlace { index: iv, frac: fv, dfrac, v, dv, in_core: v_in_core, mode: v_mode, with_values, offset })
}

/// Elevation where a border mode or a smoothing zone applies (kept out of line so
/// the common case above stays small).
#[inline(never)]
fn uv_to_z_borders(road: &Road, options: &EvalOptions, u: f64, v: f64) -> Option<f64> {
    Some(place(road, options, u, v)?.z)
}

/// An evaluated point: the elevation and what it was made of, for the gradient.
pub(crate) struct Placed {
    /// The elevation (smoothing applied).
    pub z: f64,
    /// Where u fell (after its border mode).
    pub(crate) ua: UPlace,
    /// Where v fell (after its border mode).
    pub va: VPlace,
    /// The elevation before smoothing.
    pub unsmoothed: f64,
    /// Smoothing: the scale, its base, and d scale / d (moved u); `None` without.
    pub smooth: Option<(f64, f64, f64)>,
}

/// Evaluates (u, v) with every border mode and smoothing zone; `None` where a border
/// mode refuses.
pub(crate) fn place(road: &Road, options: &EvalOptions, u: f64, v: f64) -> Option<Placed> {
    let l = &road.line;
    let g = &road.grid;
    let u = wrap_closed_u(l, options, u);
    let ua = resolve_u(l, options, u)?;
    let (u, mut with_values, mut smooth_end, mut z_offset) = (ua.u, ua.with_values, ua.smooth_end, ua.offset);
    let with_bank = with_values;

    let va = resolve_v(g, options, v)?;
    let (iv, fv, v_in_core, v_mode) = (va.index, va.frac, va.in_core, va.mode);
    let v = va.v;
    with_values &= va.with_values;
    z_offset += va.offset;

    let iu = ua.index;
    let vb = if v < g.v_first {
        g.v_first
    } else if v > g.v_last {
        g.v_last
    } else {
        v
    };
    let mut z = surface::<false>(road, iu, ua.frac, iv, fv, vb, with_values, with_bank)?;

    let mut smooth = None;
    let (begin, end) = (options.smooth_begin, options.smooth_end);
    let mut smooth_base = 0.0;
    if begin.is_some() || end.is_some() {
        if ua.in_core || smooth_end != 0 {
            if let Some(zone) = begin {
                if u - l.u_first <= zone {
                    smooth = Some(if u < l.u_first { (0.0, 0.0) } else { ((u - l.u_first) / zone, 1.0 / zone) });
                    smooth_end = 1;
                }
            }
            if let Some(zone) = end {
                if l.u_last - u <= zone {
                    smooth = Some(if u > l.u_last { (0.0, 0.0) } else { ((l.u_last - u) / zone, -1.0 / zone) });
                    smooth_end = 2;
                }
            }
        }
        smooth_base = match (smooth_end, &l.z) {
            (1, Some(rz)) => rz[0],
            (1, None) => l.z_first,
            (2, Some(rz)) => rz[l.n - 1],
            (2, None) => l.z_last,
            _ => 0.0,
        };
    }

    if !ua.in_core {
        match ua.mode {
            EX_ZERO => z = z_offset,
            EX_KEEP => z += z_offset,
            _ => {}
        }
    } else if !v_in_core {
        match v_mode {
            EX_ZERO => z = z_offset,
            EX_KEEP => z += z_offset,
            _ => {}
        }
    }
    let unsmoothed = z;
    if let Some((scale, _)) = smooth {
        z = smooth_base + (z - smooth_base) * scale;
    }
    Some(Placed { z, ua, va, unsmoothed, smooth: smooth.map(|(s, ds)| (s, smooth_base, ds)) })
}

/// Heading and curvature at (u, v). The heading is that of the reference line
/// segment holding u (the releases' profile: the segment before it); the curvature comes from points 0.5 m apart (at least one
/// increment) and, in lateral curvature mode, is that of the parallel at v.
#[inline(always)]
pub(crate) fn uv_to_pk(road: &Road, options: &EvalOptions, u: f64, v: f64) -> (f64, f64) {
    let l = &road.line;
    if l.phi.is_none() && l.phi_first.to_bits() == l.phi_last.to_bits() {
        // A straight line (no heading channel) with one heading: the answer below
        // whatever u is, without the index arithmetic.
        return (l.phi_first, 0.0);
    }
    let u = wrap_closed_u(l, options, u);
    let (iu, _) = l.interval(u);
    let nu = l.curv_step;
    if nu > iu {
        return (l.phi_first, 0.0);
    }
    let Some(phi) = l.phi.as_deref().filter(|p| iu + nu < p.len()) else {
        return (l.phi_last, 0.0);
    };
    let mut curv = l.curvature[iu];
    if options.curv_lateral && curv.abs() > 1e-10 {
        let radius = 1.0 / curv - v;
        curv = if radius.abs() < 1e-6 { 1e6 } else { 1.0 / radius };
    }
    let heading = match road.compat {
        Compat::Upstream => phi[iu + 1],
        Compat::Release201 => phi[iu],
    };
    (heading, curv)
}
