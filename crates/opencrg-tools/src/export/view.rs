//! The 3D view of a road or a map: one self-contained HTML page (WebGL 2, no external
//! script), the `.glb` of the surface embedded in `viewer.html` with lines over it (a
//! road's reference line, a map's CRG records outlined). The command writes it to a
//! file, the web page shows it in a frame.

use crate::export::map_mesh::{map_mesh, MeshOptions};
use crate::export::mesh::{grid_mesh_every, json_string, Mesh};
use crate::export::mesh_files::{write_mesh_to, MeshFormat};
use opencrg_core::units::Count;
use opencrg_core::{Budget, ContactPoint, Error, Result};
use opencrg_odr::Surface;
use std::sync::Arc;

/// The viewer page; `__TITLE__`, `__INFO__`, `__GLB__`, `__LINES__` (polylines of x/y/z
/// points, null for a missing height) and `__NAMES__` (names of the mesh's values, as
/// `{"road": [ids]}`) are filled in.
const PAGE: &str = include_str!("viewer.html");

/// A view: its page, and what it shows in numbers.
pub struct View {
    /// The HTML page.
    pub page: String,
    /// Vertices of the mesh.
    pub vertices: usize,
    /// Its triangles.
    pub triangles: usize,
}

/// The viewer page of `mesh` with `lines` over it; `info` (HTML) heads it.
fn page(mesh: &Mesh, title: &str, info: &str, lines: &[Vec<[f64; 3]>], names: &str) -> Result<View> {
    let mut glb = Vec::new();
    write_mesh_to(mesh, &mut glb, MeshFormat::Glb).map_err(|e| Error::out_of_range(format!("the view's mesh: {e}")))?;
    let number = |x: f64| if x.is_finite() { format!("{x:?}") } else { "null".into() };
    let lines: Vec<String> = lines
        .iter()
        .map(|l| {
            let points: Vec<String> =
                l.iter().map(|p| format!("[{},{},{}]", number(p[0]), number(p[1]), number(p[2]))).collect();
            format!("[{}]", points.join(","))
        })
        .collect();
    let page = PAGE
        .replace("__TITLE__", &escape(title))
        .replace("__INFO__", info)
        .replace("__LINES__", &format!("[{}]", lines.join(",")))
        .replace("__NAMES__", names)
        .replace("__GLB__", &base64(&glb));
    Ok(View { page, vertices: mesh.positions.len(), triangles: mesh.triangles.len() })
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
fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// The view of the surface `cp` evaluates, the road named `name`, over the u and v
/// ranges given (the whole road by default), on every k-th cross section where it has
/// more than `max_vertices` grid nodes; with its reference line.
pub fn road_view(
    cp: &ContactPoint,
    name: &str,
    u: Option<(f64, f64)>,
    v: Option<(f64, f64)>,
    max_vertices: usize,
    budget: &Budget,
) -> Result<View> {
    let road = cp.road();
    let nodes = road.grid().nu.saturating_mul(road.grid().nv);
    let step = nodes.div_ceil(max_vertices.max(1)).max(1);
    let mesh = grid_mesh_every(cp, u, v, step, budget)?;
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
    page(&mesh, name, &info, &[points], "{}")
}

/// The view of the map `surface` (named `name`) meshed with `options`, its CRG records
/// outlined; refused: no lane of the roads chosen to show.
pub fn map_view(surface: &Arc<Surface>, name: &str, options: &MeshOptions, budget: &Budget) -> Result<View> {
    let mesh = map_mesh(surface, options, budget)?;
    if mesh.triangles.is_empty() {
        return Err(Error::out_of_range(format!("{name}: no lane of the roads chosen to show")));
    }
    let chosen = |road: usize| options.roads.as_ref().is_none_or(|ids| ids.contains(&surface.map().roads[road].id));
    let outlines: Vec<Vec<[f64; 3]>> =
        surface.crg_outlines().into_iter().filter(|(road, ..)| chosen(*road)).map(|(_, _, line)| line).collect();
    let ids: Vec<String> = surface.map().roads.iter().map(|r| json_string(&r.id)).collect();
    let names = format!("{{\"road\": [{}]}}", ids.join(","));
    let info = format!(
        "{} &middot; {}, {} (outlined) &middot; {} vertices, {} triangles",
        escape(name),
        Count(surface.map().roads.len(), "road"),
        Count(outlines.len(), "CRG record"),
        mesh.positions.len(),
        mesh.triangles.len()
    );
    page(&mesh, name, &info, &outlines, &names)
}

#[cfg(test)]
mod tests {
    #[test]
    fn base64_as_the_standard_gives_it() {
        for (data, text) in
            [("", ""), ("f", "Zg=="), ("fo", "Zm8="), ("foob", "Zm9vYg=="), ("foo", "Zm9v"), ("foobar", "Zm9vYmFy")]
        {
            assert_eq!(super::base64(data.as_bytes()), text);
        }
    }

    #[test]
    fn names_are_json_strings() {
        assert_eq!(super::json_string("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
    }
}
