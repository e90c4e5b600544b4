//! Generates the benchmark roads into a folder (default: target/bench-roads):
//! 500 m x 4 m at 1 cm in KRBI (about 80 MB) and in LRFI, a 10 km road with a
//! winding reference line (KRBI, 1 cm along, 0.5 m across), and a 2 km winding road
//! with heading, slope and banking channels (KRBI, 1 cm along, 5 cm across, about
//! 65 MB of grid; curve radii down to about 125 m).
//!
//!     cargo run --release -p opencrg-core --example make_bench_roads -- target/bench-roads

use opencrg::synth::RoadSpec;
use opencrg::DataFormat;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::path::PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "target/bench-roads".into()));
    std::fs::create_dir_all(&dir)?;
    let surface = |u: f64, v: f64| 0.01 * (u * 7.1).sin() * (v * 3.3).cos() + 0.003 * (u * 41.0 + v * 17.0).sin();
    let track = RoadSpec::straight(500.0, 4.0, 0.01, 0.01).with_elevation(surface).build()?;
    for (name, format) in [("track_500m_krbi.crg", DataFormat::Krbi), ("track_500m_lrfi.crg", DataFormat::Lrfi)] {
        let path = dir.join(name);
        if !path.exists() {
            opencrg::write(&track, &path, format)?;
        }
        println!("{}", path.display());
    }
    let path = dir.join("winding_10km_krbi.crg");
    if !path.exists() {
        let winding = RoadSpec::straight(10_000.0, 4.0, 0.01, 0.5)
            .with_heading(|u| 3.0 * (u / 400.0).sin() + u / 2000.0)
            .with_elevation(surface)
            .build()?;
        opencrg::write(&winding, &path, DataFormat::Krbi)?;
    }
    println!("{}", path.display());
    let path = dir.join("winding_sloped_banked_2km_krbi.crg");
    if !path.exists() {
        let hilly = RoadSpec::straight(2_000.0, 4.0, 0.01, 0.05)
            .with_heading(|u| 3.0 * (u / 400.0).sin() + u / 2000.0)
            .with_slope(|u| 0.04 * (u / 150.0).sin())
            .with_bank(|u| 0.03 * (u / 90.0 + 1.0).sin())
            .with_elevation(surface)
            .build()?;
        opencrg::write(&hilly, &path, DataFormat::Krbi)?;
    }
    println!("{}", path.display());
    Ok(())
}
