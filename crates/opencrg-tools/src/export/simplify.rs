//! A mesh of the road's surface with far fewer triangles than the grid has cells, whose
//! elevation stays within a stated bound of the road's: a right-triangulated irregular
//! network (RTIN; Evans, Kirkpatrick and Townsend, "Right-Triangulated Irregular
//! Networks", Algorithmica 30, 2001).
//!
//! A lattice of points regular in u and v lies over the road's grid, at least as fine
//! as it in both directions, in square tiles of 2^k x 2^k lattice cells side by side along
//! u (k from the number of long sections). In each tile, triangles are halved along
//! their longest edge, from the tile's two halves down to triangles smaller than a grid
//! cell. Every triangle of that hierarchy is measured against the road's grid nodes it
//! covers: it *fails* when a node lies farther than the bound from its plane (in z), or
//! a corner or node has no elevation. The point halving a triangle's longest edge is
//! *needed* when a triangle on either side of that edge fails, or when a point needed
//! below them is; the mesh then halves every triangle whose point is needed. Since a
//! needed point is needed for both triangles sharing the edge (also across the border
//! of two tiles, where the levels are measured together), the mesh has no cracks, and
//! every triangle kept whole covers no node farther from its plane than the bound.
//! Between nodes the road is bilinear in each cell; at the smallest level, triangles
//! are finer than the cells.

use crate::export::mesh::{grid_nodes, Mesh, VERTEX_BYTES};
use opencrg_core::budget::Budget;
use opencrg_core::ContactPoint;
use opencrg_core::{Error, Result};

/// The fewest lattice cells across a tile: narrow roads get tiles longer than their
/// width, so that a smooth stretch needs few triangles.
const MIN_TILE: usize = 32;

/// A point of the lattice: (index along u, index across).
type Point = (usize, usize);

/// A triangle of the hierarchy: the ends of its longest edge, then its right-angled corner.
#[derive(Clone, Copy)]
struct Triangle {
    a: Point,
    b: Point,
    c: Point,
}

impl Triangle {
    /// The point halving the longest edge.
    fn middle(&self) -> Point {
        ((self.a.0 + self.b.0) / 2, (self.a.1 + self.b.1) / 2)
    }

    /// The two halves, split at [`Triangle::middle`].
    fn halves(&self) -> [Triangle; 2] {
        let m = self.middle();
        [Triangle { a: self.a, b: self.c, c: m }, Triangle { a: self.c, b: self.b, c: m }]
    }

    /// The two halves of the square tile `size` lattice cells wide starting at lattice
    /// index `start` along u.
    fn tile(start: usize, size: usize) -> [Triangle; 2] {
        let (lo, hi) = ((start, 0), (start + size, size));
        [Triangle { a: lo, b: hi, c: (start + size, 0) }, Triangle { a: hi, b: lo, c: (start, size) }]
    }
}

/// The lattice: `nu` x `nv` points, `h_u` and `h_v` apart from (`u0`, `v0`), in tiles of
/// `size` cells, with the road's elevation at each point.
struct Lattice {
    size: usize,
    tiles: usize,
    nv: usize,
    u0: f64,
    v0: f64,
    h_u: f64,
    h_v: f64,
    z: Vec<f64>,
}

impl Lattice {
    fn index(&self, p: Point) -> usize {
        p.0 * self.nv + p.1
    }

    /// Points along u.
    fn nu(&self) -> usize {
        self.tiles * self.size + 1
    }

    fn uv(&self, p: Point) -> (f64, f64) {
        (self.u0 + p.0 as f64 * self.h_u, self.v0 + p.1 as f64 * self.h_v)
    }

    /// The levels of triangles with a point halving their longest edge: 2k for tiles of
    /// 2^k cells (the triangles of level 2k are the smallest, half a lattice cell).
    fn levels(&self) -> u32 {
        2 * self.size.trailing_zeros()
    }
}

/// The road's grid nodes in the range meshed, seen from the lattice: their places in
/// lattice units and their elevations, and for each lattice line the first node at or
/// after it and the first node after it (a node on a line, up to rounding, counts as on
/// it).
struct Cover {
    /// Node `i`'s u in lattice units.
    u: Vec<f64>,
    /// Node `j`'s v in lattice units.
    v: Vec<f64>,
    /// The elevation of node (`i`, `j`) at `z[i * v.len() + j]`.
    z: Vec<f64>,
    /// For lattice index `p` along u: the nodes from `u_from[p]` on lie at or after it.
    u_from: Vec<usize>,
    /// For lattice index `p` along u: the nodes before `u_to[p]` lie at or before it.
    u_to: Vec<usize>,
    v_from: Vec<usize>,
    v_to: Vec<usize>,
}

impl Cover {
    /// The nodes at `us` x `vs` (m) with elevations `z`, seen from `lattice`.
    fn new(lattice: &Lattice, us: &[f64], vs: &[f64], z: Vec<f64>) -> Self {
        let u: Vec<f64> = us.iter().map(|&u| (u - lattice.u0) / lattice.h_u).collect();
        let v: Vec<f64> = vs.iter().map(|&v| (v - lattice.v0) / lattice.h_v).collect();
        let lines = |at: &[f64], count: usize| {
            let slack = 1e-7;
            let from = (0..count).map(|p| at.partition_point(|&x| x < p as f64 - slack)).collect();
            let to = (0..count).map(|p| at.partition_point(|&x| x <= p as f64 + slack)).collect();
            (from, to)
        };
        let (u_from, u_to) = lines(&u, lattice.nu());
        let (v_from, v_to) = lines(&v, lattice.nv);
        Cover { u, v, z, u_from, u_to, v_from, v_to }
    }
}

/// Whether triangle `t` covers a grid node farther than `bound` from its plane (or a node
/// or corner without elevation). Worked in lattice units, where the triangle's corners
/// are whole numbers.
fn fails(t: &Triangle, lattice: &Lattice, cover: &Cover, bound: f64) -> bool {
    let corners = [t.a, t.b, t.c].map(|p| [p.0 as f64, p.1 as f64, lattice.z[lattice.index(p)]]);
    if corners.iter().any(|c| !c[2].is_finite()) {
        return true;
    }
    let [p0, p1, p2] = corners;
    let (e1, e2) = ([p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]], [p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]]);
    // The plane's normal (the cross product of two edges): z = p0.z - (n.u du + n.v dv) / n.z.
    let n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    let (gu, gv) = (-n[0] / n[2], -n[1] / n[2]);
    // Inside: on the same side of each edge as the opposite corner (edges included, with
    // a margin of rounding: a node on an edge belongs to both triangles).
    let edges = [(p0, p1), (p1, p2), (p2, p0)].map(|(a, b)| {
        let s = n[2].signum();
        (s * (b[0] - a[0]), s * (b[1] - a[1]), a[0], a[1])
    });
    let margin = -1e-9 * n[2].abs();
    let (lo, hi) = (
        (t.a.0.min(t.b.0).min(t.c.0), t.a.1.min(t.b.1).min(t.c.1)),
        (t.a.0.max(t.b.0).max(t.c.0), t.a.1.max(t.b.1).max(t.c.1)),
    );
    let nv = cover.v.len();
    let (js, je) = (cover.v_from[lo.1], cover.v_to[hi.1]);
    for i in cover.u_from[lo.0]..cover.u_to[hi.0] {
        let u = cover.u[i];
        let row = &cover.z[i * nv + js..i * nv + je];
        for (&z, &v) in row.iter().zip(&cover.v[js..je]) {
            let inside = edges.iter().all(|&(du, dv, au, av)| du * (v - av) - dv * (u - au) >= margin);
            if inside {
                let plane = p0[2] + gu * (u - p0[0]) + gv * (v - p0[1]);
                if !((z - plane).abs() <= bound) {
                    return true;
                }
            }
        }
    }
    false
}

/// Calls `f` on every triangle of `level` below `t` (of level `at`).
fn each_at(t: Triangle, at: u32, level: u32, f: &mut impl FnMut(&Triangle)) {
    if at == level {
        f(&t);
    } else {
        for half in t.halves() {
            each_at(half, at + 1, level, f);
        }
    }
}

/// The needed points of the lattice (see the module's text), level by level from the
/// smallest triangles up, every tile at each level: a point on the border of two tiles
/// is measured from both before the level above reads it.
fn needed_points(lattice: &Lattice, cover: &Cover, bound: f64, progress: &mut dyn FnMut(f64)) -> Vec<bool> {
    let mut needed = vec![false; lattice.z.len()];
    let levels = lattice.levels();
    for (done, level) in (0..levels).rev().enumerate() {
        for tile in 0..lattice.tiles {
            for root in Triangle::tile(tile * lattice.size, lattice.size) {
                each_at(root, 0, level, &mut |t| {
                    let m = lattice.index(t.middle());
                    if needed[m] {
                        return;
                    }
                    let below = level + 1 < levels && t.halves().iter().any(|h| needed[lattice.index(h.middle())]);
                    needed[m] = below || fails(t, lattice, cover, bound);
                });
            }
            progress((done as f64 + (tile + 1) as f64 / lattice.tiles as f64) / levels as f64);
        }
    }
    needed
}

/// The lattice over the grid nodes `us` x `vs`: tiles of 2^k cells across (at least as
/// many as the grid has cells across, at least [`MIN_TILE`]), as many along u as the grid
/// needs, their cells no longer than the grid's.
fn lattice_over(cp: &ContactPoint, us: &[f64], vs: &[f64]) -> Result<Lattice> {
    let size = (vs.len() - 1).next_power_of_two().max(MIN_TILE);
    let tiles = (us.len() - 1).div_ceil(size);
    let (nu, nv) = lattice_size(us.len(), vs.len());
    if nu.checked_mul(nv).is_none_or(|n| n > u32::MAX as usize) {
        return Err(Error::out_of_range(format!(
            "a lattice of {nu} x {nv} points is more than 32-bit indices can hold"
        )));
    }
    let (u0, v0) = (us[0], vs[0]);
    let h_u = (us[us.len() - 1] - u0) / (tiles * size) as f64;
    let h_v = (vs[vs.len() - 1] - v0) / size as f64;
    let mut lattice = Lattice { size, tiles, nv, u0, v0, h_u, h_v, z: Vec::with_capacity(nu * nv) };
    for i in 0..nu {
        for j in 0..nv {
            let (u, v) = lattice.uv((i, j));
            lattice.z.push(cp.uv_to_z(u, v).unwrap_or(f64::NAN));
        }
    }
    Ok(lattice)
}

/// The points of the lattice over `nu` x `nv` grid nodes along u and across (see
/// [`lattice_over`]).
fn lattice_size(nu: usize, nv: usize) -> (usize, usize) {
    let size = (nv - 1).next_power_of_two().max(MIN_TILE);
    ((nu - 1).div_ceil(size) * size + 1, size + 1)
}

/// Where a simplified mesh stands, for a progress display.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stage {
    /// Evaluating the road at its grid nodes and the lattice's points.
    Sampling,
    /// Measuring the triangles: the fraction done (0 to 1).
    Measuring(f64),
    /// Building the mesh from the triangles kept.
    Building,
}

/// The mesh of the surface the contact point evaluates over the grid nodes with u in `u`
/// and v in `v` (m, inclusive; the whole road when `None`), simplified so that its z
/// stays within `max_error` (m) of the road's at every grid node (see the module's
/// text). `progress` is told each stage. The mesh's `u` and `v` are empty: its
/// vertices do not lie on a grid. Refused: a bound that is not a positive number, a
/// range holding fewer than two nodes.
pub fn simplified_mesh(
    cp: &ContactPoint,
    u: Option<(f64, f64)>,
    v: Option<(f64, f64)>,
    max_error: f64,
    budget: &Budget,
    progress: &mut dyn FnMut(Stage),
) -> Result<Mesh> {
    if !(max_error > 0.0 && max_error.is_finite()) {
        return Err(Error::out_of_range(format!(
            "the largest error must be a positive number of metres, not {max_error}"
        )));
    }
    progress(Stage::Sampling);
    let (us, vs) = grid_nodes(cp, u, v)?;
    let (nu, nv) = lattice_size(us.len(), vs.len());
    let request = format!("a simplified mesh of {} x {} grid nodes", us.len(), vs.len());
    // The grid's elevations, the lattice's, which of its points are needed and their
    // vertices, at worst a vertex of the mesh at every one.
    budget.admit(&request, (nu as f64) * (nv as f64), "lattice points", 8.0 + 8.0 + 1.0 + 4.0 + VERTEX_BYTES)?;
    let z = us.iter().flat_map(|&u| vs.iter().map(move |&v| (u, v))).map(|(u, v)| cp.uv_to_z(u, v).unwrap_or(f64::NAN));
    let z = z.collect();
    let lattice = lattice_over(cp, &us, &vs)?;
    let cover = Cover::new(&lattice, &us, &vs, z);
    let needed = needed_points(&lattice, &cover, max_error, &mut |f| progress(Stage::Measuring(f)));
    progress(Stage::Building);
    Ok(build(cp, &lattice, &needed))
}

/// The mesh of the triangles kept: a triangle is halved where its middle point is
/// needed; triangles with a corner without elevation are left out.
fn build(cp: &ContactPoint, lattice: &Lattice, needed: &[bool]) -> Mesh {
    let mut kept = Vec::new();
    let levels = lattice.levels();
    fn descend(t: Triangle, level: u32, levels: u32, lattice: &Lattice, needed: &[bool], kept: &mut Vec<Triangle>) {
        if level < levels && needed[lattice.index(t.middle())] {
            for half in t.halves() {
                descend(half, level + 1, levels, lattice, needed, kept);
            }
        } else {
            kept.push(t);
        }
    }
    for tile in 0..lattice.tiles {
        for root in Triangle::tile(tile * lattice.size, lattice.size) {
            descend(root, 0, levels, lattice, needed, &mut kept);
        }
    }
    let (u_span, v_span) = (lattice.h_u * (lattice.tiles * lattice.size) as f64, lattice.h_v * lattice.size as f64);
    let mut vertex_of = vec![u32::MAX; lattice.z.len()];
    let mut mesh = Mesh::default();
    for t in kept {
        let corners = [t.a, t.b, t.c];
        if corners.iter().any(|&p| !lattice.z[lattice.index(p)].is_finite()) {
            continue;
        }
        let mut ids = corners.map(|p| {
            let k = lattice.index(p);
            if vertex_of[k] == u32::MAX {
                vertex_of[k] = mesh.positions.len() as u32;
                let (u, v) = lattice.uv(p);
                let (x, y) = cp.uv_to_xy(u, v).unwrap_or((f64::NAN, f64::NAN));
                let (_, n) = cp.uv_to_normal(u, v).unwrap_or((f64::NAN, [0.0, 0.0, 1.0]));
                mesh.positions.push([x, y, lattice.z[k]]);
                mesh.normals.push(n.map(|c| c as f32));
                mesh.texcoords.push([((u - lattice.u0) / u_span) as f32, ((v - lattice.v0) / v_span) as f32]);
            }
            vertex_of[k]
        });
        // Counter-clockwise seen from above: u forward, v to the left, as x and y.
        let [(ua, va), (ub, vb), (uc, vc)] = corners.map(|p| (p.0 as i64, p.1 as i64));
        if (ub - ua) * (vc - va) - (vb - va) * (uc - ua) < 0 {
            ids.swap(1, 2);
        }
        mesh.triangles.push(ids);
    }
    mesh
}
