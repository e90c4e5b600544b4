//! Surface normals: the analytic gradient of the evaluated surface (grid, reference line
//! z, banking, border modes, smoothing), turned from u/v into x/y.
//!
//! Inside a grid cell the elevation is a bilinear patch plus the linear reference line z
//! and banking terms; its gradient is exact. On a cell edge the gradient is that of the
//! cell the evaluation itself uses (the one towards larger u and v; at the far borders,
//! the last cell). Where a border mode holds the surface constant (keep, zero) the
//! gradient across that border is 0; repeat and reflect carry (reflect mirrors) it.

use crate::model::road::Road;
use crate::query::eval::{self, EvalOptions};

/// Elevation and its gradient (d z / d u, d z / d v) at (u, v); `None` where a border
/// mode refuses.
pub(crate) fn uv_gradient(road: &Road, options: &EvalOptions, u: f64, v: f64) -> Option<(f64, f64, f64)> {
    let p = eval::place(road, options, u, v)?;
    let (l, g) = (&road.line, &road.grid);
    let (ua, va) = (&p.ua, &p.va);
    let (iu, fu, iv, fv) = (ua.index, ua.frac, va.index, va.frac);
    let (mut zu, mut zv) = (0.0, 0.0);
    if ua.with_values && va.with_values {
        let at = |i: usize, j: usize| f64::from(g.at(i, j));
        let (z00, z01, z10, z11) = (at(iu, iv), at(iu, iv + 1), at(iu + 1, iv), at(iu + 1, iv + 1));
        // d/dfu and d/dfv of z00 (1-fu)(1-fv) + z10 fu (1-fv) + z01 (1-fu) fv + z11 fu fv.
        zu += ((z10 - z00) * (1.0 - fv) + (z11 - z01) * fv) * ua.dfrac;
        zv += ((z01 - z00) * (1.0 - fu) + (z11 - z10) * fu) * va.dfrac;
    }
    // The reference line terms use the fraction clamped to the cell.
    let dfu = if (0.0..=1.0).contains(&fu) { ua.dfrac } else { 0.0 };
    if let Some(rz) = &l.z {
        zu += (rz[iu + 1] - rz[iu]) * dfu;
    }
    if l.has_bank && ua.with_values {
        let fc = fu.clamp(0.0, 1.0);
        let (bank, dbank) = match &l.bank {
            Some(b) => (b[iu] + fc * (b[iu + 1] - b[iu]), (b[iu + 1] - b[iu]) * dfu),
            None => (l.bank_first, 0.0),
        };
        let inside = va.v >= g.v_first && va.v <= g.v_last;
        // As the evaluation holds v for the banking (also where the borders disagree).
        let vb = if va.v < g.v_first {
            g.v_first
        } else if va.v > g.v_last {
            g.v_last
        } else {
            va.v
        };
        zu += dbank * vb;
        zv += if inside { bank * va.dv } else { 0.0 };
    }
    // Border mode zero makes the surface a constant.
    let zero_u = !ua.in_core && ua.mode == crate::base::settings::BorderMode::ExZero as i32;
    let zero_v = ua.in_core && !va.in_core && va.mode == crate::base::settings::BorderMode::ExZero as i32;
    if zero_u || zero_v {
        zu = 0.0;
        zv = 0.0;
    }
    if let Some((scale, base, dscale)) = p.smooth {
        zu = zu * scale + (p.unsmoothed - base) * dscale * ua.du;
        zv *= scale;
    }
    Some((p.z, zu, zv))
}

/// The Jacobian of (u, v) -> (x, y): [[dx/du, dx/dv], [dy/du, dy/dv]].
fn jacobian(road: &Road, options: &EvalOptions, u: f64, v: f64) -> [[f64; 2]; 2] {
    let l = &road.line;
    let u = eval::wrap_closed_u(l, options, u);
    let (i, frac) = l.interval(u);
    let t = &l.trig;
    let (c, s) = if frac < 0.0 {
        (t.first_cos, t.first_sin)
    } else if frac > 1.0 {
        (t.last_cos, t.last_sin)
    } else {
        let [n1x, n1y, n2x, n2y] = l.normals[i];
        let (ax, ay) = (l.x[i] + v * n1x, l.y[i] + v * n1y);
        let (bx, by) = (l.x[i + 1] + v * n2x, l.y[i + 1] + v * n2y);
        return [[(bx - ax) / l.u_inc, n1x + frac * (n2x - n1x)], [(by - ay) / l.u_inc, n1y + frac * (n2y - n1y)]];
    };
    [[c, -s], [s, c]]
}

/// Elevation and the upward unit normal in x/y/z at (u, v).
pub(crate) fn uv_normal(road: &Road, options: &EvalOptions, u: f64, v: f64) -> Option<(f64, [f64; 3])> {
    let (z, zu, zv) = uv_gradient(road, options, u, v)?;
    let [[a, b], [c, d]] = jacobian(road, options, u, v);
    // (zu, zv) = J^T (zx, zy): solve the 2 x 2 system.
    let det = a * d - b * c;
    let (zx, zy) = if det.abs() > 1e-300 { ((d * zu - c * zv) / det, (-b * zu + a * zv) / det) } else { (0.0, 0.0) };
    let len = (zx * zx + zy * zy + 1.0).sqrt();
    Some((z, [-zx / len, -zy / len, 1.0 / len]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::RoadSpec;

    /// On a tilted plane z = a x + b y the normal is (-a, -b, 1) normalized, whatever the
    /// road's heading.
    #[test]
    fn plane_normal() {
        let (a, b) = (0.03, -0.05);
        let (phi, x0, y0) = (0.7f64, 3.0, -2.0);
        let road = RoadSpec::straight(10.0, 4.0, 0.5, 0.5)
            .starting_at(x0, y0, phi)
            .with_heading(move |_| phi)
            .with_elevation(move |u, v| {
                let (x, y) = (x0 + u * phi.cos() - v * phi.sin(), y0 + u * phi.sin() + v * phi.cos());
                a * x + b * y
            })
            .build()
            .unwrap();
        let opts = EvalOptions::from(road.options());
        let (_, n) = uv_normal(&road, &opts, 3.3, 0.7).unwrap();
        let len = (a * a + b * b + 1.0f64).sqrt();
        for (got, want) in n.iter().zip([-a / len, -b / len, 1.0 / len]) {
            assert!((got - want).abs() < 1e-6, "{n:?}");
        }
    }
}
