//! NaN handling of a cross section's borders, as the reference does it: the one place
//! its passes are written, for grids in memory and grids read in place alike.

use crate::base::settings::NanMode;

/// NaN handling on one cross section (see `Grid::fill_nans`): from the right border
/// leftwards a NaN takes its neighbour's value (or `off`), the first value copied in a
/// pass gets `off` added; then the same from the left border. `offset_applied` carries
/// whether the offset went to a value already (the grid's passes carry it from one cross
/// section to the next). Returns how many NaNs it found.
pub(crate) fn fill_row_nans(row: &mut [f32], mode: NanMode, off: f32, offset_applied: &mut bool) -> usize {
    let nv = row.len();
    let mut found = 0;
    for v in 1..nv {
        if row[v].is_nan() {
            found += 1;
            match mode {
                NanMode::SetZero => row[v] = off,
                NanMode::KeepLast => {
                    row[v] = row[v - 1];
                    if !row[v].is_nan() && !*offset_applied {
                        row[v] += off;
                        *offset_applied = true;
                    }
                }
                NanMode::Keep => {}
            }
        }
    }
    *offset_applied = false;
    for v in (1..nv).rev() {
        if row[v - 1].is_nan() && !row[v].is_nan() {
            found += 1;
            match mode {
                NanMode::SetZero => row[v - 1] = off,
                NanMode::KeepLast => {
                    row[v - 1] = row[v];
                    if !*offset_applied {
                        row[v - 1] += off;
                        *offset_applied = true;
                    }
                }
                NanMode::Keep => {}
            }
        }
    }
    found
}
