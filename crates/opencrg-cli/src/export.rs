//! `opencrg export`: the surface as a mesh file (OBJ, STL, PLY, glTF, written by the core) or
//! as a texture over the u/v grid: a 16-bit height map, or with `--normal-map` an 8-bit
//! normal map (PNG).

use opencrg_core::{Budget, ContactPoint};
use opencrg_tools::mesh::{grid_mesh, Mesh};
use opencrg_tools::mesh_files::{write_mesh, write_whole, MeshFormat};
use opencrg_tools::simplify::{simplified_mesh, Stage};
use std::path::Path;

/// The u and v ranges of `export` and `view`.
#[derive(clap::Args)]
pub struct Ranges {
    /// Only the grid nodes with u in FROM:TO [m].
    #[arg(long, allow_hyphen_values = true)]
    u: Option<String>,
    /// Only the long sections with v in FROM:TO [m].
    #[arg(long, allow_hyphen_values = true)]
    v: Option<String>,
}

/// A u or v range, as (from, to) in m.
pub type Range = Option<(f64, f64)>;

impl Ranges {
    /// The u and v ranges given (`None` where not given).
    pub fn parse(&self) -> Result<(Range, Range), String> {
        Ok((parse_range(self.u.as_deref(), "u")?, parse_range(self.v.as_deref(), "v")?))
    }
}

/// A range given as `A:B`.
pub fn parse_range(text: Option<&str>, what: &str) -> Result<Range, String> {
    let Some(text) = text else { return Ok(None) };
    let bad = || format!("--{what} '{text}': expected FROM:TO in metres");
    let (a, b) = text.split_once(':').ok_or_else(bad)?;
    let (a, b): (f64, f64) = (a.trim().parse().map_err(|_| bad())?, b.trim().parse().map_err(|_| bad())?);
    if a.is_finite() && b.is_finite() {
        Ok(Some((a, b)))
    } else {
        Err(bad())
    }
}

/// What `export` writes, but the file.
pub struct Request {
    /// The u range (all of the road when `None`).
    pub u: Range,
    /// The v range (all of the road when `None`).
    pub v: Range,
    /// A normal map instead of a height map (PNG only).
    pub normal_map: bool,
    /// A simplified mesh within this bound (m) instead of the full one (meshes only).
    pub max_error: Option<f64>,
}

/// Writes the export `out` names by its extension.
pub fn export(cp: &ContactPoint, out: &Path, request: &Request, budget: &Budget) -> Result<String, String> {
    let &Request { u, v, normal_map, max_error } = request;
    let is_png = out.extension().and_then(|e| e.to_str()).is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if is_png {
        if max_error.is_some() {
            return Err("--max-error: only for a mesh (.obj, .stl, .ply or .glb)".into());
        }
        let mesh = grid_mesh(cp, u, v, budget).map_err(|e| e.to_string())?;
        let (nu, nv) = (mesh.u.len(), mesh.v.len());
        if normal_map {
            normal_png(cp, &mesh, nu, nv, out)?;
            return Ok(format!("{}: normal map of {nu} x {nv} grid nodes", out.display()));
        }
        let (lo, hi) = height_png(&mesh, nu, nv, out)?;
        return Ok(format!("{}: height map of {nu} x {nv} grid nodes, z {lo} to {hi} m", out.display()));
    }
    if normal_map {
        return Err("--normal-map: the output must be a .png file".into());
    }
    let format = MeshFormat::from_path(out)
        .ok_or_else(|| format!("{}: unknown export format; .obj, .stl, .ply, .glb or .png", out.display()))?;
    let mesh = match max_error {
        Some(bound) => simplified(cp, u, v, bound, budget)?,
        None => grid_mesh(cp, u, v, budget).map_err(|e| e.to_string())?,
    };
    write_mesh(&mesh, out, format).map_err(|e| e.to_string())?;
    Ok(format!("{}: {} vertices, {} triangles", out.display(), mesh.positions.len(), mesh.triangles.len()))
}

/// The simplified mesh, with a progress bar on a terminal.
fn simplified(cp: &ContactPoint, u: Range, v: Range, bound: f64, budget: &Budget) -> Result<Mesh, String> {
    let bar = indicatif::ProgressBar::new(1000);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{msg:10} {bar:40} {percent:>3} %")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let mesh = simplified_mesh(cp, u, v, bound, budget, &mut |stage| match stage {
        Stage::Sampling => bar.set_message("sampling"),
        Stage::Measuring(done) => {
            bar.set_message("measuring");
            bar.set_position((done * 1000.0) as u64);
        }
        Stage::Building => bar.set_message("building"),
    });
    bar.finish_and_clear();
    mesh.map_err(|e| e.to_string())
}

/// A PNG of `width` x `height` pixels with `channels`, `bits` deep, and text chunks,
/// written whole or not at all.
fn write_png(
    out: &Path,
    width: usize,
    height: usize,
    colour: png::ColorType,
    bits: png::BitDepth,
    texts: &[(&str, String)],
    data: &[u8],
) -> Result<(), String> {
    write_whole(out, |w| {
        let mut encoder = png::Encoder::new(w, width as u32, height as u32);
        encoder.set_color(colour);
        encoder.set_depth(bits);
        for (key, value) in texts {
            encoder.add_text_chunk(key.to_string(), value.clone())?;
        }
        let mut writer = encoder.write_header()?;
        writer.write_image_data(data)?;
        Ok(writer.finish()?)
    })
    .map_err(|e| e.to_string())
}

/// The pixel of node (i along u, j across): u runs left to right, v bottom to top (the
/// left side of the road at the top).
fn pixel(i: usize, j: usize, nu: usize, nv: usize) -> usize {
    (nv - 1 - j) * nu + i
}

/// The 16-bit height map: z from its smallest (0) to its largest value (65535) over the
/// nodes, 0 where there is none; the range is in the text chunks `z_min` and `z_max`.
fn height_png(mesh: &opencrg_tools::mesh::Mesh, nu: usize, nv: usize, out: &Path) -> Result<(f64, f64), String> {
    let z = |k: usize| mesh.positions[k][2];
    let (lo, hi) = (0..nu * nv)
        .map(z)
        .filter(|z| z.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), z| (a.min(z), b.max(z)));
    if !lo.is_finite() {
        return Err(format!("{}: no elevation in the range exported", out.display()));
    }
    let span = if hi > lo { hi - lo } else { 1.0 };
    let mut data = vec![0u8; nu * nv * 2];
    for i in 0..nu {
        for j in 0..nv {
            let value = z(i * nv + j);
            let level = if value.is_finite() { ((value - lo) / span * 65535.0).round() as u16 } else { 0 };
            let p = 2 * pixel(i, j, nu, nv);
            data[p..p + 2].copy_from_slice(&level.to_be_bytes());
        }
    }
    let texts = [
        ("z_min", format!("{lo:?}")),
        ("z_max", format!("{hi:?}")),
        ("Software", format!("opencrg {}", env!("CARGO_PKG_VERSION"))),
    ];
    write_png(out, nu, nv, png::ColorType::Grayscale, png::BitDepth::Sixteen, &texts, &data)?;
    Ok((lo, hi))
}

/// The normal map: each node's unit normal in the road's own frame (along u, across to
/// the left, up) as RGB = (n + 1) / 2 · 255, the convention of tangent-space normal maps.
fn normal_png(
    cp: &ContactPoint,
    mesh: &opencrg_tools::mesh::Mesh,
    nu: usize,
    nv: usize,
    out: &Path,
) -> Result<(), String> {
    let mut data = vec![0u8; nu * nv * 3];
    for i in 0..nu {
        for j in 0..nv {
            let k = i * nv + j;
            let n = mesh.normals[k].map(f64::from);
            // The heading of the road there turns x/y into along/across.
            let (phi, _) = cp.uv_to_pk(mesh.u[i], mesh.v[j]).unwrap_or((0.0, 0.0));
            let (s, c) = phi.sin_cos();
            let along = n[0] * c + n[1] * s;
            let across = -n[0] * s + n[1] * c;
            let rgb = [along, across, n[2]].map(|x| ((x.clamp(-1.0, 1.0) + 1.0) * 0.5 * 255.0).round() as u8);
            let p = 3 * pixel(i, j, nu, nv);
            data[p..p + 3].copy_from_slice(&rgb);
        }
    }
    write_png(
        out,
        nu,
        nv,
        png::ColorType::Rgb,
        png::BitDepth::Eight,
        &[("Software", format!("opencrg {}", env!("CARGO_PKG_VERSION")))],
        &data,
    )
}

/// `opencrg export`: a mesh of the road (or a part), or its reference line as GeoJSON.
pub(crate) fn run(
    road: &Path,
    output: &Path,
    request: &Request,
    options: &crate::eval_options::EvalOptions,
    budget: &Budget,
) -> Result<(), String> {
    let mut cp = crate::eval_options::contact_point(road, options)?;
    let is_geojson = output.extension().is_some_and(|e| e.eq_ignore_ascii_case("geojson"));
    let done = if is_geojson {
        if request.u.is_some() || request.v.is_some() || request.normal_map || request.max_error.is_some() {
            return Err(format!("{}: a .geojson export takes no ranges, --normal-map or --max-error", road.display()));
        }
        crate::geojson::write(&mut cp, output)
    } else {
        export(&cp, output, request, budget)
    };
    eprintln!("{}", done.map_err(|e| format!("{}: {e}", road.display()))?);
    Ok(())
}
