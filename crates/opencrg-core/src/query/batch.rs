//! Batch evaluation: many points through one contact point in one call, with the same
//! answers as the single-point calls made in order (the x/y search history included).
//! The elevation batch finds the grid cells of the points a few blocks ahead and starts
//! loading them into the second-level cache, so the memory accesses of many points
//! overlap.

use crate::base::error::Result;
use crate::query::contact::ContactPoint;
use crate::query::plain::PlainCell;

/// How many points the elevation batch locates at a time. Blocks of 16 with 3 blocks of
/// lead were the best of the 4 to 32 points and 1 to 8 blocks measured on the 80 MB
/// benchmark road (Intel Xeon), and 3 the best of 2 to 5 blocks with the cells loaded into
/// the second-level cache (AMD EPYC): a longer burst of prefetches is partly wasted, a
/// shorter lead arrives late.
const BLOCK: usize = 16;

/// How many blocks ahead of the one it computes the elevation batch locates cells.
const LEAD: usize = 3;

/// The values of an answer, or NaN for each where the call failed; counts successes.
#[inline(always)]
fn settle<const K: usize>(answer: Result<[f64; K]>, ok: &mut usize) -> [f64; K] {
    match answer {
        Ok(values) => {
            *ok += 1;
            values
        }
        Err(_) => [f64::NAN; K],
    }
}

/// Writes one answer per point: the value, or NaN in every output where the call failed;
/// returns how many succeeded.
fn each<const K: usize>(n: usize, out: &mut [&mut [f64]; K], mut f: impl FnMut(usize) -> Result<[f64; K]>) -> usize {
    let mut ok = 0;
    for i in 0..n {
        for (slot, value) in out.iter_mut().zip(settle(f(i), &mut ok)) {
            slot[i] = value;
        }
    }
    ok
}

/// The number of points: the shortest of the slices.
fn count(inputs: [&[f64]; 2], outputs: &[&mut [f64]]) -> usize {
    outputs.iter().map(|o| o.len()).fold(inputs[0].len().min(inputs[1].len()), usize::min)
}

impl ContactPoint {
    /// [`ContactPoint::uv_to_z`] for every (`u[i]`, `v[i]`) into `z[i]` (NaN where it fails);
    /// returns how many succeeded. The shortest slice sets the number of points.
    pub fn uv_to_z_many(&self, u: &[f64], v: &[f64], z: &mut [f64]) -> usize {
        let n = count([u, v], &[&mut *z]);
        let (u, v, z) = (&u[..n], &v[..n], &mut z[..n]);
        // The cells of the points from `start` on, loading started; a point outside the
        // lean path's case gets `None` and takes the general path when its turn comes.
        // (A grid read in place is read from its tiles: no prefetch aims into it.)
        let in_place = self.road().grid().is_in_place();
        let locate = |start: usize, cells: &mut [Option<PlainCell>; BLOCK]| {
            for ((cell, &u), &v) in cells.iter_mut().zip(&u[start..]).zip(&v[start..]) {
                *cell = self.plain_cell(u, v);
                if let (Some(cell), false) = (cell, in_place) {
                    self.plain_prefetch_far(cell);
                }
            }
        };
        // Block b's cells live in ring[b % RING], located LEAD blocks before its turn.
        const RING: usize = LEAD + 1;
        let mut ring = [[None; BLOCK]; RING];
        for (b, cells) in ring.iter_mut().enumerate().take(LEAD) {
            locate((b * BLOCK).min(n), cells);
        }
        let mut ok = 0;
        for (b, start) in (0..n).step_by(BLOCK).enumerate() {
            locate((start + LEAD * BLOCK).min(n), &mut ring[(b + LEAD) % RING]);
            let end = (start + BLOCK).min(n);
            for ((out, cell), i) in z[start..end].iter_mut().zip(&ring[b % RING]).zip(start..) {
                let value = match cell {
                    Some(cell) => Ok(self.plain_elevation(cell)),
                    None => self.uv_to_z_other(u[i], v[i]),
                };
                [*out] = settle(value.map(|z| [z]), &mut ok);
            }
        }
        ok
    }

    /// [`ContactPoint::uv_to_xy`] for every point into `x[i]`, `y[i]`.
    pub fn uv_to_xy_many(&self, u: &[f64], v: &[f64], x: &mut [f64], y: &mut [f64]) -> usize {
        let n = count([u, v], &[&mut *x, &mut *y]);
        each(n, &mut [x, y], |i| self.uv_to_xy(u[i], v[i]).map(|(a, b)| [a, b]))
    }

    /// [`ContactPoint::uv_to_pk`] for every point into `phi[i]`, `curv[i]`.
    pub fn uv_to_pk_many(&self, u: &[f64], v: &[f64], phi: &mut [f64], curv: &mut [f64]) -> usize {
        let n = count([u, v], &[&mut *phi, &mut *curv]);
        each(n, &mut [phi, curv], |i| self.uv_to_pk(u[i], v[i]).map(|(a, b)| [a, b]))
    }

    /// [`ContactPoint::xy_to_uv`] for every point, in order (each answer updates the
    /// search history the next one starts from).
    pub fn xy_to_uv_many(&mut self, x: &[f64], y: &[f64], u: &mut [f64], v: &mut [f64]) -> usize {
        let n = count([x, y], &[&mut *u, &mut *v]);
        each(n, &mut [u, v], |i| self.xy_to_uv(x[i], y[i]).map(|(a, b)| [a, b]))
    }

    /// [`ContactPoint::xy_to_z`] for every point, in order. The elevation of a point is
    /// computed after the next point's search, which hides the wait for its grid cells.
    pub fn xy_to_z_many(&mut self, x: &[f64], y: &[f64], z: &mut [f64]) -> usize {
        let n = count([x, y], &[&mut *z]);
        let road = self.road().clone();
        let mut ok = 0;
        // The point found last, its elevation still to compute.
        let mut pending: Option<(usize, f64, f64)> = None;
        let mut finish = |cp: &mut Self, (i, u, v): (usize, f64, f64), z: &mut [f64]| {
            [z[i]] = settle(cp.z_of_found(u, v).map(|z| [z]), &mut ok);
        };
        for i in 0..n {
            let found = self.xy_to_uv(x[i], y[i]);
            if let Ok((u, v)) = found {
                road.prefetch_cells(u, v);
            }
            if let Some(earlier) = pending.take() {
                finish(self, earlier, z);
            }
            match found {
                Ok((u, v)) => pending = Some((i, u, v)),
                Err(_) => z[i] = f64::NAN,
            }
        }
        if let Some(last) = pending {
            finish(self, last, z);
        }
        ok
    }

    /// [`ContactPoint::xy_to_pk`] for every point, in order.
    pub fn xy_to_pk_many(&mut self, x: &[f64], y: &[f64], phi: &mut [f64], curv: &mut [f64]) -> usize {
        let n = count([x, y], &[&mut *phi, &mut *curv]);
        each(n, &mut [phi, curv], |i| self.xy_to_pk(x[i], y[i]).map(|(a, b)| [a, b]))
    }
}

/// An evaluation call, by what it takes and gives: the one list the bindings serve their
/// evaluation methods from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Evaluation {
    /// Elevation at (u, v).
    UvToZ,
    /// Elevation at (x, y).
    XyToZ,
    /// (x, y) of (u, v).
    UvToXy,
    /// (u, v) of (x, y).
    XyToUv,
    /// Heading and curvature at (u, v).
    UvToPk,
    /// Heading and curvature at (x, y).
    XyToPk,
    /// Elevation and the upward unit normal at (u, v).
    UvToNormal,
    /// Elevation and the upward unit normal at (x, y).
    XyToNormal,
}

impl Evaluation {
    /// Every evaluation, in the order the bindings list them.
    pub const ALL: [Evaluation; 8] = [
        Evaluation::UvToZ,
        Evaluation::XyToZ,
        Evaluation::UvToXy,
        Evaluation::XyToUv,
        Evaluation::UvToPk,
        Evaluation::XyToPk,
        Evaluation::UvToNormal,
        Evaluation::XyToNormal,
    ];

    /// Its name in snake case (`uv_to_z`); each binding spells it in its language's case.
    pub fn name(self) -> &'static str {
        match self {
            Evaluation::UvToZ => "uv_to_z",
            Evaluation::XyToZ => "xy_to_z",
            Evaluation::UvToXy => "uv_to_xy",
            Evaluation::XyToUv => "xy_to_uv",
            Evaluation::UvToPk => "uv_to_pk",
            Evaluation::XyToPk => "xy_to_pk",
            Evaluation::UvToNormal => "uv_to_normal",
            Evaluation::XyToNormal => "xy_to_normal",
        }
    }

    /// The names of the values it takes per point.
    pub fn inputs(self) -> [&'static str; 2] {
        if self.takes_xy() {
            ["x", "y"]
        } else {
            ["u", "v"]
        }
    }

    /// The names of the values it gives per point.
    pub fn output_names(self) -> &'static [&'static str] {
        match self {
            Evaluation::UvToZ | Evaluation::XyToZ => &["z"],
            Evaluation::UvToXy => &["x", "y"],
            Evaluation::XyToUv => &["u", "v"],
            Evaluation::UvToPk | Evaluation::XyToPk => &["heading", "curvature"],
            Evaluation::UvToNormal | Evaluation::XyToNormal => &["z", "nx", "ny", "nz"],
        }
    }

    /// The values it gives per point.
    pub fn outputs(self) -> usize {
        self.output_names().len()
    }

    /// Whether it takes x/y (else u/v).
    pub fn takes_xy(self) -> bool {
        matches!(self, Evaluation::XyToZ | Evaluation::XyToUv | Evaluation::XyToPk | Evaluation::XyToNormal)
    }

    /// Which points of [`ContactPoint::evaluate_many`]'s `columns` were answered NaN in some
    /// value (refused, or a NaN answered): what the bindings report as refused for arrays.
    pub fn answered_nan(columns: &[Vec<f64>]) -> Vec<bool> {
        let n = columns.first().map_or(0, Vec::len);
        (0..n).map(|i| columns.iter().any(|c| c[i].is_nan())).collect()
    }
}

impl ContactPoint {
    /// `call` at every point (`a[i]`, `b[i]`), in order, through the batch calls: one
    /// vector per value it gives, NaN where a point is refused (or its answer is NaN).
    pub fn evaluate_many(&mut self, call: Evaluation, a: &[f64], b: &[f64]) -> Vec<Vec<f64>> {
        let n = a.len().min(b.len());
        let mut out = vec![vec![f64::NAN; n]; call.outputs()];
        match (call, out.as_mut_slice()) {
            (Evaluation::UvToZ, [z]) => {
                self.uv_to_z_many(a, b, z);
            }
            (Evaluation::XyToZ, [z]) => {
                self.xy_to_z_many(a, b, z);
            }
            (Evaluation::UvToXy, [x, y]) => {
                self.uv_to_xy_many(a, b, x, y);
            }
            (Evaluation::XyToUv, [u, v]) => {
                self.xy_to_uv_many(a, b, u, v);
            }
            (Evaluation::UvToPk, [phi, curv]) => {
                self.uv_to_pk_many(a, b, phi, curv);
            }
            (Evaluation::XyToPk, [phi, curv]) => {
                self.xy_to_pk_many(a, b, phi, curv);
            }
            (Evaluation::UvToNormal | Evaluation::XyToNormal, [z, nx, ny, nz]) => {
                for i in 0..n {
                    if let Ok((height, [x, y, up])) = self.evaluate_normal(call, a[i], b[i]) {
                        (z[i], nx[i], ny[i], nz[i]) = (height, x, y, up);
                    }
                }
            }
            _ => unreachable!("one output vector per value of the call"),
        }
        out
    }

    /// `call` at one point as the C API's call answers it: its values (NaN where it is
    /// refused) and whether it was refused.
    pub fn evaluate_one_or_nan(&mut self, call: Evaluation, a: f64, b: f64) -> (Vec<f64>, bool) {
        match self.evaluate_one(call, a, b) {
            Ok(values) => (values, false),
            Err(_) => (vec![f64::NAN; call.outputs()], true),
        }
    }

    /// `call` at one point: its values, or why it was refused.
    pub fn evaluate_one(&mut self, call: Evaluation, a: f64, b: f64) -> Result<Vec<f64>> {
        Ok(match call {
            Evaluation::UvToZ => vec![self.uv_to_z(a, b)?],
            Evaluation::XyToZ => vec![self.xy_to_z(a, b)?],
            Evaluation::UvToXy => <[f64; 2]>::from(self.uv_to_xy(a, b)?).to_vec(),
            Evaluation::XyToUv => <[f64; 2]>::from(self.xy_to_uv(a, b)?).to_vec(),
            Evaluation::UvToPk => <[f64; 2]>::from(self.uv_to_pk(a, b)?).to_vec(),
            Evaluation::XyToPk => <[f64; 2]>::from(self.xy_to_pk(a, b)?).to_vec(),
            Evaluation::UvToNormal | Evaluation::XyToNormal => {
                let (z, [x, y, up]) = self.evaluate_normal(call, a, b)?;
                vec![z, x, y, up]
            }
        })
    }

    fn evaluate_normal(&mut self, call: Evaluation, a: f64, b: f64) -> Result<(f64, [f64; 3])> {
        match call {
            Evaluation::UvToNormal => self.uv_to_normal(a, b),
            _ => self.xy_to_normal(a, b),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::query::contact::ContactPoint;
    use crate::synth::RoadSpec;
    use std::sync::Arc;

    /// Batches equal the single calls bit for bit, failures as NaN, on points inside,
    /// on the borders, outside, and NaN, in every v border mode and with a smoothing zone.
    #[test]
    fn batches_equal_single_calls() {
        let road = RoadSpec::straight(20.0, 4.0, 0.1, 0.25)
            .with_heading(|u| 0.02 * u)
            .with_bank(|u| 0.01 * u)
            .with_elevation(|u, v| (u * 0.7).sin() * 0.01 + v * 0.02)
            .build()
            .unwrap();
        let road = Arc::new(road);
        let mut seed = 7u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut u: Vec<f64> = (0..500).map(|_| next() * 30.0 - 5.0).collect();
        let mut v: Vec<f64> = (0..500).map(|_| next() * 8.0 - 4.0).collect();
        u[3] = f64::NAN;
        v[4] = 20.0;
        u[5] = 20.0;
        // Border modes 0 to 4 in v; then mode 4 with a smoothing zone (no lean path).
        for mode in 0..=5 {
            let mut single = ContactPoint::new(road.clone());
            single.set_option_int(crate::base::settings::opt::BORDER_MODE_V, mode.min(4)).unwrap();
            if mode == 5 {
                single.set_option_double(crate::base::settings::opt::SMOOTH_U_BEGIN, 3.0).unwrap();
            }
            let mut batch = single.clone();
            let mut z = vec![0.0; u.len()];
            let ok = batch.uv_to_z_many(&u, &v, &mut z);
            let mut expected_ok = 0;
            for i in 0..u.len() {
                match single.uv_to_z(u[i], v[i]) {
                    Ok(e) => {
                        expected_ok += 1;
                        assert_eq!(e.to_bits(), z[i].to_bits(), "mode {mode}, point {i}");
                    }
                    Err(_) => assert!(z[i].is_nan()),
                }
            }
            assert_eq!(ok, expected_ok);
            // Lengths around the elevation batch's blocks and lead.
            for len in [0, 1, 15, 16, 17, 47, 48, 49, 63, 64, 65, 113] {
                let mut part = vec![0.0; len];
                let ok = batch.uv_to_z_many(&u[..len], &v[..len], &mut part);
                assert_eq!(ok, z[..len].iter().filter(|z| !z.is_nan()).count(), "mode {mode}, {len} points");
                for (a, b) in part.iter().zip(&z) {
                    assert_eq!(a.to_bits(), b.to_bits(), "mode {mode}, {len} points");
                }
            }
            let (mut x, mut y) = (vec![0.0; u.len()], vec![0.0; u.len()]);
            batch.uv_to_xy_many(&u, &v, &mut x, &mut y);
            let (mut bu, mut bv) = (vec![0.0; u.len()], vec![0.0; u.len()]);
            batch.xy_to_uv_many(&x, &y, &mut bu, &mut bv);
            for i in 0..u.len() {
                let p = single.uv_to_xy(u[i], v[i]).unwrap_or((f64::NAN, f64::NAN));
                assert_eq!((p.0.to_bits(), p.1.to_bits()), (x[i].to_bits(), y[i].to_bits()));
                let q = single.xy_to_uv(x[i], y[i]).unwrap_or((f64::NAN, f64::NAN));
                assert_eq!((q.0.to_bits(), q.1.to_bits()), (bu[i].to_bits(), bv[i].to_bits()), "point {i}");
            }
            // x/y to z, whose batch computes each elevation one search later; points
            // moved sideways so that some leave the road (refused with border mode none).
            let y: Vec<f64> = y.iter().enumerate().map(|(i, y)| y + (i % 7) as f64 * 0.9).collect();
            for len in [0, 1, 2, 3, u.len()] {
                let mut bz = vec![0.0; len];
                let ok = batch.xy_to_z_many(&x[..len], &y[..len], &mut bz);
                let mut expected_ok = 0;
                for i in 0..len {
                    match single.xy_to_z(x[i], y[i]) {
                        Ok(e) => {
                            expected_ok += 1;
                            assert_eq!(e.to_bits(), bz[i].to_bits(), "mode {mode}, {len} points, point {i}");
                        }
                        Err(_) => assert!(bz[i].is_nan(), "mode {mode}, {len} points, point {i}"),
                    }
                }
                assert_eq!(ok, expected_ok, "mode {mode}, {len} points");
                assert!(len < 100 || (ok > 0 && ok < len) || mode > 0, "mode {mode}: successes and failures");
            }
        }
    }

    /// Every call through `evaluate_many` equals `evaluate_one` point by point, in
    /// order (the x/y search history included), refusals as NaN.
    #[test]
    fn evaluate_many_equals_evaluate_one() {
        use crate::query::batch::Evaluation::*;
        let road = RoadSpec::straight(20.0, 4.0, 0.1, 0.25)
            .with_heading(|u| 0.05 * u)
            .with_elevation(|u, v| (u * 0.7).sin() * 0.01 + v * 0.02)
            .build()
            .unwrap();
        let road = Arc::new(road);
        let a: Vec<f64> = (0..60).map(|i| i as f64 * 0.4 - 2.0).collect();
        let b: Vec<f64> = (0..60).map(|i| (i % 9) as f64 * 0.6 - 2.5).collect();
        for call in [UvToZ, XyToZ, UvToXy, XyToUv, UvToPk, XyToPk, UvToNormal, XyToNormal] {
            let mut single = ContactPoint::new(road.clone());
            single.set_option_int(crate::base::settings::opt::BORDER_MODE_V, 0).unwrap();
            let mut batch = single.clone();
            let columns = batch.evaluate_many(call, &a, &b);
            assert_eq!(columns.len(), call.outputs());
            let mut refused = 0;
            for i in 0..a.len() {
                let expected = single.evaluate_one(call, a[i], b[i]);
                refused += usize::from(expected.is_err());
                let expected = expected.unwrap_or_else(|_| vec![f64::NAN; call.outputs()]);
                for (column, e) in columns.iter().zip(expected) {
                    assert_eq!(column[i].to_bits(), e.to_bits(), "{call:?}, point {i}");
                }
            }
            assert!(refused < a.len(), "{call:?}: answers");
            // Off the road sideways (border mode none): the elevations are refused.
            if matches!(call, UvToZ | XyToZ | UvToNormal | XyToNormal) {
                assert!(refused > 0, "{call:?}: refusals");
            }
        }
    }
}
