//! The commands that make roads: cut, flip, append, resample, filter, slope, banking,
//! generate, import; and compare. Each reads its roads as stored (modifiers kept in the
//! header, not applied), writes its result all or nothing, and says what it wrote.

use crate::export::parse_range;
use crate::expr;
use crate::files::{load, Format};
use clap::{ArgGroup, Args, Subcommand};
use opencrg_core::units::Metres;
use opencrg_core::{Budget, ContactPoint, DataFormat, Road};
use opencrg_tools::{self as tools, ChannelAction, Filter, Import, Layout, LineChannel};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The commands that make and compare roads.
#[derive(Subcommand)]
pub enum MakeCommand {
    /// The part of a road between two u (and v), at the grid nodes inside, left where it was.
    Cut {
        /// The road file to read.
        input: PathBuf,
        /// The file to write.
        output: PathBuf,
        /// Keep the cross sections with u in FROM:TO [m].
        #[arg(long, allow_hyphen_values = true)]
        u: String,
        /// Keep the long sections with v in FROM:TO [m].
        #[arg(long, allow_hyphen_values = true)]
        v: Option<String>,
        #[command(flatten)]
        format: OutputFormat,
    },
    /// The same road driven the other way (u reversed, v mirrored), the surface where it was.
    Flip {
        /// The road file to read.
        input: PathBuf,
        /// The file to write.
        output: PathBuf,
        #[command(flatten)]
        format: OutputFormat,
    },
    /// SECOND continuing FIRST from its end point, heading and height (resampled to FIRST's grid where they differ).
    Append {
        /// The road that comes first.
        first: PathBuf,
        /// The road that continues it.
        second: PathBuf,
        /// The file to write.
        output: PathBuf,
        #[command(flatten)]
        format: OutputFormat,
    },
    /// The surface on a new grid, each node evaluated by the library.
    Resample {
        /// The road file to read.
        input: PathBuf,
        /// The file to write.
        output: PathBuf,
        /// Distance between cross sections [m] (default: the road's).
        #[arg(long)]
        u_inc: Option<f64>,
        /// Distance between long sections [m] (default: the road's long sections).
        #[arg(long)]
        v_inc: Option<f64>,
        #[command(flatten)]
        format: OutputFormat,
    },
    /// Filter the elevation grid: Gaussian, median, limits, or NaN filled.
    #[command(group(ArgGroup::new("filter").required(true).args(["gauss", "median", "limit", "fill_nan"])))]
    Filter {
        /// The road file to read.
        input: PathBuf,
        /// The file to write.
        output: PathBuf,
        /// A Gaussian of this standard deviation [m].
        #[arg(long, value_name = "SIGMA")]
        gauss: Option<f64>,
        /// The median of N x N nodes (N odd).
        #[arg(long, value_name = "N")]
        median: Option<i64>,
        /// Grid values limited to ZMIN:ZMAX [m].
        #[arg(long, value_name = "ZMIN:ZMAX", allow_hyphen_values = true)]
        limit: Option<String>,
        /// NaN nodes filled from their neighbours.
        #[arg(long)]
        fill_nan: bool,
        #[command(flatten)]
        format: OutputFormat,
    },
    /// Move the slope between the reference line and the grid, or remove it.
    Slope(ChannelArgs),
    /// Move the banking between the reference line and the grid, or remove it.
    Banking(ChannelArgs),
    /// A road along a smooth line through the x,y points of a CSV (a z column gives the slope).
    Generate {
        /// The file to write.
        output: PathBuf,
        /// The reference line's points: CSV or XYZ with x, y (and z).
        #[arg(long)]
        refline: PathBuf,
        #[command(flatten)]
        grid: GridArgs,
        /// The road's width [m], centred on the line.
        #[arg(long)]
        width: f64,
        /// The grid: a formula of u and v (like "0.01*sin(u)"), or a road file whose surface is taken at the same u/v.
        #[arg(long, value_name = "FUNCTION_OR_CRG", allow_hyphen_values = true)]
        surface: Option<String>,
        #[command(flatten)]
        format: OutputFormat,
    },
    /// A road from a point cloud (CSV/XYZ, PLY, LAS/LAZ) gridded along a reference line.
    Import {
        /// The points: .csv/.xyz/.txt, .ply, .las or .laz.
        cloud: PathBuf,
        /// The file to write.
        output: PathBuf,
        /// The reference line's points (default: a line fitted through the cloud).
        #[arg(long)]
        refline: Option<PathBuf>,
        /// The road's width [m] (default: as far as the cloud reaches on both sides).
        #[arg(long)]
        width: Option<f64>,
        #[command(flatten)]
        grid: GridArgs,
        /// Nodes in triangles with a longer edge [m] are NaN (default: 5 increments, at least 0.5 m).
        #[arg(long)]
        max_edge: Option<f64>,
        /// Fill the nodes without points from their neighbours.
        #[arg(long)]
        fill_nan: bool,
        /// Use only the points within X0:X1,Y0:Y1 [m] (to leave out stray points).
        #[arg(long, value_name = "X0:X1,Y0:Y1", allow_hyphen_values = true)]
        crop: Option<String>,
        #[command(flatten)]
        format: OutputFormat,
    },
    /// The largest difference between two surfaces at the same x/y (at A's grid nodes), and where.
    Compare {
        /// The road whose grid nodes are compared.
        a: PathBuf,
        /// The road compared with it.
        b: PathBuf,
        /// Exit with status 1 when the largest difference exceeds this [m].
        #[arg(long)]
        tolerance: Option<f64>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
}

/// The data format of the output.
#[derive(Args)]
pub struct OutputFormat {
    /// The data format of the output (default: the input's; KDBI for new roads).
    #[arg(long, value_enum, ignore_case = true)]
    format: Option<Format>,
}

/// The increments of a new grid.
#[derive(Args)]
pub struct GridArgs {
    /// Distance between cross sections [m].
    #[arg(long)]
    u_inc: f64,
    /// Distance between long sections [m].
    #[arg(long)]
    v_inc: f64,
}

/// The arguments of `slope` and `banking`.
#[derive(Args)]
pub struct ChannelArgs {
    /// The road file to read.
    input: PathBuf,
    /// The file to write.
    output: PathBuf,
    #[command(flatten)]
    action: Action,
    #[command(flatten)]
    format: OutputFormat,
}

/// What to do with a reference line channel.
#[derive(Args)]
#[group(required = true, multiple = false)]
pub struct Action {
    /// Find it in the grid and move it to the reference line (the surface stays).
    #[arg(long)]
    extract: bool,
    /// Fold it into the grid and drop it from the reference line (the surface stays).
    #[arg(long)]
    apply: bool,
    /// Drop it (the surface loses it).
    #[arg(long)]
    remove: bool,
}

impl Action {
    fn which(&self) -> ChannelAction {
        if self.extract {
            ChannelAction::Extract
        } else if self.apply {
            ChannelAction::Apply
        } else {
            ChannelAction::Remove
        }
    }
}

/// An area given as `X0:X1,Y0:Y1`.
fn parse_crop(text: &str) -> Result<[(f64, f64); 2], String> {
    let bad = || format!("--crop '{text}': expected X0:X1,Y0:Y1 in metres");
    let (x, y) = text.split_once(',').ok_or_else(bad)?;
    let x = parse_range(Some(x), "crop")?.ok_or_else(bad)?;
    let y = parse_range(Some(y), "crop")?.ok_or_else(bad)?;
    Ok([x, y])
}

fn data_format(f: Option<Format>, default: DataFormat) -> DataFormat {
    f.map_or(default, DataFormat::from)
}

/// Writes the road and says so.
fn save(road: &Road, out: &Path, format: DataFormat) -> Result<(), String> {
    opencrg_core::write(road, out, format).map_err(|e| e.to_string())?;
    let (nu, nv) = (road.grid().nu, road.grid().nv);
    let ((u0, u1), (v0, v1)) = (road.u_range(), road.v_range());
    eprintln!(
        "wrote {} ({}): {nu} x {nv} nodes, u {} to {} m, v {} to {} m",
        out.display(),
        format.name(),
        Metres(u0),
        Metres(u1),
        Metres(v0),
        Metres(v1)
    );
    Ok(())
}

/// Reads `input`, makes a road from it with `make`, and writes that to `output` (in the
/// input's format unless `format` names another).
fn remake(
    input: &Path,
    output: &Path,
    format: &OutputFormat,
    make: impl FnOnce(&Arc<Road>) -> opencrg_core::Result<Road>,
) -> Result<(), String> {
    let road = Arc::new(load(input)?);
    let made = make(&road).map_err(named(input))?;
    save(&made, output, data_format(format.format, road.format()))
}

/// `slope` or `banking`.
fn channel(a: ChannelArgs, which: LineChannel) -> Result<(), String> {
    let action = a.action.which();
    remake(&a.input, &a.output, &a.format, |road| tools::change_channel(road, which, action))
}

/// A progress bar on a terminal (hidden elsewhere) for long work.
fn progress_bar() -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(0);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{msg:>13} {bar:40} {percent:>3}%  {elapsed}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    bar
}

/// A tool's refusal as one line naming the file it was about.
fn named(path: &Path) -> impl Fn(opencrg_core::Error) -> String + '_ {
    move |e| format!("{}: {e}", path.display())
}

/// Runs a command that makes or compares roads; the exit status.
pub fn run(command: MakeCommand, budget: &Budget) -> Result<std::process::ExitCode, String> {
    match command {
        MakeCommand::Cut { input, output, u, v, format } => {
            let u = parse_range(Some(&u), "u")?.ok_or("--u: expected FROM:TO")?;
            let v = parse_range(v.as_deref(), "v")?;
            remake(&input, &output, &format, |road| tools::cut(road, u, v))?;
        }
        MakeCommand::Flip { input, output, format } => remake(&input, &output, &format, |road| tools::flip(road))?,
        MakeCommand::Append { first, second, output, format } => {
            let a = load(&first)?;
            let b = Arc::new(load(&second)?);
            let made = tools::append(&a, &b, budget)
                .map_err(|e| format!("{} + {}: {e}", first.display(), second.display()))?;
            save(&made, &output, data_format(format.format, a.format()))?;
        }
        MakeCommand::Resample { input, output, u_inc, v_inc, format } => {
            remake(&input, &output, &format, |road| tools::resample(road, u_inc, v_inc, budget))?;
        }
        MakeCommand::Filter { input, output, gauss, median, limit, fill_nan, format } => {
            let filter = match (gauss, median, limit, fill_nan) {
                (Some(s), ..) => Filter::Gauss(s),
                (_, Some(n), ..) => Filter::Median(
                    usize::try_from(n).map_err(|_| format!("--median {n}: the window takes an odd number of nodes"))?,
                ),
                (_, _, Some(text), _) => {
                    let (a, b) = parse_range(Some(&text), "limit")?.ok_or("--limit: expected ZMIN:ZMAX")?;
                    Filter::Limit(a, b)
                }
                _ => Filter::FillNan,
            };
            remake(&input, &output, &format, |road| tools::filter(road, filter, budget))?;
        }
        MakeCommand::Slope(a) => channel(a, LineChannel::Slope)?,
        MakeCommand::Banking(a) => channel(a, LineChannel::Banking)?,
        MakeCommand::Generate { output, refline, grid, width, surface, format } => {
            generate(&output, &refline, &grid, width, surface.as_deref(), &format, budget)?
        }
        MakeCommand::Import { cloud, output, refline, width, grid, max_edge, fill_nan, crop, format } => {
            let crop = crop.as_deref().map(parse_crop).transpose()?;
            let refline = refline.map(|l| tools::read_points(&l).map_err(|e| e.to_string())).transpose()?;
            let how = Import { refline, width, u_inc: grid.u_inc, v_inc: grid.v_inc, max_edge, fill: fill_nan, crop };
            import(&cloud, &output, &how, &format, budget)?
        }
        MakeCommand::Compare { a, b, tolerance, json } => return compare(&a, &b, tolerance, json),
    }
    Ok(std::process::ExitCode::SUCCESS)
}

/// `make generate`: a road along a reference line, flat or with a surface (a road file's
/// or a formula's).
fn generate(
    output: &Path,
    refline: &Path,
    grid: &GridArgs,
    width: f64,
    surface: Option<&str>,
    format: &OutputFormat,
    budget: &Budget,
) -> Result<(), String> {
    let line = tools::read_points(refline).map_err(|e| e.to_string())?;
    let layout = Layout { width, u_inc: grid.u_inc, v_inc: grid.v_inc };
    let made = match surface {
        None => tools::generate(&line, layout, None, budget),
        Some(text) if Path::new(text).is_file() => {
            let other = ContactPoint::new(Arc::new(load(Path::new(text))?));
            let f = move |u: f64, v: f64| other.uv_to_z(u, v).unwrap_or(f64::NAN);
            tools::generate(&line, layout, Some(&f), budget)
        }
        Some(text) => {
            let e = expr::parse(text).map_err(|m| format!("--surface '{}': {m}", expr::abridged(text)))?;
            tools::generate(&line, layout, Some(&|u, v| e.at(u, v)), budget)
        }
    }
    .map_err(named(refline))?;
    save(&made, output, data_format(format.format, DataFormat::Kdbi))?;
    Ok(())
}

/// `make import`: a road gridded from a point cloud, with a progress bar.
fn import(cloud: &Path, output: &Path, how: &Import, format: &OutputFormat, budget: &Budget) -> Result<(), String> {
    let bar = progress_bar();
    bar.set_message("reading");
    let points = tools::read_points(cloud).map_err(|e| e.to_string())?;
    let started = std::time::Instant::now();
    let made = tools::import(
        &points,
        how,
        &|stage, done, total| {
            bar.set_message(stage.to_string());
            bar.set_length(total);
            bar.set_position(done);
        },
        budget,
    );
    bar.finish_and_clear();
    let made = made.map_err(named(cloud))?;
    let seconds = started.elapsed().as_secs_f64();
    eprintln!("gridded {} points in {seconds:.2} s ({:.0} points/s)", points.len(), points.len() as f64 / seconds);
    save(&made, output, data_format(format.format, DataFormat::Kdbi))?;
    Ok(())
}

/// `make compare`: the largest and the rms difference of two roads' surfaces; exit status
/// 1 beyond `tolerance`.
fn compare(a: &Path, b: &Path, tolerance: Option<f64>, json: bool) -> Result<std::process::ExitCode, String> {
    let (ra, rb) = (Arc::new(load(a)?), Arc::new(load(b)?));
    let c = tools::compare(&ra, &rb, &|_, _, _| {}).map_err(named(a))?;
    if json {
        let value = serde_json::json!({
            "compared": c.compared,
            "only_in_a": c.only_first,
            "max_difference": c.max_difference,
            "signed": c.signed,
            "at": { "u": c.at[0], "v": c.at[1], "x": c.at[2], "y": c.at[3] },
            "rms": c.rms,
        });
        println!("{}", serde_json::to_string_pretty(&value).map_err(|e| e.to_string())?);
    } else {
        println!(
            "largest difference {:.6} m (B - A = {:.6} m) at u = {:.3}, v = {:.3} (x = {:.3}, y = {:.3})\n\
             rms {:.6} m over {} nodes of A; {} nodes of A have no surface of B at their x/y",
            c.max_difference, c.signed, c.at[0], c.at[1], c.at[2], c.at[3], c.rms, c.compared, c.only_first
        );
    }
    if c.compared == 0 {
        return Err(format!("{} and {}: no grid node of A lies on B", a.display(), b.display()));
    }
    if tolerance.is_some_and(|t| c.max_difference > t) {
        return Ok(std::process::ExitCode::from(1));
    }
    Ok(std::process::ExitCode::SUCCESS)
}
