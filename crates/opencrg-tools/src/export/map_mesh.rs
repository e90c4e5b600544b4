//! The drivable surface of a map as one triangle mesh for 3D tools: every lane of the
//! chosen roads and types, following its borders, the elevation, superelevation, lateral
//! shape and lane heights, with the CRG records laid on, in world coordinates.
//!
//! Each lane section is cut where anything along s starts anew (reference line records,
//! CRG records, lane widths, profiles); every piece is meshed as rows across the road
//! (stations shared by all its lanes, so that neighbouring lanes meet vertex on vertex)
//! and columns across each lane, from its inner border (lambda 0) to its outer one
//! (lambda 1). Where a CRG record lays its heights, rows and columns start at the CRG
//! grid's increments; elsewhere rows are halved until the surface between them lies
//! within the bound of the chord (columns too where a lateral shape bends the section).
//! With a bound given, the rows and columns of CRG pieces are then thinned: a piece
//! starts from its corners, and wherever a sample of the full resolution lies farther
//! than the bound from the mesh's triangles, the quad holding it is halved: by a row
//! (for all lanes of the piece, so that no crack opens) where the surface bends along
//! s, by a column where it bends across, by both where it only twists.
//!
//! The mesh carries, per vertex, `friction` (-1 where none is known), `road` (the
//! road's index in the map), `lane` (its id), `s` and `t`; one group of triangles per
//! lane of a lane section, named and described (road id, lane id, section, type).

use crate::export::mesh::{json_string, Mesh, MeshGroup, VertexValues};
use opencrg_core::{Budget, Error, Result};
use opencrg_odr::Road;
use opencrg_odr::{Lane, LaneSection};
use opencrg_odr::{Probe, Surface};
use std::sync::Arc;

/// What to mesh and how closely.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MeshOptions {
    /// The roads meshed (their ids); `None`: every road.
    pub roads: Option<Vec<String>>,
    /// The lane types meshed; `None`: every lane whose type is not `none`.
    pub lane_types: Option<Vec<String>>,
    /// The largest distance (m) between the mesh and the surface's samples; `None`: CRG
    /// detail at its grid's resolution, [`DEFAULT_ERROR`] elsewhere.
    pub max_error: Option<f64>,
}

/// The bound (m) of the mesh where no CRG record lays detail and no bound is given.
pub const DEFAULT_ERROR: f64 = 0.001;
/// The shortest row spacing the halving goes down to (m).
const MIN_STEP: f64 = 0.005;
/// The longest row spacing (m).
const MAX_STEP: f64 = 25.0;
/// The bytes a sample costs while a piece is meshed, and a vertex of the mesh with its
/// share of triangles and values.
const SAMPLE_BYTES: f64 = 48.0;
const VERTEX_BYTES: f64 = 160.0;
/// How far inside its lane a border vertex is evaluated (m), so that it takes its own
/// lane's height.
const INSIDE: f64 = 1e-9;

/// A lane of a section, as meshed.
struct LaneRef<'a> {
    lane: &'a Lane,
    left: bool,
    /// Its place among the lanes of its side, outwards.
    rank: usize,
}

/// What one piece of a lane section is meshed from: the road (and its index in the map),
/// the section and the lanes chosen.
#[derive(Clone, Copy)]
struct Piece<'a> {
    index: usize,
    road: &'a Road,
    section: &'a LaneSection,
    lanes: &'a [LaneRef<'a>],
}

/// One evaluated point of the surface.
#[derive(Clone, Copy)]
struct Sample {
    p: [f64; 3],
    friction: f64,
    s: f64,
    t: f64,
}

/// The mesh being built, and what it is being built from.
struct Builder<'a> {
    surface: &'a Surface,
    probe: Probe,
    mesh: Mesh,
    friction: Vec<f32>,
    road_of: Vec<f32>,
    lane_of: Vec<f32>,
    s_of: Vec<f32>,
    t_of: Vec<f32>,
    budget: &'a Budget,
}

/// The surface of the map's chosen roads and lanes as one mesh (see the module's text).
/// Refused: an unknown road id, a bound that is not a positive number, a mesh beyond
/// `budget`.
pub fn map_mesh(surface: &Arc<Surface>, options: &MeshOptions, budget: &Budget) -> Result<Mesh> {
    if let Some(e) = options.max_error {
        if !(e > 0.0 && e.is_finite()) {
            return Err(Error::out_of_range(format!("the largest error must be a positive number of metres, not {e}")));
        }
    }
    let map = surface.map();
    let roads: Vec<usize> = match &options.roads {
        None => (0..map.roads.len()).collect(),
        Some(ids) => ids
            .iter()
            .map(|id| map.road_index(id).ok_or_else(|| Error::out_of_range(format!("no road '{id}' in the map"))))
            .collect::<Result<_>>()?,
    };
    let mut b = Builder {
        surface,
        probe: surface.probe(),
        mesh: Mesh::default(),
        friction: Vec::new(),
        road_of: Vec::new(),
        lane_of: Vec::new(),
        s_of: Vec::new(),
        t_of: Vec::new(),
        budget,
    };
    for i in roads {
        let road = &map.roads[i];
        for (k, section) in road.lanes.sections.iter().enumerate() {
            let end = road.lanes.sections.get(k + 1).map_or(road.length, |n| n.s).min(road.length);
            let start = section.s.max(0.0);
            if !(end - start > 1e-9) {
                continue;
            }
            let lanes = chosen_lanes(section, options);
            if !lanes.is_empty() {
                let piece = Piece { index: i, road, section, lanes: &lanes };
                b.section(piece, k, (start, end), options.max_error)?;
            }
        }
    }
    let Builder { mut mesh, friction, road_of, lane_of, s_of, t_of, .. } = b;
    mesh.normals = normals(&mesh);
    for (name, values) in [("friction", friction), ("road", road_of), ("lane", lane_of), ("s", s_of), ("t", t_of)] {
        mesh.values.push(VertexValues { name: name.into(), values });
    }
    Ok(mesh)
}

/// The lanes of `section` the options choose, left and right.
fn chosen_lanes<'a>(section: &'a LaneSection, options: &MeshOptions) -> Vec<LaneRef<'a>> {
    let wanted = |lane: &Lane| match &options.lane_types {
        None => lane.kind != "none",
        Some(types) => types.iter().any(|t| t == &lane.kind),
    };
    let side = |lanes: &'a [Lane], left: bool| {
        lanes.iter().enumerate().filter(move |(_, l)| wanted(l)).map(move |(rank, lane)| LaneRef { lane, left, rank })
    };
    side(&section.left, true).chain(side(&section.right, false)).collect()
}

/// The borders (inner, outer) of a lane at s.
fn borders(road: &Road, section: &LaneSection, lane: &LaneRef, s: f64) -> (f64, f64) {
    let ds = s - section.s;
    let span = section.spans(lane.left, ds, road.lanes.offset.at(s)).nth(lane.rank);
    span.map_or((0.0, 0.0), |sp| (sp.inner, sp.outer))
}

/// Where along [a, b] something starts anew: reference line records, CRG records, lane
/// widths and borders, heights, materials, the profiles' records.
fn breaks(surface: &Surface, index: usize, road: &Road, section: &LaneSection, (a, b): (f64, f64)) -> Vec<f64> {
    let mut at: Vec<f64> = vec![a, b];
    at.extend(road.plan.iter().map(|g| g.s));
    at.extend(surface.crg_bounds(index));
    for p in [&road.elevation, &road.superelevation, &road.lanes.offset] {
        at.extend(p.records().iter().map(|r| r.s));
    }
    at.extend(road.shape.iter().map(|g| g.s));
    for lane in section.left.iter().chain(&section.right) {
        at.extend(lane.width.iter().chain(&lane.border).map(|r| section.s + r.s));
        at.extend(lane.heights.iter().map(|h| section.s + h.s_offset));
        at.extend(lane.materials.iter().map(|m| section.s + m.s_offset));
    }
    at.retain(|s| s.is_finite() && *s >= a && *s <= b);
    at.sort_by(f64::total_cmp);
    at.dedup_by(|x, y| (*x - *y).abs() < 1e-9);
    at
}

impl Builder<'_> {
    /// Meshes the lanes of `piece`, the `k`th lane section of its road, over `range`.
    fn section(&mut self, piece: Piece, k: usize, range: (f64, f64), max_error: Option<f64>) -> Result<()> {
        let Piece { index, road, section, lanes } = piece;
        let first = self.mesh.triangles.len();
        let mut groups: Vec<Vec<[u32; 3]>> = vec![Vec::new(); lanes.len()];
        let cuts = breaks(self.surface, index, road, section, range);
        for cut in cuts.windows(2) {
            let (a, b) = (cut[0], cut[1]);
            let detail = self.surface.elevation_detail(index, 0.5 * (a + b));
            let tris = match detail {
                Some((du, dv)) => self.detail_piece(piece, (a, b), (du, dv), max_error)?,
                None => self.smooth_piece(piece, (a, b), max_error.unwrap_or(DEFAULT_ERROR))?,
            };
            for (g, t) in groups.iter_mut().zip(tris) {
                g.extend(t);
            }
        }
        let mut start = first;
        for (lane, tris) in lanes.iter().zip(groups) {
            let count = tris.len();
            self.mesh.triangles.extend(tris);
            let id = lane.lane.id;
            self.mesh.groups.push(MeshGroup {
                name: format!("road {} lane {id} section {k}", road.id),
                triangles: start..start + count,
                extras: format!(
                    r#""road":{},"lane":{id},"section":{k},"type":{}"#,
                    json_string(&road.id),
                    json_string(&lane.lane.kind)
                ),
            });
            start += count;
        }
        Ok(())
    }

    /// The sample at row s and column lambda of a lane of `piece`.
    fn sample(&mut self, piece: Piece, lane: &LaneRef, s: f64, l: f64) -> Sample {
        let (inner, outer) = borders(piece.road, piece.section, lane, s);
        let width = outer - inner;
        let inside = if width.abs() > 2.0 * INSIDE { INSIDE / width.abs() } else { 0.0 };
        let t = inner + width * l.clamp(inside, 1.0 - inside);
        match self.probe.ground_st(piece.index, s, t) {
            Some((x, y, g)) => {
                Sample { p: [x, y, g.z], friction: if g.friction.is_finite() { g.friction } else { -1.0 }, s, t }
            }
            None => Sample { p: [f64::NAN; 3], friction: -1.0, s, t },
        }
    }

    /// The rows and columns of a piece without CRG detail: rows halved until every lane's
    /// surface at the middle and the quarters of each row gap lies within `bound` / 2 of
    /// the chord; columns at the lane borders, halved the same way where a lateral shape
    /// bends the section.
    fn smooth_piece(&mut self, piece: Piece, (a, b): (f64, f64), bound: f64) -> Result<Vec<Vec<[u32; 3]>>> {
        let (road, lanes) = (piece.road, piece.lanes);
        let tolerance = 0.5 * bound;
        let probes =
            if road.shape.is_empty() { vec![0.0, 0.5, 1.0] } else { (0..=8).map(|k| k as f64 / 8.0).collect() };
        // Rows: a stack of gaps, halved while too coarse.
        let mut rows = vec![a];
        let mut todo = vec![(a, b)];
        while let Some((p, q)) = todo.pop() {
            let split = q - p > MAX_STEP
                || (q - p > MIN_STEP
                    && lanes.iter().any(|lane| {
                        probes.iter().any(|&l| {
                            let (sp, sq) = (self.sample(piece, lane, p, l), self.sample(piece, lane, q, l));
                            [0.25, 0.5, 0.75].iter().any(|&w| {
                                let m = self.sample(piece, lane, p + w * (q - p), l);
                                let chord = lerp(sp.p, sq.p, w);
                                distance(m.p, chord) > tolerance
                            })
                        })
                    }));
            if split {
                let m = 0.5 * (p + q);
                todo.push((m, q));
                todo.push((p, m));
            } else {
                rows.push(q);
            }
        }
        let mut columns = Vec::with_capacity(lanes.len());
        for lane in lanes {
            let mut cols = vec![0.0];
            let mut todo = vec![(0.0, 1.0)];
            while let Some((p, q)) = todo.pop() {
                let split = !road.shape.is_empty()
                    && q - p > 1.0 / 256.0
                    && [a, 0.5 * (a + b), b].iter().any(|&s| {
                        let (sp, sq) = (self.sample(piece, lane, s, p), self.sample(piece, lane, s, q));
                        let m = self.sample(piece, lane, s, 0.5 * (p + q));
                        distance(m.p, lerp(sp.p, sq.p, 0.5)) > tolerance
                    });
                if split {
                    let m = 0.5 * (p + q);
                    todo.push((m, q));
                    todo.push((p, m));
                } else {
                    cols.push(q);
                }
            }
            columns.push(cols);
        }
        let grid = self.samples(piece, &rows, &columns)?;
        Ok(self.emit(piece, &columns, grid))
    }

    /// The rows and columns of a piece where a CRG record lays detail: at the CRG grid's
    /// increments, thinned to `max_error` when one is given.
    fn detail_piece(
        &mut self,
        piece: Piece,
        (a, b): (f64, f64),
        (du, dv): (f64, f64),
        max_error: Option<f64>,
    ) -> Result<Vec<Vec<[u32; 3]>>> {
        let (road, section, lanes) = (piece.road, piece.section, piece.lanes);
        let n_rows = ((b - a) / du).ceil().max(1.0);
        let widths: Vec<f64> = lanes
            .iter()
            .map(|lane| {
                [a, 0.5 * (a + b), b]
                    .iter()
                    .map(|&s| {
                        let (i, o) = borders(road, section, lane, s);
                        (o - i).abs()
                    })
                    .fold(0.0, f64::max)
            })
            .collect();
        let n_cols: Vec<f64> = widths.iter().map(|w| (w / dv).ceil().max(1.0)).collect();
        let samples = (n_rows + 1.0) * n_cols.iter().map(|c| c + 1.0).sum::<f64>();
        let request = format!("the CRG detail of road '{}' from s = {a:.3} to {b:.3}", road.id);
        self.budget.admit(&request, samples, "samples", SAMPLE_BYTES + VERTEX_BYTES)?;
        let rows: Vec<f64> = (0..=n_rows as usize).map(|j| a + (b - a) * j as f64 / n_rows).collect();
        let columns: Vec<Vec<f64>> = n_cols.iter().map(|&n| (0..=n as usize).map(|m| m as f64 / n).collect()).collect();
        // Every sample of the full resolution, lane by lane, row by row.
        let grid = self.samples(piece, &rows, &columns)?;
        let Some(bound) = max_error else {
            return Ok(self.emit(piece, &columns, grid));
        };
        let points: Vec<Vec<[f64; 3]>> = grid.iter().map(|g| g.iter().map(|v| v.p).collect()).collect();
        let n_cols: Vec<usize> = columns.iter().map(Vec::len).collect();
        let (keep_rows, keep_cols) = thinned(&points, rows.len(), &n_cols, bound);
        // The samples of the rows and columns kept.
        let kept: Vec<Vec<Sample>> = grid
            .iter()
            .zip(&keep_cols)
            .map(|(g, cols)| {
                let nc = cols.len();
                g.iter().enumerate().filter(|(i, _)| keep_rows[i / nc] && cols[i % nc]).map(|(_, v)| *v).collect()
            })
            .collect();
        let columns: Vec<Vec<f64>> = columns
            .iter()
            .zip(&keep_cols)
            .map(|(c, k)| c.iter().zip(k).filter(|(_, &keep)| keep).map(|(&l, _)| l).collect())
            .collect();
        Ok(self.emit(piece, &columns, kept))
    }

    /// The samples at every row and column of each lane of `piece`, row by row; the
    /// piece's first and last rows evaluated just inside it, so that where a record starts
    /// or ends (a CRG record's heights, a lane's height) each piece takes its own side.
    /// Refused: more vertices than 32-bit indices or the budget allow.
    fn samples(&mut self, piece: Piece, rows: &[f64], columns: &[Vec<f64>]) -> Result<Vec<Vec<Sample>>> {
        let count: usize = columns.iter().map(|c| c.len() * rows.len()).sum();
        let total = self.mesh.positions.len() + count;
        if total > u32::MAX as usize {
            return Err(Error::out_of_range(format!(
                "a mesh of {total} vertices is more than 32-bit indices can hold"
            )));
        }
        self.budget.admit(&"the map's mesh", total as f64, "vertices", VERTEX_BYTES)?;
        let (a, b) = (rows[0], rows[rows.len() - 1]);
        let inside = |s: f64| if rows.len() < 2 { s } else { s.clamp(a + INSIDE, b - INSIDE) };
        let mut grid = Vec::with_capacity(piece.lanes.len());
        for (lane, cols) in piece.lanes.iter().zip(columns) {
            let mut g = Vec::with_capacity(rows.len() * cols.len());
            for &s in rows {
                for &l in cols {
                    g.push(self.sample(piece, lane, inside(s), l));
                }
            }
            grid.push(g);
        }
        Ok(grid)
    }

    /// The vertices of each lane's samples (row by row, `columns` of that lane a row) and
    /// two triangles per quad whose corners all have a height, counter-clockwise seen from
    /// above.
    fn emit(&mut self, piece: Piece, columns: &[Vec<f64>], grid: Vec<Vec<Sample>>) -> Vec<Vec<[u32; 3]>> {
        let mut out = Vec::with_capacity(piece.lanes.len());
        for ((lane, cols), samples) in piece.lanes.iter().zip(columns).zip(grid) {
            let first = self.mesh.positions.len();
            let nc = cols.len();
            for (i, v) in samples.iter().enumerate() {
                self.mesh.positions.push(v.p);
                self.mesh.texcoords.push([(v.s / piece.road.length.max(1e-9)) as f32, cols[i % nc] as f32]);
                self.friction.push(v.friction as f32);
                self.road_of.push(piece.index as f32);
                self.lane_of.push(lane.lane.id as f32);
                self.s_of.push(v.s as f32);
                self.t_of.push(v.t as f32);
            }
            let nr = samples.len() / nc.max(1);
            let id = |j: usize, m: usize| (first + j * nc + m) as u32;
            let ok = |i: u32| self.mesh.positions[i as usize].iter().all(|c| c.is_finite());
            let mut tris = Vec::new();
            for j in 0..nr.saturating_sub(1) {
                for m in 0..nc.saturating_sub(1) {
                    let (p00, p10, p11, p01) = (id(j, m), id(j + 1, m), id(j + 1, m + 1), id(j, m + 1));
                    if !(ok(p00) && ok(p10) && ok(p11) && ok(p01)) {
                        continue;
                    }
                    for t in [[p00, p10, p11], [p00, p11, p01]] {
                        tris.push(self.upward(t));
                    }
                }
            }
            out.push(tris);
        }
        out
    }

    /// The triangle with its corners counter-clockwise seen from above.
    fn upward(&self, [a, b, c]: [u32; 3]) -> [u32; 3] {
        let [pa, pb, pc] = [a, b, c].map(|i| self.mesh.positions[i as usize]);
        let turn = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
        if turn < 0.0 {
            [a, c, b]
        } else {
            [a, b, c]
        }
    }
}

/// Upward unit normals at the vertices: the area-weighted normals of the triangles
/// The rows (shared by the lanes) and each lane's columns that a mesh of `bound` keeps of
/// full-resolution samples: `lanes[l]` holds a lane's points row by row, `n_cols[l]` of
/// them a row, `n_rows` rows. The first and last row and column are kept; a quad of kept
/// rows and columns whose two triangles (split along its diagonal from its first row and
/// column) leave a finite sample farther than `bound` gets the middle row, the middle
/// column or both, as the surface bends along or across it, until none does.
fn thinned(lanes: &[Vec<[f64; 3]>], n_rows: usize, n_cols: &[usize], bound: f64) -> (Vec<bool>, Vec<Vec<bool>>) {
    let mut keep_rows = vec![false; n_rows];
    keep_rows[0] = true;
    keep_rows[n_rows - 1] = true;
    let mut keep_cols: Vec<Vec<bool>> = n_cols
        .iter()
        .map(|&n| {
            let mut k = vec![false; n];
            k[0] = true;
            k[n - 1] = true;
            k
        })
        .collect();
    loop {
        let kept_rows: Vec<usize> = (0..n_rows).filter(|&j| keep_rows[j]).collect();
        let mut changed = false;
        for (l, points) in lanes.iter().enumerate() {
            let nc = n_cols[l];
            let at = |j: usize, m: usize| points[j * nc + m];
            let kept_cols: Vec<usize> = (0..nc).filter(|&m| keep_cols[l][m]).collect();
            for r in kept_rows.windows(2) {
                for c in kept_cols.windows(2) {
                    let quad = (r[0], r[1], c[0], c[1]);
                    let Some((row, col)) = split_of(&at, quad, bound) else { continue };
                    let (r0, r1, c0, c1) = quad;
                    if row && r1 - r0 >= 2 && !keep_rows[(r0 + r1) / 2] {
                        keep_rows[(r0 + r1) / 2] = true;
                        changed = true;
                    }
                    if col && c1 - c0 >= 2 && !keep_cols[l][(c0 + c1) / 2] {
                        keep_cols[l][(c0 + c1) / 2] = true;
                        changed = true;
                    }
                }
            }
        }
        if !changed {
            return (keep_rows, keep_cols);
        }
    }
}

/// Whether the quad (rows r0..r1, columns c0..c1) of the points `at` gives needs a middle
/// row, a middle column (or both): `None` when its two triangles keep every finite sample
/// within `bound`. A way that cannot be halved any more passes to the other.
fn split_of(
    at: &impl Fn(usize, usize) -> [f64; 3],
    (r0, r1, c0, c1): (usize, usize, usize, usize),
    bound: f64,
) -> Option<(bool, bool)> {
    if r1 - r0 < 2 && c1 - c0 < 2 {
        return None;
    }
    let (p00, p10, p11, p01) = (at(r0, c0), at(r1, c0), at(r1, c1), at(r0, c1));
    let far = (r0..=r1).any(|j| {
        (c0..=c1).any(|m| {
            let (x, y) = ((j - r0) as f64 / (r1 - r0).max(1) as f64, (m - c0) as f64 / (c1 - c0).max(1) as f64);
            // The two triangles split the quad along (r0, c0)-(r1, c1).
            let on = if x >= y {
                add3(p00, add3(scale(sub(p10, p00), x - y), scale(sub(p11, p00), y)))
            } else {
                add3(p00, add3(scale(sub(p01, p00), y - x), scale(sub(p11, p00), x)))
            };
            !(distance(on, at(j, m)) <= bound) && at(j, m)[2].is_finite()
        })
    });
    if !far {
        return None;
    }
    // Which way the surface bends: samples off the straight line between the quad's sides
    // along s (at its first, middle and last column) call for a row; across (at its rows),
    // for a column.
    let worst = |it: &mut dyn Iterator<Item = f64>| it.filter(|e| e.is_finite()).fold(0.0, f64::max);
    let off_along = |m: usize| {
        (r0..=r1).map(move |j| {
            let w = (j - r0) as f64 / (r1 - r0).max(1) as f64;
            distance(at(j, m), lerp(at(r0, m), at(r1, m), w))
        })
    };
    let off_across = |j: usize| {
        (c0..=c1).map(move |m| {
            let w = (m - c0) as f64 / (c1 - c0).max(1) as f64;
            distance(at(j, m), lerp(at(j, c0), at(j, c1), w))
        })
    };
    let along = [c0, (c0 + c1) / 2, c1].iter().map(|&m| worst(&mut off_along(m))).fold(0.0, f64::max);
    let across = [r0, (r0 + r1) / 2, r1].iter().map(|&j| worst(&mut off_across(j))).fold(0.0, f64::max);
    let (mut row, mut col) = (along > 0.5 * bound, across > 0.5 * bound);
    if !row && !col {
        (row, col) = (true, true);
    }
    if row && r1 - r0 < 2 {
        col = true;
    }
    if col && c1 - c0 < 2 {
        row = true;
    }
    Some((row, col))
}

/// around each.
fn normals(mesh: &Mesh) -> Vec<[f32; 3]> {
    let mut sum = vec![[0.0f64; 3]; mesh.positions.len()];
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let n = cross(sub(b, a), sub(c, a));
        for &i in t {
            sum[i as usize] = add3(sum[i as usize], n);
        }
    }
    sum.iter()
        .map(|n| {
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            if len > 0.0 {
                [(n[0] / len) as f32, (n[1] / len) as f32, (n[2] / len) as f32]
            } else {
                [0.0, 0.0, 1.0]
            }
        })
        .collect()
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(a: [f64; 3], k: f64) -> [f64; 3] {
    [a[0] * k, a[1] * k, a[2] * k]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn lerp(a: [f64; 3], b: [f64; 3], w: f64) -> [f64; 3] {
    add3(a, scale(sub(b, a), w))
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    let d = sub(a, b);
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A lane's points on a regular grid of `n_rows` x `n_cols`, 0.1 m apart, height `z`.
    fn lane(n_rows: usize, n_cols: usize, z: impl Fn(f64, f64) -> f64) -> Vec<[f64; 3]> {
        let mut out = Vec::new();
        for j in 0..n_rows {
            for m in 0..n_cols {
                let (x, y) = (0.1 * j as f64, 0.1 * m as f64);
                out.push([x, y, z(x, y)]);
            }
        }
        out
    }

    /// Every sample lies within `bound` of the triangles of the kept quad around it.
    fn within_bound(points: &[[f64; 3]], rows: &[bool], cols: &[bool], bound: f64) -> bool {
        let nc = cols.len();
        let at = |j: usize, m: usize| points[j * nc + m];
        let kept = |k: &[bool]| -> Vec<usize> { (0..k.len()).filter(|&i| k[i]).collect() };
        let (kr, kc) = (kept(rows), kept(cols));
        kr.windows(2).all(|r| {
            kc.windows(2).all(|c| {
                let quad = (r[0], r[1], c[0], c[1]);
                split_of(&at, quad, bound).is_none() || (r[1] - r[0] < 2 && c[1] - c[0] < 2)
            })
        })
    }

    #[test]
    fn a_plane_keeps_its_corners_only() {
        let points = lane(33, 17, |x, y| 0.02 * x - 0.01 * y + 3.0);
        let (rows, cols) = thinned(&[points], 33, &[17], 0.001);
        assert_eq!(rows.iter().filter(|&&k| k).count(), 2);
        assert_eq!(cols[0].iter().filter(|&&k| k).count(), 2);
    }

    #[test]
    fn a_bump_keeps_what_the_bound_needs_and_no_more_than_the_samples() {
        let bump = |x: f64, y: f64| 0.05 * (-((x - 1.6).powi(2) + (y - 0.8).powi(2)) / 0.1).exp();
        let lanes = [lane(33, 17, bump), lane(33, 9, |_, _| 0.0)];
        for bound in [0.01, 0.002, 0.0005] {
            let (rows, cols) = thinned(&lanes, 33, &[17, 9], bound);
            for (l, points) in lanes.iter().enumerate() {
                assert!(within_bound(points, &rows, &cols[l], bound), "bound {bound}, lane {l}");
            }
            // The flat lane keeps its border columns only; the rows it shares follow the bump.
            assert_eq!(cols[1].iter().filter(|&&k| k).count(), 2);
            let kept = rows.iter().filter(|&&k| k).count();
            assert!(kept > 2 && kept < 33, "bound {bound}: {kept} rows");
        }
        // A tighter bound keeps at least as much.
        let count = |b: f64| thinned(&lanes, 33, &[17, 9], b).0.iter().filter(|&&k| k).count();
        assert!(count(0.0005) >= count(0.002) && count(0.002) >= count(0.01));
    }

    #[test]
    fn a_hole_in_the_samples_is_met_at_full_resolution() {
        // No height beyond x, y > 0.3: a quad with such a corner cannot say how far its
        // samples lie, and is halved down to single cells; the flat part away from it is not.
        let points = lane(17, 17, |x, y| if x > 1.05 && y > 1.05 { f64::NAN } else { 0.0 });
        let (rows, cols) = thinned(std::slice::from_ref(&points), 17, &[17], 0.001);
        assert!(within_bound(&points, &rows, &cols[0], 0.001));
        assert!(rows[10] && rows[11] && cols[0][10] && cols[0][11], "the hole's border at full resolution");
        assert!(!rows[2] && !cols[0][2], "the flat part far from it thinned");
    }
}
