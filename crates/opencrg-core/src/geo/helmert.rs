//! The datum transformations of the specification between earth-centred coordinates of
//! the global and of the local ellipsoid: seven-parameter Helmert transformations in
//! the coordinate-frame convention, `X_local = T + (1 + ds) R X_global` (the parameters
//! describe the way from the global datum to the local one, as the MATLAB tools read
//! them; the way back is the inverse).
//!
//! - `HN7`: R is the exact rotation, `R = (Rx(rx) Ry(ry) Rz(rz))ᵀ`; its inverse is its
//!   transpose.
//! - `HL7`: R is the same rotation linearised for small angles; the inverse solves the
//!   linear system exactly.
//! - `HS7`: the linearised rotation with `1 + ds` on its diagonal (no separate scale); the
//!   inverse applies the same formula with every parameter negated.

use crate::base::math;
use crate::model::georef::{Datum, DatumKind};

type Matrix = [[f64; 3]; 3];

fn transpose(m: Matrix) -> Matrix {
    let mut t = [[0.0; 3]; 3];
    for (i, row) in m.iter().enumerate() {
        for (j, v) in row.iter().enumerate() {
            t[j][i] = *v;
        }
    }
    t
}

fn times(m: &Matrix, x: [f64; 3]) -> [f64; 3] {
    m.map(|row| row[0] * x[0] + row[1] * x[1] + row[2] * x[2])
}

fn product(a: &Matrix, b: &Matrix) -> Matrix {
    let mut p = [[0.0; 3]; 3];
    for (i, row) in p.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    p
}

/// The solution y of `m y = x` (Cramer's rule; the matrices here are close to unity).
fn solve(m: &Matrix, x: [f64; 3]) -> [f64; 3] {
    let det = |m: &Matrix| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(m);
    std::array::from_fn(|c| {
        let mut k = *m;
        for r in 0..3 {
            k[r][c] = x[r];
        }
        det(&k) / d
    })
}

/// The linearised rotation (and, for `HS7`, scale) matrix of the parameters, before
/// transposition.
fn linear(r: [f64; 3], diagonal: f64) -> Matrix {
    [[diagonal, -r[2], r[1]], [r[2], diagonal, -r[0]], [-r[1], r[0], diagonal]]
}

/// The exact rotation `Rx(rx) Ry(ry) Rz(rz)`, before transposition.
fn exact(r: [f64; 3]) -> Matrix {
    let (s1, c1) = math::sin_cos(r[0]);
    let (s2, c2) = math::sin_cos(r[1]);
    let (s3, c3) = math::sin_cos(r[2]);
    let rx = [[1.0, 0.0, 0.0], [0.0, c1, -s1], [0.0, s1, c1]];
    let ry = [[c2, 0.0, s2], [0.0, 1.0, 0.0], [-s2, 0.0, c2]];
    let rz = [[c3, -s3, 0.0], [s3, c3, 0.0], [0.0, 0.0, 1.0]];
    product(&product(&rx, &ry), &rz)
}

/// Earth-centred coordinates of the global datum to the local one.
pub(crate) fn global_to_local(d: &Datum, x: [f64; 3]) -> [f64; 3] {
    let t = d.translation;
    let (m, scale) = match d.kind {
        DatumKind::Nop => return x,
        DatumKind::Hl7 => (transpose(linear(d.rotation, 1.0)), 1.0 + d.ds),
        DatumKind::Hn7 => (transpose(exact(d.rotation)), 1.0 + d.ds),
        DatumKind::Hs7 => (transpose(linear(d.rotation, 1.0 + d.ds)), 1.0),
    };
    let r = times(&m, x);
    std::array::from_fn(|i| t[i] + scale * r[i])
}

/// Earth-centred coordinates of the local datum to the global one.
pub(crate) fn local_to_global(d: &Datum, x: [f64; 3]) -> [f64; 3] {
    let t = d.translation;
    let shifted: [f64; 3] = std::array::from_fn(|i| x[i] - t[i]);
    match d.kind {
        DatumKind::Nop => x,
        DatumKind::Hl7 => solve(&transpose(linear(d.rotation, 1.0)), shifted).map(|v| v / (1.0 + d.ds)),
        DatumKind::Hn7 => times(&exact(d.rotation), shifted).map(|v| v / (1.0 + d.ds)),
        DatumKind::Hs7 => {
            let negated =
                Datum { kind: DatumKind::Hs7, ds: -d.ds, rotation: d.rotation.map(|r| -r), translation: t.map(|v| -v) };
            global_to_local(&negated, x)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverses() {
        let x = [4_157_222.5, 664_789.3, 4_774_952.1];
        for kind in [DatumKind::Hl7, DatumKind::Hn7] {
            let d = Datum {
                kind,
                ds: -5.2379e-6,
                rotation: [3.49e-6, 5.39e-7, -8.34e-6],
                translation: [-604.7, -72.4, -424.4],
            };
            let there = global_to_local(&d, x);
            assert!((there[0] - x[0]).abs() > 100.0);
            let back = local_to_global(&d, there);
            assert!((0..3).all(|i| (back[i] - x[i]).abs() < 1e-6), "{kind:?}: {back:?}");
        }
        // The simple form's inverse is approximate: within a millimetre here.
        let d = Datum { kind: DatumKind::Hs7, ds: 1e-6, rotation: [1e-6, -2e-6, 3e-6], translation: [1.0, 2.0, 3.0] };
        let back = local_to_global(&d, global_to_local(&d, x));
        assert!((0..3).all(|i| (back[i] - x[i]).abs() < 1e-3), "{back:?}");
    }
}
