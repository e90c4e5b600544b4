//! `opencrg`: look into, check, convert, evaluate and render OpenCRG road files.
//!
//! ```text
//! opencrg info ROAD [--json] [--scan]
//! opencrg check ROAD
//! opencrg convert IN OUT --format KRBI|KDBI|LRFI|LDFI
//! opencrg eval ROAD [--xy] [options] < points
//! opencrg render ROAD OUT.png [--size PX] [--profile u=U|v=V]
//! opencrg roughness ROAD [--track V]... [--segment LENGTH] [--json] [--plot OUT.png]
//! opencrg export ROAD OUT.obj|.stl|.ply|.glb|.png [--u A:B] [--v C:D] [--normal-map] [--raw]
//! opencrg view ROAD OUT.html [--u A:B] [--v C:D] [--max-vertices N] [--raw]
//! opencrg cut IN OUT --u A:B [--v C:D]          opencrg flip IN OUT
//! opencrg append FIRST SECOND OUT                opencrg resample IN OUT [--u-inc DU] [--v-inc DV]
//! opencrg filter IN OUT --gauss SIGMA | --median N | --limit ZMIN:ZMAX | --fill-nan
//! opencrg slope|banking IN OUT --extract|--apply|--remove
//! opencrg generate OUT --refline LINE.csv --width W --u-inc DU --v-inc DV [--surface F]
//! opencrg import CLOUD OUT [--refline LINE.csv] [--width W] --u-inc DU --v-inc DV
//! opencrg compare A B [--tolerance T]
//! opencrg fmu ROAD OUT.fmu [--wheels N] [--fmi 2|3] [--binaries DIR]
//! opencrg odr info MAP [--json]                  opencrg odr check MAP
//! opencrg odr eval MAP < points                 opencrg odr render MAP OUT.png [--size PX]
//! opencrg odr export MAP OUT.glb [--roads ID,..] [--lanes TYPE,..] [--max-error M]
//! opencrg odr view MAP OUT.html [--roads ID,..] [--max-error M]
//! ```
//!
//! Bad input gives one line on stderr and exit status 2; a road that fails its checks
//! gives exit status 1 from `check`.

mod eval_options;
mod export;
mod expr;
mod files;
mod fmu;
mod geojson;
mod info;
mod make;
mod odr;
mod plot;
mod render;
mod roughness;
mod view;

use clap::{Parser, Subcommand};
use eval_options::{contact_point, EvalOptions};
use files::{load, stdin_pairs, Failure, Format};
use opencrg_core::{Budget, ContactPoint};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "opencrg",
    version,
    about = "Look into, check, convert, evaluate, render, export, cut, join, filter, generate and import OpenCRG road files"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// The most memory one command may use, like 8G, 512M or 2GiB (default: half of
    /// what the system has available); requests that would need more are refused.
    #[arg(long, global = true, value_name = "BYTES", value_parser = opencrg_core::parse_bytes, allow_hyphen_values = true)]
    max_memory: Option<u64>,
}

#[derive(Subcommand)]
enum Command {
    /// What the file holds: format, channels, size, u/v ranges, reference line, elevation range, settings.
    Info {
        /// The road file.
        road: PathBuf,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Read a grid read in place whole, for its elevation range and NaN cells.
        #[arg(long)]
        scan: bool,
    },
    /// The library's checks (options, modifiers, curvature against width): exit status 0 or 1.
    Check {
        /// The road file.
        road: PathBuf,
    },
    /// Write the road in another data format, header sections kept.
    Convert {
        /// The road file to read.
        input: PathBuf,
        /// The file to write.
        output: PathBuf,
        /// The data format of the output (in any case).
        #[arg(long, value_enum, ignore_case = true)]
        format: Format,
    },
    /// Read `u v` lines (or `x y` with --xy) from stdin, print CSV with z, x/y or u/v, heading and curvature.
    Eval {
        /// The road file.
        road: PathBuf,
        /// The input lines hold x y instead of u v.
        #[arg(long)]
        xy: bool,
        #[command(flatten)]
        options: EvalOptions,
    },
    /// A picture of the road: a top view coloured by elevation, or a section as a line plot.
    Render {
        /// The road file.
        road: PathBuf,
        /// The PNG file to write.
        output: PathBuf,
        /// Pixels on the longer side of the map (16 to 20000).
        #[arg(long, default_value_t = 1200)]
        size: usize,
        /// Draw a section instead: `u=12.5` across the road, `v=0.5` along it.
        #[arg(long)]
        profile: Option<String>,
        #[command(flatten)]
        options: EvalOptions,
    },
    /// The surface for 3D tools: a mesh at the grid nodes or simplified (.obj, .stl, .ply, .glb), a height or normal map (.png), or the reference line and outline in WGS 84 (.geojson).
    Export {
        /// The road file (checked and its modifiers applied unless --raw, as `eval` does).
        road: PathBuf,
        /// The file to write; its extension names the format.
        output: PathBuf,
        #[command(flatten)]
        ranges: export::Ranges,
        /// With a .png output: a normal map instead of a height map.
        #[arg(long)]
        normal_map: bool,
        /// A simplified mesh whose z stays within this many metres of the road's at every grid node.
        #[arg(long, value_name = "METRES")]
        max_error: Option<f64>,
        #[command(flatten)]
        options: EvalOptions,
    },
    /// One self-contained HTML file showing the road in 3D (WebGL, works offline).
    View {
        /// The road file (checked and its modifiers applied unless --raw).
        road: PathBuf,
        /// The HTML file to write.
        output: PathBuf,
        #[command(flatten)]
        ranges: export::Ranges,
        /// Largest number of grid nodes shown (more: every k-th cross section).
        #[arg(long, default_value_t = 1_000_000)]
        max_vertices: usize,
        #[command(flatten)]
        options: EvalOptions,
    },
    /// How rough the road is along wheel tracks: IRI (ASTM E1926) over each track and per segment, ISO 8608 PSD class.
    Roughness {
        /// The road file (checked and its modifiers applied, as the C API's programs do).
        road: PathBuf,
        /// v of a track [m]; repeat for more (default: -0.85, 0 and 0.85).
        #[arg(long = "track", allow_negative_numbers = true)]
        tracks: Vec<f64>,
        /// Length of the IRI's segments [m].
        #[arg(long, default_value_t = opencrg_tools::roughness::DEFAULT_SEGMENT)]
        segment: f64,
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
        /// Also draw the densities among the class bands and the IRI along u into this PNG.
        #[arg(long)]
        plot: Option<PathBuf>,
    },
    /// Pack the road (a CRG file, or a map with its CRG files) as an FMU (FMI 2 or 3, model exchange and co-simulation) answering height, normal and friction under each wheel.
    Fmu(fmu::FmuArgs),
    #[command(flatten)]
    Make(make::MakeCommand),
    /// OpenDRIVE maps with CRG surfaces: info, check, eval, render, export, view.
    #[command(subcommand)]
    Odr(odr::OdrCommand),
}

fn number(v: Option<f64>) -> String {
    files::number(v.unwrap_or(f64::NAN))
}

/// Reads point lines from stdin and writes the CSV.
fn eval(cp: &mut ContactPoint, xy: bool) -> Result<(), Failure> {
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let io = |e: std::io::Error| format!("stdout: {e}");
    writeln!(out, "{}", if xy { "x,y,u,v,z,phi,curv" } else { "u,v,x,y,z,phi,curv" }).map_err(io)?;
    stdin_pairs(|a, b| {
        let (u, v, x, y) = if xy {
            let (u, v) = cp.xy_to_uv(a, b).map_or((None, None), |(u, v)| (Some(u), Some(v)));
            (u, v, Some(a), Some(b))
        } else {
            let (x, y) = cp.uv_to_xy(a, b).map_or((None, None), |(x, y)| (Some(x), Some(y)));
            (Some(a), Some(b), x, y)
        };
        let (z, pk) = if xy {
            (cp.xy_to_z(a, b).ok(), cp.xy_to_pk(a, b).ok())
        } else {
            (cp.uv_to_z(a, b).ok(), cp.uv_to_pk(a, b).ok())
        };
        let fields = if xy { [x, y, u, v] } else { [u, v, x, y] };
        let row: Vec<String> = fields.into_iter().chain([z, pk.map(|p| p.0), pk.map(|p| p.1)]).map(number).collect();
        writeln!(out, "{}", row.join(",")).map_err(io)
    })?;
    out.flush().map_err(io)
}

/// Runs the command the line names.
fn run(cli: Cli) -> Result<ExitCode, Failure> {
    let budget = match cli.max_memory {
        Some(bytes) => Budget::with_bytes(bytes),
        None => Budget::machine(),
    }
    .raised_with("--max-memory");
    match cli.command {
        Command::Info { road, json, scan } => info::run(&road, json, scan)?,
        Command::Check { road } => return check(&road),
        Command::Convert { input, output, format } => {
            opencrg_core::write(&load(&input)?, &output, format.into()).map_err(|e| e.to_string())?
        }
        Command::Eval { road, xy, options } => eval(&mut contact_point(&road, &options)?, xy)?,
        Command::Render { road, output, size, profile, options } => {
            render::run(&road, &output, size, profile.as_deref(), &options, &budget)?
        }
        Command::Export { road, output, ranges, normal_map, max_error, options } => {
            let (u, v) = ranges.parse()?;
            export::run(&road, &output, &export::Request { u, v, normal_map, max_error }, &options, &budget)?
        }
        Command::View { road, output, ranges, max_vertices, options } => {
            view::run(&road, &output, ranges.parse()?, max_vertices, &options, &budget)?
        }
        Command::Roughness { road, tracks, segment, json, plot } => {
            roughness::run(&road, tracks, segment, json, plot.as_deref())?
        }
        Command::Fmu(args) => fmu::run(args)?,
        Command::Make(command) => return make::run(command, &budget),
        Command::Odr(command) => return odr::run(command, &budget),
    }
    Ok(ExitCode::SUCCESS)
}

/// `opencrg check`: the map's disagreements as warnings, then the check; exit status 1
/// where it fails.
fn check(road: &Path) -> Result<ExitCode, Failure> {
    let mut r = load(road)?;
    for sentence in opencrg_core::map_disagreements(&r) {
        eprintln!("opencrg: warning: {}: {sentence}", road.display());
    }
    Ok(match r.check() {
        Ok(()) => {
            println!("{}: passes the checks", road.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{}: {e}", road.display());
            ExitCode::from(1)
        }
    })
}

/// The command line, every value that looks like a negative number taken as one (so
/// that `--u-inc -1` reaches the command's own checks), in every subcommand.
fn parse_arguments() -> Cli {
    use clap::{CommandFactory, FromArgMatches};
    fn negatives(command: clap::Command) -> clap::Command {
        command
            .mut_args(|a| if a.get_action().takes_values() { a.allow_negative_numbers(true) } else { a })
            .mut_subcommands(negatives)
    }
    let matches = negatives(Cli::command()).get_matches();
    Cli::from_arg_matches(&matches).unwrap_or_else(|e| e.exit())
}

fn main() -> ExitCode {
    // A bug must still end in one line, not a panic trace.
    std::panic::set_hook(Box::new(|info| {
        let payload = info.payload();
        let what = payload
            .downcast_ref::<&str>()
            .copied()
            .or_else(|| payload.downcast_ref::<String>().map(String::as_str))
            .unwrap_or("unexpected state");
        eprintln!("opencrg: internal error: {what}");
    }));
    let cli = parse_arguments();
    match std::panic::catch_unwind(|| run(cli)) {
        Ok(Ok(code)) => code,
        Ok(Err(message)) => {
            eprintln!("opencrg: {message}");
            ExitCode::from(2)
        }
        Err(_) => ExitCode::from(2),
    }
}
