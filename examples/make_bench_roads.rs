//! Generates the benchmark roads into a folder (default: target/bench-roads):
//! 500 m x 4 m at 1 cm in KRBI (about 80 MB) and in LRFI, a 10 km road with a
//! winding reference line (KRBI, 1 cm along, 0.5 m across), and a 2 km winding road
//! with heading, slope and banking channels (KRBI, 1 cm along, 5 cm across, about
//! 65 MB of grid; curve radii down to about 125 m). Roads already there are kept; names
//! after the folder (without `.crg`) make only those.
//!
//!     cargo run --release -p opencrg-core --example make_bench_roads -- target/bench-roads [NAME ...]

use opencrg_core::synth::RoadSpec;
use opencrg_core::{DataFormat, Road};

/// How a benchmark road is made.
type Make = fn() -> opencrg_core::Result<Road>;

/// The benchmark roads: file name (without `.crg`), format, and how to make the road.
const ROADS: [(&str, DataFormat, Make); 4] = [
    ("track_500m_krbi", DataFormat::Krbi, track),
    ("track_500m_lrfi", DataFormat::Lrfi, track),
    ("winding_10km_krbi", DataFormat::Krbi, winding),
    ("winding_sloped_banked_2km_krbi", DataFormat::Krbi, hilly),
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

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let dir = std::path::PathBuf::from(args.next().unwrap_or_else(|| "target/bench-roads".into()));
    let wanted: Vec<String> = args.collect();
    if let Some(unknown) = wanted.iter().find(|w| !ROADS.iter().any(|(name, ..)| name == w)) {
        return Err(format!("no benchmark road is named {unknown}").into());
    }
    std::fs::create_dir_all(&dir)?;
    for (name, format, make) in ROADS {
        if !wanted.is_empty() && !wanted.iter().any(|w| w == name) {
            continue;
        }
        let path = dir.join(format!("{name}.crg"));
        if !path.exists() {
            opencrg_core::write(&make()?, &path, format)?;
        }
        println!("{}", path.display());
    }
    Ok(())
}
