//! The surface mesh: every vertex on the evaluated surface, the triangles of every cell
//! with data, ranges, and the files (OBJ, STL, PLY) as their formats define them.

use opencrg_core::synth::RoadSpec;
use opencrg_core::{Budget, ContactPoint};
use opencrg_tools::mesh::grid_mesh;
use opencrg_tools::mesh_files::{write_mesh, MeshFormat};
use std::sync::Arc;

/// A curved, sloped and banked road with uneven long sections and one NaN node.
fn road(with_nan: bool) -> ContactPoint {
    let spec = RoadSpec::straight(40.0, 4.0, 0.5, 1.0)
        .with_sections(vec![-2.0, -1.2, -0.3, 0.0, 0.9, 2.0])
        .starting_at(100.0, 50.0, 0.4)
        .with_heading(|u| 0.4 + 0.02 * u)
        .with_slope(|u| 0.03 * (u / 7.0).sin())
        .with_bank(|u| 0.02 - 0.001 * u)
        .with_elevation(move |u, v| {
            if with_nan && u == 20.0 && v == 0.0 {
                f64::NAN
            } else {
                0.01 * (u * 1.3).sin() * (v + 0.5).cos()
            }
        });
    ContactPoint::new(Arc::new(spec.build().unwrap()))
}

#[test]
fn every_vertex_lies_on_the_surface() {
    let cp = road(false);
    let mesh = grid_mesh(&cp, None, None, &Budget::machine()).unwrap();
    let r = cp.road().clone();
    let (nu, nv) = (r.grid().nu, r.grid().nv);
    assert_eq!(mesh.positions.len(), nu * nv);
    assert_eq!(mesh.triangles.len(), 2 * (nu - 1) * (nv - 1));
    // Vertex i * nv + j is node (u_i, v_j): x/y and z as the library evaluates them there.
    let (u0, du) = (r.u_range().0, r.increments().0);
    for i in 0..nu {
        for (j, &v) in r.grid().v.iter().enumerate() {
            let u = u0 + i as f64 * du;
            let (x, y) = cp.uv_to_xy(u, v).unwrap();
            let [px, py, pz] = mesh.positions[i * nv + j];
            assert_eq!((px, py, pz), (x, y, cp.uv_to_z(u, v).unwrap()), "node {i}, {j}");
            let n = mesh.normals[i * nv + j];
            let len = n.iter().map(|c| c * c).sum::<f32>().sqrt();
            assert!((len - 1.0).abs() < 1e-5 && n[2] > 0.9, "{n:?}");
        }
    }
    // Counter-clockwise seen from above: every triangle's normal points up.
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let up = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        assert!(up > 0.0, "{t:?}");
    }
}

/// On a straight road the way back from x/y is exact: each vertex's x/y finds its z.
#[test]
fn vertices_found_again_from_x_and_y() {
    let spec = RoadSpec::straight(30.0, 3.0, 0.25, 0.5)
        .starting_at(-20.0, 7.0, 1.1)
        .with_elevation(|u, v| 0.02 * (u * 0.9).cos() + 0.01 * v);
    let mut cp = ContactPoint::new(Arc::new(spec.build().unwrap()));
    let mesh = grid_mesh(&cp, None, None, &Budget::machine()).unwrap();
    for p in &mesh.positions {
        let z = cp.xy_to_z(p[0], p[1]).unwrap();
        assert!((z - p[2]).abs() < 1e-9, "{p:?}: the surface is at {z}");
    }
}

#[test]
fn ranges_and_gaps() {
    let cp = road(true);
    let all = grid_mesh(&cp, None, None, &Budget::machine()).unwrap();
    let (nu, nv) = (cp.road().grid().nu, cp.road().grid().nv);
    // The evaluation gives NaN at the nodes whose cell holds the NaN value (the node and
    // its three neighbours towards smaller u and v); the cells touching them are left out.
    let nan: Vec<usize> = (0..all.positions.len()).filter(|&i| all.positions[i][2].is_nan()).collect();
    assert_eq!(nan.len(), 4, "{nan:?}");
    assert_eq!(all.triangles.len(), 2 * (nu - 1) * (nv - 1) - 2 * 9);
    assert!(all.triangles.iter().flatten().all(|&i| !nan.contains(&(i as usize))));
    let part = grid_mesh(&cp, Some((10.0, 15.0)), Some((-0.5, 1.0)), &Budget::machine()).unwrap();
    // u 10..15 at 0.5 m: 11 nodes; v -0.3, 0, 0.9: 3 sections.
    assert_eq!(part.positions.len(), 11 * 3);
    assert_eq!(part.texcoords[0], [0.0, 0.0]);
    assert_eq!(*part.texcoords.last().unwrap(), [1.0, 1.0]);
    let e = grid_mesh(&cp, Some((50.0, 60.0)), None, &Budget::machine()).unwrap_err().to_string();
    assert!(e.contains("u 50:60") && e.contains("fewer than two"), "{e}");
}

#[test]
fn files_follow_their_formats() {
    let cp = road(true);
    let mesh = grid_mesh(&cp, None, None, &Budget::machine()).unwrap();
    let dir = scratch_dir("mesh");
    let (nvert, ntri) = (mesh.positions.len(), mesh.triangles.len());

    let stl = dir.join("road.stl");
    write_mesh(&mesh, &stl, MeshFormat::from_path(&stl).unwrap()).unwrap();
    let bytes = std::fs::read(&stl).unwrap();
    assert_eq!(bytes.len(), 84 + 50 * ntri);
    assert_eq!(u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize, ntri);
    let f32_at = |k: usize| f32::from_le_bytes(bytes[k..k + 4].try_into().unwrap());
    let first = mesh.positions[mesh.triangles[0][0] as usize];
    assert_eq!([f32_at(96), f32_at(100), f32_at(104)], first.map(|x| x as f32));

    let ply = dir.join("road.PLY");
    write_mesh(&mesh, &ply, MeshFormat::from_path(&ply).unwrap()).unwrap();
    let bytes = std::fs::read(&ply).unwrap();
    let end = bytes.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
    let header = String::from_utf8_lossy(&bytes[..end]);
    assert!(header.starts_with("ply\nformat binary_little_endian 1.0\n"), "{header}");
    assert!(
        header.contains(&format!("element vertex {nvert}\n")) && header.contains(&format!("element face {ntri}\n"))
    );
    assert_eq!(bytes.len(), end + nvert * (3 * 8 + 5 * 4) + ntri * (1 + 3 * 4));
    let x = f64::from_le_bytes(bytes[end..end + 8].try_into().unwrap());
    assert_eq!(x, mesh.positions[0][0]);

    let obj = dir.join("road.obj");
    write_mesh(&mesh, &obj, MeshFormat::Obj).unwrap();
    let text = std::fs::read_to_string(&obj).unwrap();
    let count = |prefix: &str| text.lines().filter(|l| l.starts_with(prefix)).count();
    assert_eq!((count("v "), count("vn "), count("vt "), count("f ")), (nvert, nvert, nvert, ntri));
    let v: Vec<f64> =
        text.lines().find(|l| l.starts_with("v ")).unwrap()[2..].split(' ').map(|s| s.parse().unwrap()).collect();
    assert_eq!(v, mesh.positions[0]);

    // A file that cannot be written leaves nothing behind.
    let bad = dir.join("no-such-folder").join("road.obj");
    assert!(write_mesh(&mesh, &bad, MeshFormat::Obj).is_err());
    assert!(MeshFormat::from_path(std::path::Path::new("road.gltf")).is_none());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The .glb reads back with the `gltf` crate (which validates it): y up, the node's
/// translation plus each single-precision position at the vertex, every index and
/// normal there.
#[test]
fn gltf_reads_back() {
    let cp = road(true);
    let mesh = grid_mesh(&cp, None, None, &Budget::machine()).unwrap();
    let dir = scratch_dir("glb");
    let path = dir.join("road.glb");
    write_mesh(&mesh, &path, MeshFormat::from_path(&path).unwrap()).unwrap();
    let (doc, buffers, _) = gltf::import(&path).unwrap();
    let node = doc.nodes().next().unwrap();
    let t = node.transform().decomposed().0;
    let primitive = node.mesh().unwrap().primitives().next().unwrap();
    let reader = primitive.reader(|b| Some(&buffers[b.index()]));
    let positions: Vec<[f32; 3]> = reader.read_positions().unwrap().collect();
    assert_eq!(positions.len(), mesh.positions.len());
    for (p, q) in mesh.positions.iter().zip(&positions) {
        if p.iter().all(|c| c.is_finite()) {
            let back = [f64::from(q[0] + t[0]), -f64::from(q[2] + t[2]), f64::from(q[1] + t[1])];
            // The translation is kept in single precision by the reader; the file holds it in double.
            assert!(p.iter().zip(back).all(|(a, b)| (a - b).abs() < 1e-4), "{p:?} read back as {back:?}");
        }
    }
    let indices: Vec<u32> = reader.read_indices().unwrap().into_u32().collect();
    assert_eq!(indices, mesh.triangles.iter().flatten().copied().collect::<Vec<_>>());
    let normals: Vec<[f32; 3]> = reader.read_normals().unwrap().collect();
    assert_eq!(normals[0], [mesh.normals[0][0], mesh.normals[0][2], -mesh.normals[0][1]]);
    assert_eq!(reader.read_tex_coords(0).unwrap().into_f32().count(), mesh.positions.len());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A folder of this test process for the files a test writes.
fn scratch_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("opencrg-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
