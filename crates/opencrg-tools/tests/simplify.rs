//! The simplified mesh: far fewer triangles than cells on a smooth road, z within the
//! bound at random points, every vertex on the surface, no cracks between triangles,
//! holes where the road has no elevation, and a bound that is not a number refused.

use opencrg_core::synth::RoadSpec;
use opencrg_core::{Budget, ContactPoint};
use opencrg_tools::simplify::{simplified_mesh, Stage};
use std::collections::HashMap;
use std::sync::Arc;

fn contact_point(spec: RoadSpec) -> ContactPoint {
    ContactPoint::new(Arc::new(spec.build().unwrap()))
}

/// A small pseudo-random generator (no dependency), uniform in [0, 1).
fn random(seed: u64) -> impl FnMut() -> f64 {
    let mut s = seed;
    move || {
        s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The mesh's z at (x, y) (the triangle holding it, found among those whose x range
/// covers it), or `None` where no triangle does.
struct Lookup<'m> {
    mesh: &'m opencrg_tools::mesh::Mesh,
    bins: HashMap<i64, Vec<usize>>,
    width: f64,
}

impl<'m> Lookup<'m> {
    fn new(mesh: &'m opencrg_tools::mesh::Mesh, width: f64) -> Self {
        let mut bins: HashMap<i64, Vec<usize>> = HashMap::new();
        for (k, t) in mesh.triangles.iter().enumerate() {
            let xs = t.map(|i| mesh.positions[i as usize][0]);
            let (lo, hi) = (
                xs.iter().copied().fold(f64::INFINITY, f64::min),
                xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            );
            for b in (lo / width).floor() as i64..=(hi / width).floor() as i64 {
                bins.entry(b).or_default().push(k);
            }
        }
        Lookup { mesh, bins, width }
    }

    fn z(&self, x: f64, y: f64) -> Option<f64> {
        for &k in self.bins.get(&((x / self.width).floor() as i64))? {
            let [a, b, c] = self.mesh.triangles[k].map(|i| self.mesh.positions[i as usize]);
            let det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            let wb = ((x - a[0]) * (c[1] - a[1]) - (y - a[1]) * (c[0] - a[0])) / det;
            let wc = ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) / det;
            let tol = -1e-9;
            if wb >= tol && wc >= tol && 1.0 - wb - wc >= tol {
                return Some(a[2] + wb * (b[2] - a[2]) + wc * (c[2] - a[2]));
            }
        }
        None
    }
}

/// A smooth straight road of 500 m by 5 m at 1 cm by 5 cm: 5 million cells. With a bound
/// of 1 mm the mesh has at most 1 % of the full mesh's triangles, and its z stays within
/// the bound of the road's at random points.
#[test]
fn smooth_road_few_triangles_within_the_bound() {
    let spec = RoadSpec::straight(500.0, 5.0, 0.01, 0.05).with_elevation(|u, v| {
        0.04 * (u / 37.0 * std::f64::consts::TAU).sin() + 0.03 * (u / 91.0).cos() + 0.02 * v - 0.004 * v * v
    });
    let cp = contact_point(spec);
    let (nu, nv) = (cp.road().grid().nu, cp.road().grid().nv);
    assert_eq!((nu - 1) * (nv - 1), 5_000_000);
    let bound = 0.001;
    let mut stages = Vec::new();
    let mesh = simplified_mesh(&cp, None, None, bound, &Budget::machine(), &mut |s| stages.push(s)).unwrap();
    let full = 2 * (nu - 1) * (nv - 1);
    assert!(mesh.triangles.len() * 100 <= full, "{} triangles of {full}", mesh.triangles.len());
    assert!(mesh.triangles.len() > 100, "{} triangles", mesh.triangles.len());
    assert_eq!(stages.first(), Some(&Stage::Sampling));
    assert_eq!(stages.last(), Some(&Stage::Building));
    assert!(stages.contains(&Stage::Measuring(1.0)));

    // The road runs along x from u = 0: (u, v) is (x, y).
    let lookup = Lookup::new(&mesh, 1.0);
    let (u_first, u_last) = cp.road().u_range();
    assert_eq!(u_first, 0.0);
    let mut r = random(5);
    let mut worst: f64 = 0.0;
    for _ in 0..20_000 {
        let (u, v) = (u_first + r() * (u_last - u_first), -2.5 + 5.0 * r());
        let (x, y) = cp.uv_to_xy(u, v).unwrap();
        let z = lookup.z(x, y).unwrap_or_else(|| panic!("no triangle at u {u}, v {v}"));
        worst = worst.max((z - cp.uv_to_z(u, v).unwrap()).abs());
    }
    assert!(worst <= bound, "the mesh lies {worst} m from the road");
    // Every vertex lies on the surface.
    for p in &mesh.positions {
        assert!((p[2] - cp.uv_to_z(p[0], p[1]).unwrap()).abs() < 1e-12, "{p:?}");
    }
}

/// A road with local bumps and a node without elevation, turned on the map: every edge inside the
/// mesh belongs to two triangles (no cracks, no vertex in the middle of another
/// triangle's edge), the edges of only one triangle lie on the border or around the
/// hole, the triangles face up, and z is within the bound at the grid's nodes.
#[test]
fn bumpy_road_without_cracks() {
    let spec = RoadSpec::straight(60.0, 4.0, 0.05, 0.1).starting_at(100.0, 50.0, 0.4).with_elevation(|u, v| {
        if (u - 30.0).abs() < 0.01 && v.abs() < 0.01 {
            return f64::NAN;
        }
        let bump = |c: f64, w: f64| (-((u - c) / w).powi(2)).exp();
        0.05 * bump(12.0, 0.7) + 0.02 * bump(40.0, 3.0) * (v * 2.0).sin() + 0.001 * (u * 0.5).sin()
    });
    let cp = contact_point(spec);
    let bound = 0.0005;
    let mesh = simplified_mesh(&cp, None, None, bound, &Budget::machine(), &mut |_| {}).unwrap();
    let (nu, nv) = (cp.road().grid().nu, cp.road().grid().nv);
    assert!(mesh.triangles.len() < (nu - 1) * (nv - 1), "{} triangles", mesh.triangles.len());

    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &mesh.triangles {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            *edges.entry((a.min(b), a.max(b))).or_default() += 1;
        }
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        assert!((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0.0, "{t:?} faces down");
    }
    let hole_uv = (30.0, 0.0);
    let (u_first, u_last) = cp.road().u_range();
    for (&(a, b), &count) in &edges {
        assert!(count <= 2, "edge {a}-{b} in {count} triangles");
        if count == 1 {
            // A border edge: both ends on the same side of the road, or near the hole.
            let [ta, tb] = [a, b].map(|i| mesh.texcoords[i as usize]);
            let on_side = |k: usize, value: f32| (ta[k] - value).abs() < 1e-6 && (tb[k] - value).abs() < 1e-6;
            let by_hole = [ta, tb].iter().all(|t| {
                let (u, v) = (u_first + f64::from(t[0]) * (u_last - u_first), -2.0 + 4.0 * f64::from(t[1]));
                (u - hole_uv.0).abs() < 0.5 && (v - hole_uv.1).abs() < 0.5
            });
            assert!(
                on_side(0, 0.0) || on_side(0, 1.0) || on_side(1, 0.0) || on_side(1, 1.0) || by_hole,
                "edge {ta:?}-{tb:?} has one triangle"
            );
        }
    }

    // At the grid's nodes away from the hole: the mesh's z (found from x/y) within the bound.
    let r = cp.road().clone();
    let lookup_mesh = Lookup::new(&mesh, 0.5);
    let (du, mut checked) = (r.increments().0, 0);
    for i in 0..nu {
        for &v in &r.grid().v {
            let u = u_first + i as f64 * du;
            if (u - hole_uv.0).abs() < 0.2 && (v - hole_uv.1).abs() < 0.2 {
                continue;
            }
            let (x, y) = cp.uv_to_xy(u, v).unwrap();
            if let Some(z) = lookup_mesh.z(x, y) {
                checked += 1;
                assert!((z - cp.uv_to_z(u, v).unwrap()).abs() <= bound + 1e-9, "node {u}, {v}: {z}");
            }
        }
    }
    assert!(checked * 10 >= nu * nv * 9, "{checked} of {} nodes found", nu * nv);
}

#[test]
fn a_bound_that_is_not_a_positive_number_is_refused() {
    let cp = contact_point(RoadSpec::straight(10.0, 2.0, 0.5, 0.5));
    for bound in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let err = simplified_mesh(&cp, None, None, bound, &Budget::machine(), &mut |_| {}).unwrap_err().to_string();
        assert!(err.contains("largest error"), "{err}");
    }
}
