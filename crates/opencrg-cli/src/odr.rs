//! `opencrg odr`: OpenDRIVE maps with CRG surfaces. `info` says what a map holds, `check`
//! applies the rules of its CRG records and roads, `eval` answers height, friction, road,
//! s and t at world points read from stdin, `render` draws the map's heights, `export`
//! writes the drivable surface as a mesh, `view` shows it in the browser.

use crate::files::number;
use clap::Subcommand;
use opencrg_core::Budget;
use opencrg_odr::{Map, Surface};
use opencrg_tools::map_mesh::{map_mesh, MeshOptions};
use opencrg_tools::mesh_files::{write_mesh, MeshFormat};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

/// The commands on OpenDRIVE maps.
#[derive(Subcommand)]
pub enum OdrCommand {
    /// What the map holds: roads, their length, junctions, CRG records per road, extent.
    Info {
        /// The OpenDRIVE map (.xodr).
        map: PathBuf,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// The rules of the CRG records and the roads: exit status 0 when clean, 1 with one line per finding.
    Check {
        /// The OpenDRIVE map (.xodr).
        map: PathBuf,
    },
    /// Read `x y` lines from stdin, print `z friction road s t` (`nan nan - nan nan` off every road).
    Eval {
        /// The OpenDRIVE map (.xodr).
        map: PathBuf,
    },
    /// A top view of the map's roads coloured by height, CRG records laid on, with a scale bar.
    Render {
        /// The OpenDRIVE map (.xodr).
        map: PathBuf,
        /// The PNG file to write.
        output: PathBuf,
        /// Pixels on the longer side of the picture (16 to 20000).
        #[arg(long, default_value_t = 1200)]
        size: usize,
    },
    /// The drivable surface as a mesh (.glb, .obj, .ply or .stl), CRG records laid on.
    Export {
        /// The OpenDRIVE map (.xodr).
        map: PathBuf,
        /// The file to write; its extension names the format.
        output: PathBuf,
        /// Only these roads (ids, comma-separated).
        #[arg(long, value_delimiter = ',', value_name = "ID,...")]
        roads: Option<Vec<String>>,
        /// Only lanes of these types (comma-separated; default every type but `none`).
        #[arg(long, value_delimiter = ',', value_name = "TYPE,...")]
        lanes: Option<Vec<String>>,
        /// Keep the mesh within this many metres of the surface's samples, CRG detail thinned
        /// (default: CRG detail at its grid's resolution, 1 mm elsewhere).
        #[arg(long, value_name = "METRES")]
        max_error: Option<f64>,
    },
    /// One self-contained HTML file showing the map in 3D (WebGL, works offline): CRG
    /// records outlined, click a point to read road, lane, s, t, height and friction.
    View {
        /// The OpenDRIVE map (.xodr).
        map: PathBuf,
        /// The HTML file to write.
        output: PathBuf,
        /// Only these roads (ids, comma-separated).
        #[arg(long, value_delimiter = ',', value_name = "ID,...")]
        roads: Option<Vec<String>>,
        /// The mesh's bound (m): CRG detail thinned to it.
        #[arg(long, value_name = "METRES", default_value_t = 0.005)]
        max_error: f64,
    },
}

fn load(path: &Path) -> Result<Map, String> {
    Map::load(path).map_err(|e| e.to_string())
}

fn info(map: &Map, json: bool) {
    let info = map.info();
    if json {
        println!("{}", info.to_json());
    } else {
        print!("{info}");
    }
}

fn eval(path: &Path) -> Result<(), String> {
    let surface = Arc::new(Surface::load(path).map_err(|e| e.to_string())?);
    let mut probe = surface.probe();
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let io = |e: std::io::Error| format!("stdout: {e}");
    crate::files::stdin_pairs(|x, y| match probe.ground(x, y) {
        Some(g) => {
            let road = &surface.map().roads[g.road].id;
            writeln!(out, "{} {} {road} {} {}", number(g.z), number(g.friction), number(g.s), number(g.t)).map_err(io)
        }
        None => writeln!(out, "nan nan - nan nan").map_err(io),
    })?;
    out.flush().map_err(io)
}

fn render(path: &Path, output: &Path, size: usize, budget: &Budget) -> Result<(), String> {
    if !(16..=crate::render::MAX_SIZE).contains(&size) {
        return Err(format!(
            "--size {size} px: the longer side of a picture takes 16 to {} px",
            crate::render::MAX_SIZE
        ));
    }
    let surface = Arc::new(Surface::load(path).map_err(|e| e.to_string())?);
    let e = surface.map().extent().ok_or_else(|| format!("{}: no road to draw", path.display()))?;
    let crate::render::RasterFrame { px, west: x0, north: y1, width: mw, height: mh } =
        crate::render::RasterFrame::around(e, size);
    let request = format!("a map picture of {mw} x {mh} px");
    budget.admit(&request, mw as f64 * mh as f64, "pixels", crate::render::PIXEL_BYTES).map_err(|e| e.to_string())?;
    let bar = indicatif::ProgressBar::new(mh as u64);
    let mut z = vec![None; mw * mh];
    let mut probe = surface.probe();
    for row in 0..mh {
        let y = y1 - (row as f64 + 0.5) * px;
        // Alternate the direction so each wheel of the scan stays on its road.
        let cols: Box<dyn Iterator<Item = usize>> =
            if row % 2 == 0 { Box::new(0..mw) } else { Box::new((0..mw).rev()) };
        for col in cols {
            let x = x0 + (col as f64 + 0.5) * px;
            z[row * mw + col] = probe.ground(x, y).map(|g| g.z);
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let raster = crate::render::Raster { z: &z, width: mw, height: mh, px, west: x0, north: y1 };
    crate::render::height_picture(&raster, &format!("{name}: elevation"))?.write(output)?;
    eprintln!("{}: {mw} x {mh} px, {px:.3} m a pixel", output.display());
    Ok(())
}

fn export(path: &Path, output: &Path, options: &MeshOptions, budget: &Budget) -> Result<(), String> {
    let format = MeshFormat::from_path(output).ok_or_else(|| {
        format!("{}: the output's extension names its format: .glb, .obj, .ply or .stl", output.display())
    })?;
    let surface = Arc::new(Surface::load(path).map_err(|e| e.to_string())?);
    let spinner = indicatif::ProgressBar::new_spinner().with_message("meshing the map");
    spinner.enable_steady_tick(std::time::Duration::from_millis(200));
    let mesh = map_mesh(&surface, options, budget);
    spinner.finish_and_clear();
    let mesh = mesh.map_err(|e| e.to_string())?;
    if mesh.triangles.is_empty() {
        return Err(format!("{}: no lane of the roads and types chosen to mesh", path.display()));
    }
    write_mesh(&mesh, output, format).map_err(|e| e.to_string())?;
    eprintln!(
        "{}: {} vertices, {} triangles, {} lanes of lane sections",
        output.display(),
        mesh.positions.len(),
        mesh.triangles.len(),
        mesh.groups.iter().filter(|g| !g.triangles.is_empty()).count()
    );
    Ok(())
}

fn view(path: &Path, output: &Path, options: &MeshOptions, budget: &Budget) -> Result<(), String> {
    let surface = Arc::new(Surface::load(path).map_err(|e| e.to_string())?);
    let name = path.file_name().map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
    let shown = opencrg_tools::view::map_view(&surface, &name, options, budget).map_err(|e| e.to_string())?;
    eprintln!("{}", crate::view::write(&shown, output)?);
    Ok(())
}

/// Runs an `odr` command; the exit status.
pub fn run(command: OdrCommand, budget: &Budget) -> Result<ExitCode, String> {
    match command {
        OdrCommand::Info { map, json } => info(&load(&map)?, json),
        OdrCommand::Check { map } => {
            let m = load(&map)?;
            let findings = opencrg_odr::check(&m);
            for f in &findings {
                println!("{}:{f}", map.display());
            }
            if !findings.is_empty() {
                eprintln!("{}: {} finding(s)", map.display(), findings.len());
                return Ok(ExitCode::from(1));
            }
            println!("{}: passes the checks", map.display());
        }
        OdrCommand::Eval { map } => eval(&map)?,
        OdrCommand::Render { map, output, size } => render(&map, &output, size, budget)?,
        OdrCommand::Export { map, output, roads, lanes, max_error } => {
            let options = MeshOptions { roads, lane_types: lanes, max_error };
            export(&map, &output, &options, budget)?
        }
        OdrCommand::View { map, output, roads, max_error } => {
            let options = MeshOptions { roads, lane_types: None, max_error: Some(max_error) };
            view(&map, &output, &options, budget)?
        }
    }
    Ok(ExitCode::SUCCESS)
}
