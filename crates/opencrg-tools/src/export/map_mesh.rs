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
                b.section(i, road, k, section, &lanes, (start, end), options.max_error)?;
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
    /// Meshes the lanes of one lane section over `range`.
    #[allow(clippy::too_many_arguments)]
    fn section(
        &mut self,
        index: usize,
        road: &Road,
        k: usize,
        section: &LaneSection,
        lanes: &[LaneRef],
        range: (f64, f64),
        max_error: Option<f64>,
    ) -> Result<()> {
        let first = self.mesh.triangles.len();
        let mut groups: Vec<Vec<[u32; 3]>> = vec![Vec::new(); lanes.len()];
        let cuts = breaks(self.surface, index, road, section, range);
        let piece = Piece { index, road, section, lanes };
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
        let mut keep_rows = vec![false; rows.len()];
        keep_rows[0] = true;
        keep_rows[rows.len() - 1] = true;
        let mut keep_cols: Vec<Vec<bool>> = columns
            .iter()
            .map(|c| {
                let mut k = vec![false; c.len()];
                k[0] = true;
                k[c.len() - 1] = true;
                k
            })
            .collect();
        loop {
            let kept_rows: Vec<usize> = (0..rows.len()).filter(|&j| keep_rows[j]).collect();
            let mut changed = false;
            for (l, g) in grid.iter().enumerate() {
                let nc = columns[l].len();
                let kept_cols: Vec<usize> = (0..nc).filter(|&m| keep_cols[l][m]).collect();
                for r in kept_rows.windows(2) {
                    for c in kept_cols.windows(2) {
                        let (r0, r1, c0, c1) = (r[0], r[1], c[0], c[1]);
                        if r1 - r0 < 2 && c1 - c0 < 2 {
                            continue;
                        }
                        let at = |j: usize, m: usize| g[j * nc + m].p;
                        let (p00, p10, p11, p01) = (at(r0, c0), at(r1, c0), at(r1, c1), at(r0, c1));
                        let far = (r0..=r1).any(|j| {
                            (c0..=c1).any(|m| {
                                let (x, y) = ((j - r0) as f64 / (r1 - r0) as f64, (m - c0) as f64 / (c1 - c0) as f64);
                                // The two triangles split the quad along (r0, c0)-(r1, c1).
                                let on = if x >= y {
                                    add3(p00, add3(scale(sub(p10, p00), x - y), scale(sub(p11, p00), y)))
                                } else {
                                    add3(p00, add3(scale(sub(p01, p00), y - x), scale(sub(p11, p00), x)))
                                };
                                !(distance(on, at(j, m)) <= bound) && at(j, m)[2].is_finite()
                            })
                        });
                        if far {
                            // Which way the surface bends: samples off the straight line
                            // between the quad's sides along s (at its first, middle and
                            // last column) call for a row; across (at its rows), for a column.
                            let off_along = |m: usize| {
                                (r0..=r1).map(move |j| {
                                    let w = (j - r0) as f64 / (r1 - r0) as f64;
                                    distance(at(j, m), lerp(at(r0, m), at(r1, m), w))
                                })
                            };
                            let off_across = |j: usize| {
                                (c0..=c1).map(move |m| {
                                    let w = (m - c0) as f64 / (c1 - c0).max(1) as f64;
                                    distance(at(j, m), lerp(at(j, c0), at(j, c1), w))
                                })
                            };
                            let worst =
                                |it: &mut dyn Iterator<Item = f64>| it.filter(|e| e.is_finite()).fold(0.0, f64::max);
                            let along =
                                [c0, (c0 + c1) / 2, c1].iter().map(|&m| worst(&mut off_along(m))).fold(0.0, f64::max);
                            let across =
                                [r0, (r0 + r1) / 2, r1].iter().map(|&j| worst(&mut off_across(j))).fold(0.0, f64::max);
                            let (mut row, mut col) = (along > 0.5 * bound, across > 0.5 * bound);
                            if !row && !col {
                                (row, col) = (true, true);
                            }
                            // A way that cannot be halved any more passes to the other.
                            if row && r1 - r0 < 2 {
                                col = true;
                            }
                            if col && c1 - c0 < 2 {
                                row = true;
                            }
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
            }
            if !changed {
                break;
            }
        }
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
