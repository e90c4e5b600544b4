//! Roads from point clouds: the points triangulated (Delaunay, with `spade`), each grid
//! node interpolated linearly in the triangle around it.

use super::filter::fill_nan;
use super::generate::{along, along_with, Layout, Points};
use super::nodes::{at_nodes, Progress};
use super::path::Curve;
use super::resample::{cross_sections, position_count};
use opencrg_core::budget::{filled, Budget};
use opencrg_core::units::Num;
use opencrg_core::ContactPoint;
use opencrg_core::Road;
use opencrg_core::{Error, Result};
use spade::handles::FixedVertexHandle;
use spade::{DelaunayTriangulation, HasPosition, Point2, PositionInTriangulation, Triangulation};
use std::sync::Arc;

/// How a cloud becomes a road.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Import {
    /// The reference line's points (a smooth curve passes through them, as in
    /// [`generate`](super::generate::generate)); without, a line fitted through the cloud.
    pub refline: Option<Points>,
    /// The road's width; without, as wide as the cloud reaches on both sides of the line.
    pub width: Option<f64>,
    /// Distance between cross sections, m.
    pub u_inc: f64,
    /// Distance between long sections, m.
    pub v_inc: f64,
    /// Nodes in triangles with an edge longer than this are NaN (holes in the cloud);
    /// without, 5 times the larger increment, at least 0.5 m.
    pub max_edge: Option<f64>,
    /// Whether NaN nodes are filled (as [`Filter::FillNan`](super::filter::Filter)).
    pub fill: bool,
    /// Only the points within these x and y ranges (`[(x_min, x_max), (y_min, y_max)]`)
    /// are used: a way to leave out stray points far from the rest.
    pub crop: Option<[(f64, f64); 2]>,
}

#[derive(Clone, Copy)]
struct CloudPoint {
    p: Point2<f64>,
    z: f64,
}

impl HasPosition for CloudPoint {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.p
    }
}

/// The memory a point takes in the triangulation (spade's vertices, edges and faces,
/// and the copy handed to it), measured on clouds of 10^6 points and rounded up.
const TRIANGULATED_POINT_BYTES: f64 = 240.0;

/// The road a point cloud (x, y, z) describes along a reference line. Refused: points
/// without z or fewer than three, a layout as [`generate`](super::generate::generate)
/// refuses it, a triangulation or grid beyond `budget`, points covering less than half
/// the grid.
pub fn import(cloud: &Points, how: &Import, progress: Progress, budget: &Budget) -> Result<Road> {
    let z = cloud.z.as_ref().ok_or_else(|| Error::out_of_range("the points have no z"))?;
    if cloud.y.len() != cloud.len() || z.len() != cloud.len() {
        return Err(Error::out_of_range(format!(
            "the points have {} x, {} y and {} z values: one of each per point",
            cloud.len(),
            cloud.y.len(),
            z.len()
        )));
    }
    let cropped;
    let cloud = match how.crop {
        Some(area) => {
            cropped = crop(cloud, z, area)?;
            &cropped
        }
        None => cloud,
    };
    let z = cloud.z.as_ref().ok_or_else(|| Error::out_of_range("the points have no z"))?;
    if cloud.len() < 3 {
        return Err(Error::out_of_range(format!("{} point(s): a surface needs at least three", cloud.len())));
    }
    // What the points' spread says, for a refusal: stray points far from the rest make a
    // road the size of the distance between them.
    let hint = |e: Error| match (e, stray_points(cloud)) {
        (Error::TooLarge(m), Some(stray)) => Error::TooLarge(format!("{m}; {stray}")),
        (e, _) => e,
    };
    let request = format!("triangulating {} points", cloud.len());
    budget.admit(&request, cloud.len() as f64, "triangulated points", TRIANGULATED_POINT_BYTES)?;
    let line = match &how.refline {
        Some(l) => l.clone(),
        None => fitted_line(cloud)?,
    };
    // The road's cross sections with the narrowest grid, sized before the width is
    // measured around the line.
    along_admitted(&line, Layout { width: 2.0 * how.v_inc, u_inc: how.u_inc, v_inc: how.v_inc }, budget)
        .map_err(hint)?;
    let width = match how.width {
        Some(w) => w,
        None => reach(cloud, &line, how.v_inc, budget)?,
    };
    let mut d = along(&line, Layout { width, u_inc: how.u_inc, v_inc: how.v_inc }, budget).map_err(hint)?;
    if line.z.is_none() {
        // Heights near the grid's values keep single precision fine.
        d.z_start = z.iter().sum::<f64>() / z.len() as f64;
    }
    progress("triangulating", 0, cloud.len() as u64);
    let mut vertices =
        filled(cloud.len(), CloudPoint { p: Point2::new(0.0, 0.0), z: 0.0 }, "the points to triangulate")?;
    for (i, v) in vertices.iter_mut().enumerate() {
        *v = CloudPoint { p: Point2::new(cloud.x[i], cloud.y[i]), z: z[i] };
    }
    let tri: DelaunayTriangulation<CloudPoint> = DelaunayTriangulation::bulk_load(vertices)
        .map_err(|e| Error::out_of_range(format!("the points cannot be triangulated: {e}")))?;
    progress("triangulating", cloud.len() as u64, cloud.len() as u64);
    let max_edge = how.max_edge.unwrap_or((5.0 * how.u_inc.max(how.v_inc)).max(0.5));
    let frame = Arc::new(d.frame(d.v[0], d.v[d.nv() - 1])?);
    let line_z = d.line_z();
    let v = d.v.clone();
    let nodes = |_: &str, done, total| progress("gridding", done, total);
    d.z = at_nodes(
        &frame,
        &v,
        || None::<FixedVertexHandle>,
        |hint, node| match interpolate(&tri, node.x, node.y, max_edge, hint) {
            Some(z) => (z - line_z[node.iu]) as f32,
            None => f32::NAN,
        },
        &nodes,
    )?;
    let covered = d.z.iter().filter(|z| !z.is_nan()).count();
    let share = covered as f64 / d.z.len() as f64;
    if share < 0.5 {
        return Err(Error::out_of_range(format!(
            "the points cover {:.0} % of the road's {} nodes (triangles with edges up to {max_edge} m): \
             the reference line or the width reaches beyond the cloud",
            100.0 * share,
            d.z.len()
        )));
    }
    if how.fill {
        let nu = d.nu();
        fill_nan(&mut d.z, nu, &d.v);
    }
    let what = format!(
        "imported by opencrg {} from {} points: {:.1} % of the nodes inside the cloud{}",
        env!("CARGO_PKG_VERSION"),
        cloud.len(),
        100.0 * share,
        if how.fill && covered < d.z.len() { ", the others filled" } else { "" }
    );
    d.into_road(&what)
}

/// z at (x, y), linear in the Delaunay triangle holding it; `None` outside the cloud or
/// in a triangle with an edge longer than `max_edge`.
fn interpolate(
    tri: &DelaunayTriangulation<CloudPoint>,
    x: f64,
    y: f64,
    max_edge: f64,
    hint: &mut Option<FixedVertexHandle>,
) -> Option<f64> {
    let p = Point2::new(x, y);
    let found = match *hint {
        Some(h) => tri.locate_with_hint(p, h),
        None => tri.locate(p),
    };
    let long = |a: Point2<f64>, b: Point2<f64>| (a.x - b.x).hypot(a.y - b.y) > max_edge;
    match found {
        PositionInTriangulation::OnVertex(v) => {
            *hint = Some(v);
            Some(tri.vertex(v).data().z)
        }
        PositionInTriangulation::OnEdge(e) => {
            let e = tri.directed_edge(e);
            let [a, b] = e.vertices();
            *hint = Some(a.fix());
            let (pa, pb) = (a.position(), b.position());
            if long(pa, pb) {
                return None;
            }
            let len = (pb.x - pa.x).hypot(pb.y - pa.y);
            let t = ((x - pa.x).hypot(y - pa.y) / len).clamp(0.0, 1.0);
            Some(a.data().z * (1.0 - t) + b.data().z * t)
        }
        PositionInTriangulation::OnFace(f) => {
            let face = tri.face(f);
            let [a, b, c] = face.vertices();
            *hint = Some(a.fix());
            let (pa, pb, pc) = (a.position(), b.position(), c.position());
            if long(pa, pb) || long(pb, pc) || long(pc, pa) {
                return None;
            }
            let [wa, wb, wc] = face.barycentric_interpolation(p);
            Some(wa * a.data().z + wb * b.data().z + wc * c.data().z)
        }
        _ => None,
    }
}

/// A line through the middle of the cloud: the centroids of slices across its main
/// direction (at most 40, at least 5 m long), in order along it. Clouds of roads that
/// turn back on themselves need a given line.
fn fitted_line(cloud: &Points) -> Result<Points> {
    let n = cloud.len() as f64;
    let (mx, my) = (cloud.x.iter().sum::<f64>() / n, cloud.y.iter().sum::<f64>() / n);
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for (x, y) in cloud.x.iter().zip(&cloud.y) {
        let (dx, dy) = (x - mx, y - my);
        sxx += dx * dx;
        sxy += dx * dy;
        syy += dy * dy;
    }
    // The main axis of the covariance.
    let angle = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let (c, s) = (angle.cos(), angle.sin());
    let along: Vec<f64> = cloud.x.iter().zip(&cloud.y).map(|(x, y)| (x - mx) * c + (y - my) * s).collect();
    let (lo, hi) = along.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| (a.min(t), b.max(t)));
    let length = hi - lo;
    let slices = ((length / 5.0).floor() as usize).clamp(2, 40);
    let mut sums = vec![(0.0, 0.0, 0usize); slices];
    for (i, &t) in along.iter().enumerate() {
        let k = (((t - lo) / length * slices as f64) as usize).min(slices - 1);
        sums[k].0 += cloud.x[i];
        sums[k].1 += cloud.y[i];
        sums[k].2 += 1;
    }
    let mut line = Points::default();
    for (x, y, count) in sums.into_iter().filter(|s| s.2 > 0) {
        line.x.push(x / count as f64);
        line.y.push(y / count as f64);
    }
    if line.len() < 2 {
        return Err(Error::out_of_range("the points do not spread along a line to fit a road to"));
    }
    Ok(line)
}

/// How wide a road the cloud carries around the line: twice the smaller of the reaches
/// to the right and to the left (each the 99th percentile of the points' |v| on that
/// side, of at most 200,000 points), down to whole long section increments. The points'
/// v are measured against the line walked at most 20,000 cross sections along, whatever
/// the road's own increment.
fn reach(cloud: &Points, line: &Points, v_inc: f64, budget: &Budget) -> Result<f64> {
    let length = Curve::through(&line.x, &line.y, None).map_or(0.0, |c| c.length);
    let probe_inc = (length / 20_000.0).max(v_inc).max(1e-3);
    let probe = along_with(line, Layout { width: 2.0, u_inc: probe_inc, v_inc: 1.0 }, probe_inc / 8.0, budget)?;
    let frame = Arc::new(probe.frame(-1.0, 1.0)?);
    let mut cp = ContactPoint::new(frame);
    let step = (cloud.len() / 200_000).max(1);
    let (mut right, mut left) = (Vec::new(), Vec::new());
    for i in (0..cloud.len()).step_by(step) {
        if let Ok((_, v)) = cp.xy_to_uv(cloud.x[i], cloud.y[i]) {
            if v < 0.0 {
                right.push(-v);
            } else {
                left.push(v);
            }
        }
    }
    let q = |mut d: Vec<f64>| {
        d.sort_by(f64::total_cmp);
        d.get((d.len() as f64 * 0.99) as usize).or(d.last()).copied().unwrap_or(0.0)
    };
    let half = q(right).min(q(left));
    let width = 2.0 * (half / v_inc).floor() * v_inc;
    if !(width >= 2.0 * v_inc) {
        return Err(Error::out_of_range("the points lie on one side of the line: give the width"));
    }
    Ok(width)
}

/// Sizes the road `along` would make against `budget`, without making it.
fn along_admitted(line: &Points, layout: Layout, budget: &Budget) -> Result<()> {
    let curve = Curve::through(&line.x, &line.y, None)
        .map_err(|i| Error::out_of_range(format!("reference line points {i} and {} coincide", i + 1)))?;
    let nu = cross_sections(curve.length, layout.u_inc)?;
    let nv = position_count(-layout.width / 2.0, layout.width / 2.0, layout.v_inc, "v increment")?;
    let request = format!("a road {} m long with a u increment of {} m", Num(curve.length), Num(layout.u_inc));
    budget.admit_road(&request, nu, nv, 0.0).map(|_| ())
}

/// The points within `area` (x range, y range). Refused: an area that is not two ranges
/// of finite numbers, or holds fewer than three points.
fn crop(cloud: &Points, z: &[f64], [(x0, x1), (y0, y1)]: [(f64, f64); 2]) -> Result<Points> {
    if ![x0, x1, y0, y1].iter().all(|c| c.is_finite()) || x0 >= x1 || y0 >= y1 {
        return Err(Error::out_of_range(format!(
            "crop x {}:{}, y {}:{}: two ranges of finite numbers, each from the smaller to the larger",
            Num(x0),
            Num(x1),
            Num(y0),
            Num(y1)
        )));
    }
    let (mut xs, mut ys, mut zs) = (Vec::new(), Vec::new(), Vec::new());
    for ((&x, &y), &z) in cloud.x.iter().zip(&cloud.y).zip(z) {
        if (x0..=x1).contains(&x) && (y0..=y1).contains(&y) {
            xs.push(x);
            ys.push(y);
            zs.push(z);
        }
    }
    let kept = Points { x: xs, y: ys, z: Some(zs) };
    if kept.len() < 3 {
        return Err(Error::out_of_range(format!(
            "{} of the {} points lie within x {}:{}, y {}:{}: a surface needs at least three",
            kept.len(),
            cloud.len(),
            Num(x0),
            Num(x1),
            Num(y0),
            Num(y1)
        )));
    }
    Ok(kept)
}

/// A sentence on stray points, when a few lie far from the rest: the share of points in
/// the central box and its size against the full extent, and the crop that leaves the
/// others out; `None` when the points spread evenly.
fn stray_points(cloud: &Points) -> Option<String> {
    let quantiles = |values: &[f64]| {
        let mut v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
        let n = v.len();
        if n < 3 {
            return None;
        }
        let k = |q: f64| ((n - 1) as f64 * q).round() as usize;
        let lo = *v.select_nth_unstable_by(k(0.01), f64::total_cmp).1;
        let hi = *v.select_nth_unstable_by(k(0.99), f64::total_cmp).1;
        let min = v.iter().copied().fold(f64::INFINITY, f64::min);
        let max = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Some((min, lo, hi, max))
    };
    let (xmin, x0, x1, xmax) = quantiles(&cloud.x)?;
    let (ymin, y0, y1, ymax) = quantiles(&cloud.y)?;
    let central = (x1 - x0).hypot(y1 - y0);
    let full = (xmax - xmin).hypot(ymax - ymin);
    if !(full > 3.0 * central + 100.0) {
        return None;
    }
    // The box around the central points, a tenth of its size (at least 10 m) added round.
    let margin = (0.1 * central).max(10.0);
    let (cx0, cx1, cy0, cy1) =
        ((x0 - margin).floor(), (x1 + margin).ceil(), (y0 - margin).floor(), (y1 + margin).ceil());
    let outside =
        (0..cloud.len()).filter(|&i| !((cx0..=cx1).contains(&cloud.x[i]) && (cy0..=cy1).contains(&cloud.y[i]))).count();
    Some(format!(
        "all but {outside} of the {} points lie within {central:.0} m of each other, all of them within {full:.0} m: \
         stray points? Leave them out with a crop to x {cx0}:{cx1}, y {cy0}:{cy1} (--crop {cx0}:{cx1},{cy0}:{cy1})",
        cloud.len()
    ))
}
