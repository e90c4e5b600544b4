//! Where the cells of each tile of a grid read in place lie in u and v: for each column
//! of tiles along the road and each row across it, the first and last u (or v) whose
//! cell the tile holds, found once when the road is prepared. A contact point entering a
//! tile looks its bounds up instead of searching for them (a search takes a few
//! divisions and steps of one rounding each, on the path of every tile switch).
//!
//! A point's cell index is the truncation of its grid fraction `(x - first) / inc`; the
//! bounds are exact in that arithmetic: every x from a tile's first bound to its last
//! has its index in the tile, and no other x has.

use crate::model::grid::Grid;
use crate::model::refline::RefLine;
use crate::model::tiles::{HALF_U, TILE_V};

/// The largest `b <= last` for which `(b - first) / inc` lies below `limit` (and so
/// does that of every x from `first` to `b`: subtraction and division by a positive
/// increment never decrease as x grows); NaN where it is not found within a few steps
/// down from `last`.
pub(crate) fn inner_bound(first: f64, last: f64, inc: f64, limit: f64) -> f64 {
    let mut b = last;
    for _ in 0..64 {
        if (b - first) / inc < limit {
            return b;
        }
        b = b.next_down();
    }
    f64::NAN
}

/// The smallest `x` for which `(x - first) / inc` is at least `limit`, found within a few
/// steps of `first + limit * inc`; NaN where it is not. The largest `x` below `limit` is
/// the one just under it.
fn at_least(first: f64, inc: f64, limit: f64) -> f64 {
    let frac = |x: f64| (x - first) / inc;
    let mut x = first + limit * inc;
    if frac(x) >= limit {
        for _ in 0..64 {
            let down = x.next_down();
            if frac(down) < limit {
                return x;
            }
            x = down;
        }
    } else {
        for _ in 0..64 {
            x = x.next_up();
            if frac(x) >= limit {
                return x;
            }
        }
    }
    f64::NAN
}

/// The bounds of the cells of each half of a tile column (along u, [`HALF_U`] cross
/// sections) and of each tile row (across, in v) of a grid read in place; empty for a
/// grid in memory.
#[derive(Debug, Clone, Default)]
pub(crate) struct TileBounds {
    along: Box<[[f64; 2]]>,
    across: Box<[[f64; 2]]>,
}

/// An axis of the grid: where its first section lies, its last section's position, the
/// increment, the last section's grid fraction (`n - 1`), and how many sections a tile
/// holds cells of.
struct Axis {
    first: f64,
    last: f64,
    inc: f64,
    last_frac: f64,
    tile: usize,
}

impl Axis {
    /// The first and last position of the cells of each tile: those of the tile's
    /// sections, within the range whose fractions lie below the last section's. A tile
    /// ends just under where the next begins.
    fn bounds(&self, sections: usize) -> Box<[[f64; 2]]> {
        let Axis { first, last, inc, last_frac, tile } = *self;
        let (lo, hi) = (first, inner_bound(first, last, inc, last_frac));
        let tiles = sections.saturating_sub(1).div_ceil(tile);
        // Where each tile begins, and where the range ends just above the last one.
        let starts: Vec<f64> = (0..tiles)
            .map(|t| if t == 0 { lo } else { at_least(first, inc, (t * tile) as f64).max(lo) })
            .chain([hi.next_up()])
            .collect();
        starts.windows(2).map(|w| [w[0], w[1].next_down().min(hi)]).collect()
    }
}

impl TileBounds {
    /// The bounds of the tiles of `grid` (read in place) on `line`.
    pub(crate) fn new(line: &RefLine, grid: &Grid) -> TileBounds {
        if !grid.is_in_place() {
            return TileBounds::default();
        }
        let along =
            Axis { first: line.u_first, last: line.u_last, inc: line.u_inc, last_frac: line.last_frac, tile: HALF_U };
        let across =
            Axis { first: grid.v_first, last: grid.v_last, inc: grid.v_inc, last_frac: grid.last_frac, tile: TILE_V };
        TileBounds { along: along.bounds(grid.nu), across: across.bounds(grid.nv) }
    }

    /// The first and last u of the cells of the halves of tiles `hu` along (the cross
    /// sections from `hu * HALF_U` on; `None` beyond the grid).
    #[inline]
    pub(crate) fn along(&self, hu: usize) -> Option<[f64; 2]> {
        self.along.get(hu).copied()
    }

    /// The first and last v of the cells of the tiles `tv` across (`None` beyond the grid).
    #[inline]
    pub(crate) fn across(&self, tv: usize) -> Option<[f64; 2]> {
        self.across.get(tv).copied()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each tile's bounds hold exactly the positions whose cell index (the truncated grid
    /// fraction) lies in the tile: the first bound's index is the tile's first, the
    /// position one rounding step below it belongs to the tile before; the last bound's
    /// index is in the tile, the position one step above it beyond (or past the range).
    #[test]
    fn bounds_hold_exactly_the_cells_of_their_tiles() {
        let frac = |a: &Axis, x: f64| (x - a.first) / a.inc;
        for (first, inc, sections, tile) in [
            (0.0, 0.01, 5000, HALF_U),
            (-3.7, 0.013, 2049, HALF_U),
            (12345.678, 0.0097, 1537, HALF_U),
            (-2.0, 0.01, 401, TILE_V),
            (-1.234, 0.0233, 97, TILE_V),
        ] {
            let last_frac = (sections - 1) as f64;
            let a = Axis { first, last: first + last_frac * inc, inc, last_frac, tile };
            let bounds = a.bounds(sections);
            assert_eq!(bounds.len(), (sections - 1).div_ceil(tile));
            let hi = inner_bound(first, a.last, inc, last_frac);
            for (t, &[from, to]) in bounds.iter().enumerate() {
                let (start, end) = ((t * tile) as f64, ((t + 1) * tile) as f64);
                assert!(from <= to, "tile {t} of {first}/{inc}");
                assert_eq!(frac(&a, from).trunc(), start, "tile {t} starts at its first section");
                if t > 0 {
                    assert!(frac(&a, from.next_down()) < start, "tile {t}: below its start is the tile before");
                }
                assert!(frac(&a, to) < end.min(last_frac), "tile {t} ends inside");
                if t + 1 < bounds.len() {
                    assert!(frac(&a, to.next_up()) >= end, "tile {t}: above its end is the next tile");
                    assert_eq!(bounds[t + 1][0], to.next_up(), "tiles {t} and {} meet", t + 1);
                } else {
                    assert_eq!(to, hi, "the last tile ends where the range does");
                }
            }
        }
    }
}
