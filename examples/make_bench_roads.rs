//! Generates the benchmark roads into a folder (default: target/bench-roads):
//! 500 m x 4 m at 1 cm in KRBI (about 80 MB) and in LRFI, a 10 km road with a
//! winding reference line (KRBI, 1 cm along, 0.5 m across), and a 2 km winding road
//! with heading, slope and banking channels (KRBI, 1 cm along, 5 cm across, about
//! 65 MB of grid; curve radii down to about 125 m). Roads already there are kept; names
//! after the folder (without `.crg`) make only those.
//!
//! Roads of gigabytes are made only when named (streamed to the file, never held in
//! memory): `winding_5km_2gb_krbi`, 5 km x 10 m at 1 cm (2.0 GB, the test run's),
//! `winding_10km_4gb_krbi`, 10 km x 10 m (4.0 GB), and `proving_ground_16gb_krbi`, 10 km x
//! 40 m (16.0 GB), all at 1 cm with heading, slope and banking channels.
//!
//!     cargo run --release -p opencrg-core --example make_bench_roads -- target/bench-roads [NAME ...]

use opencrg_core::synth::RoadSpec;
use opencrg_core::{DataFormat, Road};

/// How a benchmark road is made: in memory and written, or streamed into its file.
#[derive(Clone, Copy)]
enum Make {
    Road(fn() -> opencrg_core::Result<Road>),
    Streamed(fn() -> RoadSpec),
}

/// The benchmark roads: file name (without `.crg`), format, how to make the road, and
/// whether it is made without being named.
const ROADS: [(&str, DataFormat, Make, bool); 7] = [
    ("track_500m_krbi", DataFormat::Krbi, Make::Road(track), true),
    ("track_500m_lrfi", DataFormat::Lrfi, Make::Road(track), true),
    ("winding_10km_krbi", DataFormat::Krbi, Make::Road(winding), true),
    ("winding_sloped_banked_2km_krbi", DataFormat::Krbi, Make::Road(hilly), true),
    ("winding_5km_2gb_krbi", DataFormat::Krbi, Make::Streamed(big_2gb), false),
    ("winding_10km_4gb_krbi", DataFormat::Krbi, Make::Streamed(big_4gb), false),
    ("proving_ground_16gb_krbi", DataFormat::Krbi, Make::Streamed(big_16gb), false),
];

/// The elevation grid every road carries: bumps of a centimetre.
fn surface(u: f64, v: f64) -> f64 {
    0.01 * (u * 7.1).sin() * (v * 3.3).cos() + 0.003 * (u * 41.0 + v * 17.0).sin()
}

fn track() -> opencrg_core::Result<Road> {
    RoadSpec::straight(500.0, 4.0, 0.01, 0.01).with_elevation(surface).build()
}

fn winding() -> opencrg_core::Result<Road> {
    RoadSpec::straight(10_000.0, 4.0, 0.01, 0.5)
        .with_heading(|u| 3.0 * (u / 400.0).sin() + u / 2000.0)
        .with_elevation(surface)
        .build()
}

fn hilly() -> opencrg_core::Result<Road> {
    RoadSpec::straight(2_000.0, 4.0, 0.01, 0.05)
        .with_heading(|u| 3.0 * (u / 400.0).sin() + u / 2000.0)
        .with_slope(|u| 0.04 * (u / 150.0).sin())
        .with_bank(|u| 0.03 * (u / 90.0 + 1.0).sin())
        .with_elevation(surface)
        .build()
}

/// A road `length` metres long and `width` wide at 1 cm both ways, winding, sloped and
/// banked.
fn big(length: f64, width: f64) -> RoadSpec {
    RoadSpec::straight(length, width, 0.01, 0.01)
        .with_heading(|u| 3.0 * (u / 400.0).sin() + u / 2000.0)
        .with_slope(|u| 0.04 * (u / 150.0).sin())
        .with_bank(|u| 0.03 * (u / 90.0 + 1.0).sin())
        .with_elevation(surface)
}

fn big_2gb() -> RoadSpec {
    big(5_000.0, 10.0)
}

fn big_4gb() -> RoadSpec {
    big(10_000.0, 10.0)
}

fn big_16gb() -> RoadSpec {
    big(10_000.0, 40.0)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let dir = std::path::PathBuf::from(args.next().unwrap_or_else(|| "target/bench-roads".into()));
    let wanted: Vec<String> = args.collect();
    if let Some(unknown) = wanted.iter().find(|w| !ROADS.iter().any(|(name, ..)| name == w)) {
        return Err(format!("no benchmark road is named {unknown}").into());
    }
    std::fs::create_dir_all(&dir)?;
    for (name, format, make, by_default) in ROADS {
        if !(wanted.is_empty() && by_default || wanted.iter().any(|w| w == name)) {
            continue;
        }
        let path = dir.join(format!("{name}.crg"));
        if !path.exists() {
            match make {
                Make::Road(make) => opencrg_core::write(&make()?, &path, format)?,
                Make::Streamed(spec) => {
                    // Written under another name first: an interrupted run leaves no road.
                    let partial = path.with_extension("partial");
                    spec().write(&partial, format)?;
                    std::fs::rename(&partial, &path)?;
                }
            }
        }
        println!("{}", path.display());
    }
    Ok(())
}
