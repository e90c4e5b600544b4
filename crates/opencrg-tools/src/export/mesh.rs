//! The road's surface as a triangle mesh for 3D tools: a vertex at every grid node (u
//! along the reference line, v at each long section), its x/y/z, upward normal and u/v
//! texture coordinates evaluated by a [`ContactPoint`] (so with its options, and with
//! the road's modifiers as applied), two triangles per cell; cells with a corner without
//! elevation (NaN) are left out.

use opencrg_core::budget::Budget;
use opencrg_core::ContactPoint;
use opencrg_core::{Error, Result};

/// The memory of a mesh vertex: position, normal and texture coordinates, its share of
/// the triangles, and the same again as the bytes of a file being written.
pub(crate) const VERTEX_BYTES: f64 = 136.0;

/// A triangle mesh: positions in the road's x/y/z frame (m), upward unit normals, texture
/// coordinates (u and v of the road, scaled to 0..1 over the mesh), and triangles as
/// indices into them, counter-clockwise seen from above.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// x, y, z of each vertex.
    pub positions: Vec<[f64; 3]>,
    /// The upward unit normal at each vertex.
    pub normals: Vec<[f32; 3]>,
    /// u and v of each vertex, scaled to 0..1 over the mesh.
    pub texcoords: Vec<[f32; 2]>,
    /// Three vertex indices per triangle.
    pub triangles: Vec<[u32; 3]>,
    /// The u of the grid nodes (m): vertex `i * v.len() + j` lies at `u[i]`, `v[j]`; empty
    /// for a simplified mesh, whose vertices do not lie on a grid.
    pub u: Vec<f64>,
    /// The v of the long sections (m); empty for a simplified mesh.
    pub v: Vec<f64>,
    /// Named parts of the triangles, in order, each a glTF primitive and an OBJ group;
    /// empty: one part of every triangle.
    pub groups: Vec<MeshGroup>,
    /// Numbers per vertex of the mesh's own (one per vertex each): glTF attributes
    /// `_NAME` (upper case), PLY properties `name`.
    pub values: Vec<VertexValues>,
}

/// `text` as a JSON string (for a group's `extras`).
pub fn json_string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A named part of a mesh's triangles.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MeshGroup {
    /// Its name (an OBJ group's, a glTF primitive's `extras.name`).
    pub name: String,
    /// Its triangles: a range of [`Mesh::triangles`].
    pub triangles: std::ops::Range<usize>,
    /// What it is, as the members of a JSON object (`"road":"12","lane":-1`), written to
    /// its glTF primitive's `extras` with its name.
    pub extras: String,
}

/// A number at each vertex of a mesh, under a name.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct VertexValues {
    /// Its name: lower case letters, digits and `_`.
    pub name: String,
    /// One value per vertex.
    pub values: Vec<f32>,
}

/// The grid nodes of the road within `range` (inclusive), as indices into `nodes`.
fn nodes_within(nodes: &[f64], range: Option<(f64, f64)>, what: &str) -> Result<std::ops::Range<usize>> {
    let Some((a, b)) = range else { return Ok(0..nodes.len()) };
    let first = nodes.partition_point(|&x| x < a.min(b));
    let end = nodes.partition_point(|&x| x <= a.max(b));
    if end < first + 2 {
        let (lo, hi) = (nodes.first().copied().unwrap_or(0.0), nodes.last().copied().unwrap_or(0.0));
        return Err(Error::out_of_range(format!(
            "{what} {a}:{b} holds fewer than two grid nodes of the road (which spans {what} {lo} to {hi})"
        )));
    }
    Ok(first..end)
}

/// The u of the grid nodes with u in `u` and the v of the long sections with v in `v`
/// (m, inclusive; all of them when `None`). Refused: a range holding fewer than two.
pub(crate) fn grid_nodes(
    cp: &ContactPoint,
    u: Option<(f64, f64)>,
    v: Option<(f64, f64)>,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let road = cp.road();
    let (u_first, _) = road.u_range();
    let du = road.increments().0;
    let all: Vec<f64> = (0..road.grid().nu).map(|i| u_first + i as f64 * du).collect();
    let (iu, iv) = (nodes_within(&all, u, "u")?, nodes_within(&road.grid().v, v, "v")?);
    Ok((all[iu].to_vec(), road.grid().v[iv].to_vec()))
}

/// The mesh of the surface the contact point evaluates, over the grid nodes with u in
/// `u` and v in `v` (m, inclusive; the whole road when `None`). Refused: a range holding
/// fewer than two nodes, a mesh of 2^32 vertices or more, a mesh beyond `budget`.
pub fn grid_mesh(cp: &ContactPoint, u: Option<(f64, f64)>, v: Option<(f64, f64)>, budget: &Budget) -> Result<Mesh> {
    grid_mesh_every(cp, u, v, 1, budget)
}

/// [`grid_mesh`] over every `step`-th node along u (and the last one in the range): a
/// lighter mesh for a view, whose vertices still lie on the surface.
pub fn grid_mesh_every(
    cp: &ContactPoint,
    u: Option<(f64, f64)>,
    v: Option<(f64, f64)>,
    step: usize,
    budget: &Budget,
) -> Result<Mesh> {
    let (all, vs) = grid_nodes(cp, u, v)?;
    let (last, step) = (all.len() - 1, step.max(1));
    let mut us: Vec<f64> = all.iter().copied().step_by(step).collect();
    if last % step != 0 {
        us.push(all[last]);
    }
    let (us, vs) = (&us[..], &vs[..]);
    let count = us.len() * vs.len();
    if count > u32::MAX as usize {
        return Err(Error::out_of_range(format!("a mesh of {count} vertices is more than 32-bit indices can hold")));
    }
    let request = format!("a mesh of {} x {} grid nodes", us.len(), vs.len());
    budget.admit(&request, count as f64, "vertices", VERTEX_BYTES)?;
    let (u0, u_span) = (us[0], us[us.len() - 1] - us[0]);
    let (v0, v_span) = (vs[0], vs[vs.len() - 1] - vs[0]);
    let mut mesh = Mesh {
        positions: Vec::with_capacity(count),
        normals: Vec::with_capacity(count),
        texcoords: Vec::with_capacity(count),
        triangles: Vec::new(),
        u: us.to_vec(),
        v: vs.to_vec(),
        ..Mesh::default()
    };
    for &u in us {
        for &v in vs {
            let (x, y) = cp.uv_to_xy(u, v).unwrap_or((f64::NAN, f64::NAN));
            let (z, n) = cp.uv_to_normal(u, v).unwrap_or((f64::NAN, [0.0, 0.0, 1.0]));
            mesh.positions.push([x, y, z]);
            mesh.normals.push(n.map(|c| c as f32));
            mesh.texcoords.push([((u - u0) / u_span) as f32, ((v - v0) / v_span) as f32]);
        }
    }
    let nv = vs.len();
    let ok = |i: usize| mesh.positions[i].iter().all(|c| c.is_finite());
    let mut triangles = Vec::with_capacity(2 * (us.len() - 1) * (nv - 1));
    for i in 0..us.len() - 1 {
        for j in 0..nv - 1 {
            // v grows to the left of the direction of u: (u, v), (u+, v), (u+, v+) turn
            // counter-clockwise seen from above.
            let (a, b, c, d) = (i * nv + j, (i + 1) * nv + j, (i + 1) * nv + j + 1, i * nv + j + 1);
            if ok(a) && ok(b) && ok(c) && ok(d) {
                triangles.push([a as u32, b as u32, c as u32]);
                triangles.push([a as u32, c as u32, d as u32]);
            }
        }
    }
    mesh.triangles = triangles;
    Ok(mesh)
}
