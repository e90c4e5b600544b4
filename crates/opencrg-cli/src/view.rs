//! `opencrg view`: one self-contained HTML file showing the road in 3D (WebGL 2, no
//! external script): the `.glb` export of the surface embedded in `viewer.html`, with the
//! reference line. Roads of more than `max_vertices` grid nodes are shown on every k-th
//! cross section.

use crate::export::Range;
use opencrg_core::{Budget, ContactPoint};
use opencrg_tools::mesh::grid_mesh_every;
use opencrg_tools::mesh_files::{write_mesh_to, write_whole, MeshFormat};
use std::io::Write;
use std::path::Path;

/// The viewer page; `__TITLE__`, `__INFO__`, `__GLB__`, `__LINES__` (polylines of x/y/z
/// points, null for a missing height) and `__NAMES__` (names of the mesh's values, as
/// `{"road": [ids]}`) are filled in.
const PAGE: &str = include_str!("viewer.html");

/// The viewer page of `mesh` with `lines` over it; `info` (HTML) heads it.
pub fn page(
    mesh: &opencrg_tools::mesh::Mesh,
    title: &str,
    info: &str,
    lines: &[Vec<[f64; 3]>],
    names: &str,
) -> Result<String, String> {
    let mut glb = Vec::new();
    write_mesh_to(mesh, &mut glb, MeshFormat::Glb).map_err(|e| e.to_string())?;
    let number = |x: f64| if x.is_finite() { format!("{x:?}") } else { "null".into() };
    let lines: Vec<String> = lines
        .iter()
        .map(|l| {
            let points: Vec<String> =
                l.iter().map(|p| format!("[{},{},{}]", number(p[0]), number(p[1]), number(p[2]))).collect();
            format!("[{}]", points.join(","))
        })
        .collect();
    Ok(PAGE
        .replace("__TITLE__", &escape(title))
        .replace("__INFO__", info)
        .replace("__LINES__", &format!("[{}]", lines.join(",")))
        .replace("__NAMES__", names)
        .replace("__GLB__", &base64(&glb)))
}

/// Standard base64 of `data`.
fn base64(data: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(data.len().div_ceil(3) * 4);
    for chunk in data.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * k) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// Text safe inside an HTML element.
pub fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// Writes the viewer of the surface `cp` evaluates (u and v ranges as `export`) to `out`.
pub fn view(
    cp: &ContactPoint,
    name: &str,
    out: &Path,
    u: Range,
    v: Range,
    max_vertices: usize,
    budget: &Budget,
) -> Result<String, String> {
    let road = cp.road();
    let nodes = road.grid().nu.saturating_mul(road.grid().nv);
    let step = nodes.div_ceil(max_vertices.max(1)).max(1);
    let mesh = grid_mesh_every(cp, u, v, step, budget).map_err(|e| e.to_string())?;
    // The reference line over the mesh's u range, at most 4000 points.
    let line = road.reference_line();
    let (u0, u1) = (mesh.u[0], mesh.u[mesh.u.len() - 1]);
    let inside: Vec<usize> = (0..line.n).filter(|&i| (u0..=u1).contains(&line.u_at(i))).collect();
    let points: Vec<[f64; 3]> = inside
        .iter()
        .step_by(inside.len().div_ceil(4000).max(1))
        .map(|&i| [line.x[i], line.y[i], line.z_at(i)])
        .collect();
    let info = format!(
        "{} &middot; u {u0:.2} to {u1:.2} m &middot; {} vertices, {} triangles{}",
        escape(name),
        mesh.positions.len(),
        mesh.triangles.len(),
        if step > 1 { format!(" (every {step}th cross section)") } else { String::new() }
    );
    let page = page(&mesh, name, &info, &[points], "{}")?;
    write_whole(out, |w| w.write_all(page.as_bytes())).map_err(|e| e.to_string())?;
    Ok(format!("{}: {} vertices, {} triangles", out.display(), mesh.positions.len(), mesh.triangles.len()))
}

#[cfg(test)]
mod tests {
    #[test]
    fn base64_as_the_standard_gives_it() {
        for (data, text) in
            [("", ""), ("f", "Zg=="), ("fo", "Zm8="), ("foo", "Zm9v"), ("foob", "Zm9vYg=="), ("foobar", "Zm9vYmFy")]
        {
            assert_eq!(super::base64(data.as_bytes()), text);
        }
    }
}
