//! The map's mesh against the surface it stands for: every vertex on the ground the
//! probes give at its x/y, in every CRG mode; the bound kept where it is given; no gap
//! between neighbouring lanes and roads of real maps wider than the bound.

use opencrg_core::synth::RoadSpec;
use opencrg_core::Budget;
use opencrg_odr::Surface;
use opencrg_tools::map_mesh::{map_mesh, MeshOptions};
use opencrg_tools::mesh::Mesh;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

fn shared(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/opendrive").join(rel)
}

/// A fresh folder (tests running at once each get their own).
fn dir(name: &str) -> PathBuf {
    static MADE: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = MADE.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let d = std::env::temp_dir().join(format!("opencrg-map-mesh-{}-{k}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A CRG file 60 m x 5 m with bumps of a few millimetres, its reference line at
/// (x0, y0, phi0).
fn bumpy_crg(dir: &Path, start: (f64, f64, f64)) -> PathBuf {
    let spec = RoadSpec::straight(60.0, 5.0, 0.1, 0.1)
        .starting_at(start.0, start.1, start.2)
        .with_elevation(|u, v| 0.004 * (u * 2.1).sin() * (v * 1.7).cos() + 0.002 * (u * 7.3 + v).sin());
    let p = dir.join("bumps.crg");
    std::fs::write(&p, spec.to_crg()).unwrap();
    p
}

/// A road of a line, a spiral and an arc (the arc's start taken from the spiral's end),
/// climbing and superelevated, its lanes widening and offset, with `record` laid on.
fn map_with(dir: &Path, record: &str) -> Arc<Surface> {
    let spiral = opencrg_odr::Geometry {
        s: 30.0,
        x: 30.0,
        y: 0.0,
        hdg: 0.0,
        length: 40.0,
        shape: opencrg_odr::Shape::Spiral { start: 0.0, end: 0.02 },
    };
    let end = spiral.pose(40.0);
    let text = format!(
        r#"<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="r" length="120" junction="-1">
<planView>
<geometry s="0" x="0" y="0" hdg="0" length="30"><line/></geometry>
<geometry s="30" x="30" y="0" hdg="0" length="40"><spiral curvStart="0" curvEnd="0.02"/></geometry>
<geometry s="70" x="{}" y="{}" hdg="{}" length="50"><arc curvature="0.02"/></geometry>
</planView>
<elevationProfile><elevation s="0" a="1" b="0.03" c="0.0002" d="0"/></elevationProfile>
<lateralProfile><superelevation s="0" a="0.03" b="0" c="0" d="0"/></lateralProfile>
<lanes><laneOffset s="0" a="0.2" b="0" c="0" d="0"/><laneSection s="0">
<left><lane id="1" type="driving"><width sOffset="0" a="3.0" b="0.005" c="0" d="0"/><material sOffset="0" friction="0.8"/></lane></left>
<center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/><material sOffset="0" friction="0.6"/></lane>
<lane id="-2" type="sidewalk"><width sOffset="0" a="1.5" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes>
<surface>{record}</surface>
</road></OpenDRIVE>"#,
        end.x, end.y, end.hdg
    );
    let path = dir.join("map.xodr");
    std::fs::write(&path, text).unwrap();
    Arc::new(Surface::load(&path).unwrap())
}

/// The value `name` of the mesh at each vertex.
fn values<'a>(mesh: &'a Mesh, name: &str) -> &'a [f32] {
    &mesh.values.iter().find(|v| v.name == name).unwrap().values
}

/// The maps of every mode: the CRG laid on the road's s from 20 to 80.
fn maps_of_every_mode() -> Vec<(&'static str, Arc<Surface>)> {
    ["attached", "attached0", "genuine", "global"]
        .into_iter()
        .map(|mode| {
            let d = dir(mode);
            let crg = bumpy_crg(&d, if mode == "global" { (25.0, -1.0, 0.3) } else { (0.0, 0.0, 0.0) });
            let record = format!(
                r#"<CRG file="{}" sStart="20" sEnd="80" mode="{mode}" sOffset="20" tOffset="0.3" hOffset="0.1" zOffset="0.2"/>"#,
                crg.display()
            );
            (mode, map_with(&d, &record))
        })
        .collect()
}

#[test]
fn every_vertex_lies_on_the_ground_the_probes_give_in_every_mode() {
    for (mode, surface) in maps_of_every_mode() {
        for max_error in [None, Some(0.002)] {
            let options = MeshOptions { max_error, ..MeshOptions::default() };
            let mesh = map_mesh(&surface, &options, &Budget::machine()).unwrap();
            let mut probe = surface.probe();
            let (friction, lane) = (values(&mesh, "friction"), values(&mesh, "lane"));
            let (mut checked, mut worst) = (0, 0.0f64);
            for (i, p) in mesh.positions.iter().enumerate() {
                if !p[2].is_finite() {
                    continue;
                }
                let g = probe.ground(p[0], p[1]).unwrap_or_else(|| panic!("{mode}: vertex {i} {p:?} off the road"));
                let mut off = (g.z - p[2]).abs();
                // Where the record starts or ends the ground steps: a vertex there takes
                // the side of its own piece of the mesh.
                if (g.s - 20.0).abs() < 1e-6 || (g.s - 80.0).abs() < 1e-6 {
                    for ds in [-1e-6, 1e-6] {
                        let (_, _, side) = probe.ground_st(0, g.s + ds, g.t).unwrap();
                        off = off.min((side.z - p[2]).abs() - 1e-6);
                    }
                }
                worst = worst.max(off);
                // A vertex on a border between lanes belongs to its own lane.
                if g.lane == lane[i] as i32 {
                    let want = if g.friction.is_finite() { g.friction as f32 } else { -1.0 };
                    assert_eq!(want, friction[i], "{mode}: vertex {i}");
                }
                checked += 1;
            }
            assert!(worst < 1e-6, "{mode} {max_error:?}: {worst}");
            assert!(checked > 1000, "{mode}: {checked} vertices");
            // Three lanes of one section, each its group; every triangle faces up.
            assert_eq!(mesh.groups.len(), 3);
            for t in &mesh.triangles {
                let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
                assert!((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0.0, "{mode}");
            }
        }
    }
}

/// Triangles found by where they lie in x/y.
struct Locator<'a> {
    mesh: &'a Mesh,
    cells: HashMap<(i64, i64), Vec<u32>>,
    size: f64,
}

impl<'a> Locator<'a> {
    fn new(mesh: &'a Mesh, size: f64) -> Self {
        let mut cells: HashMap<(i64, i64), Vec<u32>> = HashMap::new();
        for (k, t) in mesh.triangles.iter().enumerate() {
            let ps = t.map(|i| mesh.positions[i as usize]);
            let (x0, x1) = (
                ps.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min),
                ps.iter().map(|p| p[0]).fold(f64::NEG_INFINITY, f64::max),
            );
            let (y0, y1) = (
                ps.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min),
                ps.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max),
            );
            for cx in (x0 / size).floor() as i64..=(x1 / size).floor() as i64 {
                for cy in (y0 / size).floor() as i64..=(y1 / size).floor() as i64 {
                    cells.entry((cx, cy)).or_default().push(k as u32);
                }
            }
        }
        Locator { mesh, cells, size }
    }

    /// The heights of the mesh's triangles over (x, y).
    fn heights(&self, x: f64, y: f64) -> Vec<f64> {
        let key = ((x / self.size).floor() as i64, (y / self.size).floor() as i64);
        let mut out = Vec::new();
        for &k in self.cells.get(&key).into_iter().flatten() {
            let [a, b, c] = self.mesh.triangles[k as usize].map(|i| self.mesh.positions[i as usize]);
            let det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
            let l1 = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det;
            let l2 = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
            if l1 >= -1e-9 && l2 >= -1e-9 && l1 + l2 <= 1.0 + 1e-9 {
                out.push(a[2] + l1 * (b[2] - a[2]) + l2 * (c[2] - a[2]));
            }
        }
        out
    }
}

#[test]
fn the_bound_holds_between_the_vertices() {
    // Points 2 cm apart along and across every lane: the mesh's height there against the
    // ground's. Away from CRG detail the bound holds everywhere; over the CRG grid it is
    // kept at samples of the grid's resolution, and between them the CRG surface's own
    // bending within a sample's spacing adds (here under a millimetre).
    for (mode, surface) in maps_of_every_mode() {
        for (max_error, allowed_detail, fewer) in [(0.005, 0.006, 10), (0.001, 0.002, 2)] {
            let options = MeshOptions { max_error: Some(max_error), ..MeshOptions::default() };
            let mesh = map_mesh(&surface, &options, &Budget::machine()).unwrap();
            let full = map_mesh(&surface, &MeshOptions::default(), &Budget::machine()).unwrap();
            let (kept, all) = (mesh.triangles.len(), full.triangles.len());
            assert!(kept * fewer < all, "{mode} {max_error}: {kept} of {all} triangles");
            let locator = Locator::new(&mesh, 2.0);
            let road = &surface.map().roads[0];
            let mut probe = surface.probe();
            let (mut smooth, mut detail, mut points) = (0.0f64, 0.0f64, 0);
            for i in 0..6000 {
                let s = 0.01 + i as f64 * 0.02;
                for k in 0..40 {
                    let t = -4.9 + k as f64 * 0.2 + 0.01;
                    let [x, y, _] = road.surface_point(s, t);
                    let Some(g) = probe.ground(x, y) else { continue };
                    if !g.z.is_finite() {
                        continue;
                    }
                    for h in locator.heights(x, y) {
                        let e = (h - g.z).abs();
                        if (20.0..=80.0).contains(&s) {
                            detail = detail.max(e);
                        } else {
                            smooth = smooth.max(e);
                        }
                        points += 1;
                    }
                }
            }
            assert!(points > 100_000, "{mode}: {points}");
            assert!(smooth <= max_error, "{mode} {max_error}: {smooth} away from the CRG");
            assert!(detail <= allowed_detail, "{mode} {max_error}: {detail} over the CRG");
        }
    }
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_maps_neighbouring_lanes_and_roads_meet_without_gaps() {
    // Every edge of the mesh's border on every shared map: a point 2 mm beyond its middle
    // lies on another triangle, off every lane the mesh holds (the edge of the drivable
    // area), or within the bound of a lane's border (a gap no wider than the bound).
    let mut maps: Vec<PathBuf> = ["carla", "esmini"]
        .iter()
        .flat_map(|d| std::fs::read_dir(shared(d)).unwrap().map(|e| e.unwrap().path()))
        .filter(|p| p.extension().is_some_and(|e| e == "xodr"))
        .collect();
    maps.sort();
    assert!(maps.len() >= 26, "{} maps", maps.len());
    for path in &maps {
        let map = path.display();
        let surface = Arc::new(Surface::load(path).unwrap());
        let mesh = map_mesh(&surface, &MeshOptions::default(), &Budget::machine()).unwrap();
        let locator = Locator::new(&mesh, 4.0);
        let mut uses: HashMap<(u32, u32), (u32, usize)> = HashMap::new();
        for t in &mesh.triangles {
            for e in 0..3 {
                let (a, b) = (t[e], t[(e + 1) % 3]);
                let key = (a.min(b), a.max(b));
                let entry = uses.entry(key).or_insert((t[(e + 2) % 3], 0));
                entry.1 += 1;
            }
        }
        let mut probe = surface.probe();
        let (mut borders, mut gaps) = (0, Vec::new());
        for (&(a, b), &(c, n)) in &uses {
            if n != 1 {
                continue;
            }
            borders += 1;
            let [pa, pb, pc] = [a, b, c].map(|i| mesh.positions[i as usize]);
            let (mx, my) = (0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]));
            let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
            let len = dx.hypot(dy);
            if len < 1e-6 {
                continue;
            }
            // The normal away from the triangle's third corner.
            let (mut nx, mut ny) = (-dy / len, dx / len);
            if nx * (pc[0] - mx) + ny * (pc[1] - my) > 0.0 {
                (nx, ny) = (-nx, -ny);
            }
            let (x, y) = (mx + 0.002 * nx, my + 0.002 * ny);
            if !locator.heights(x, y).is_empty() {
                continue;
            }
            if let Some(g) = probe.ground(x, y) {
                let lanes = &surface.map().roads[g.road].lanes;
                let lane = lanes.section_at(g.s).and_then(|(sec, ds)| sec.lane_at(ds, g.t, lanes.offset.at(g.s)));
                // Uncovered within the bound of a lane's border (the chords of a curved
                // border cut inside it by up to the bound) or of the road's ends (where
                // the map leaves a gap between two roads).
                let length = surface.map().roads[g.road].length;
                let inside =
                    lane.map_or(0.0, |l| (g.t - l.inner).abs().min((g.t - l.outer).abs()).min(g.s).min(length - g.s));
                if lane.is_some_and(|l| l.lane.kind != "none") && inside > opencrg_tools::map_mesh::DEFAULT_ERROR {
                    gaps.push((x, y, g.road, g.s, g.t));
                }
            }
        }
        assert!(borders >= 4, "{map}: {borders} border edges");
        assert!(
            gaps.is_empty(),
            "{map}: {} of {borders} border edges open onto a lane, first {:?}",
            gaps.len(),
            &gaps[..gaps.len().min(5)]
        );
    }
}
