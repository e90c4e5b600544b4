//! Generates the demo road shipped in examples/data/demo_road.crg: 120 m of a
//! gently curved, banked and sloped road, 6 m wide, with a bumpy surface.
//!
//!     cargo run -p opencrg-core --example make_demo_road -- examples/data/demo_road.crg

use opencrg_core::synth::RoadSpec;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1).unwrap_or_else(|| "examples/data/demo_road.crg".into());
    let road = RoadSpec::straight(120.0, 6.0, 0.5, 0.25)
        .starting_at(100.0, 50.0, 0.2)
        .with_heading(|u| 0.2 + 0.4 * (u / 120.0).powi(2))
        .with_slope(|u| 0.02 * (u / 40.0).sin())
        .with_bank(|u| 0.01 + 0.01 * (u / 60.0).cos())
        .with_elevation(|u, v| 0.005 * (u * 1.7).sin() * (v * 2.3).cos() + 0.002 * ((u * 0.31 + v).sin()))
        .build()?;
    opencrg_core::write(&road, &out, opencrg_core::DataFormat::Lrfi)?;
    println!("wrote {out}");
    Ok(())
}
