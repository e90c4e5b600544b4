//! A part of a road: the cross sections and long sections between two u (and v), at
//! the grid nodes inside, left where they were.

use opencrg_core::draft::Draft;
use opencrg_core::units::Metres;
use opencrg_core::units::Num;
use opencrg_core::Road;
use opencrg_core::{Error, Result};

/// The part of `road` between `u.0` and `u.1` (and between `v.0` and `v.1`, when
/// given): the grid nodes inside those ranges, with the same surface at the same x/y/z.
/// A range must overlap the road by at least two nodes in each direction.
pub fn cut(road: &Road, u: (f64, f64), v: Option<(f64, f64)>) -> Result<Road> {
    let d = Draft::line_of(road);
    let (u_first, u_last) = road.u_range();
    let (v_right, v_left) = road.v_range();
    let (a, b) = nodes_within(u, |i| d.u_first + i as f64 * d.u_inc, d.nu())
        .ok_or_else(|| outside("u", u, (u_first, u_last)))?;
    let (c, e) = match v {
        Some(v) => nodes_within(v, |i| d.v[i], d.nv()).ok_or_else(|| outside("v", v, (v_right, v_left)))?,
        None => (0, d.nv() - 1),
    };
    let what = format!(
        "cut by opencrg {}: u {} to {} m, v {} to {} m",
        env!("CARGO_PKG_VERSION"),
        Metres(d.u_first + a as f64 * d.u_inc),
        Metres(d.u_first + b as f64 * d.u_inc),
        Metres(d.v[c]),
        Metres(d.v[e])
    );
    let (us, vs) = (a..=b, c..=e);
    // A grid read in place as its file gives it: the part is read from the file where it
    // is asked for (written out, it streams through); else its values are copied.
    match road.grid().part(us.clone(), vs.clone()) {
        Some(part) => slice(d, Vec::new(), us, vs).into_road_over(&what, part),
        None => {
            let values = part_values(road.grid(), us.clone(), vs.clone())?;
            slice(d, values, us, vs).into_road(&what)
        }
    }
}

/// The values of the cross sections `us` and long sections `vs` of `grid`, long section by
/// long section: from memory, or only those cross sections read from the file of a grid
/// read in place.
fn part_values(
    grid: &opencrg_core::grid::Grid,
    us: std::ops::RangeInclusive<usize>,
    vs: std::ops::RangeInclusive<usize>,
) -> Result<Vec<f32>> {
    let (a, b, nu) = (*us.start(), *us.end(), grid.nu);
    let len = b - a + 1;
    if let Some(values) = grid.in_memory() {
        let mut part = Vec::with_capacity(len * vs.clone().count());
        for iv in vs {
            part.extend_from_slice(&values[iv * nu + a..=iv * nu + b]);
        }
        return Ok(part);
    }
    let mut part = vec![0.0f32; len * vs.clone().count()];
    grid.rows(a..b + 1, |iu, row| {
        for (k, iv) in vs.clone().enumerate() {
            part[k * len + iu - a] = row[iv];
        }
        Ok::<(), Error>(())
    })?;
    Ok(part)
}

/// The first and last of `n` nodes (positions `at(i)`, increasing) within `range`, when
/// at least two are.
fn nodes_within(range: (f64, f64), at: impl Fn(usize) -> f64, n: usize) -> Option<(usize, usize)> {
    let (lo, hi) = (range.0.min(range.1), range.0.max(range.1));
    // Positions computed from a grid carry rounding; a bound on a node takes the node.
    let slack = |x: f64| 1e-9 * (1.0 + x.abs());
    let first = (0..n).find(|&i| at(i) >= lo - slack(lo))?;
    let last = (0..n).rev().find(|&i| at(i) <= hi + slack(hi))?;
    (last > first).then_some((first, last))
}

fn outside(axis: &str, asked: (f64, f64), road: (f64, f64)) -> Error {
    Error::out_of_range(format!(
        "{axis} range {}:{} holds fewer than two grid nodes of the road ({axis} from {} to {} m)",
        Num(asked.0),
        Num(asked.1),
        road.0,
        road.1
    ))
}

/// The draft's cross sections `us` and long sections `vs` with `part` as their elevations
/// (long section by long section; empty for a grid part the road reads itself), the line
/// starting at the first of them where it was.
fn slice(d: Draft, part: Vec<f32>, us: std::ops::RangeInclusive<usize>, vs: std::ops::RangeInclusive<usize>) -> Draft {
    let (x, y) = d.line_xy();
    let z = d.line_z();
    let (a, b) = (*us.start(), *us.end());
    let nu = d.nu();
    let moved = a != 0 || b != nu - 1;
    Draft {
        u_first: d.u_first + a as f64 * d.u_inc,
        start: (x[a], y[a]),
        z_start: z[a],
        phi: d.phi[us.clone()].to_vec(),
        slope: d.slope.as_ref().map(|s| s[us.clone()].to_vec()),
        bank: d.bank.as_ref().map(|s| s[us.clone()].to_vec()),
        regular: d.regular,
        // The same banking over the part kept.
        bank_v: (d.bank_v.0.max(d.v[*vs.start()]), d.bank_v.1.min(d.v[*vs.end()])),
        v: d.v[vs].to_vec(),
        z: part,
        moved: d.moved || moved,
        ..d
    }
}
