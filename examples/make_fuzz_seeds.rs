//! Writes seed inputs for the fuzz targets (see fuzz/seed.sh) from roads the project
//! generates: whole files for the header target, data sections for the readers.

use opencrg::synth::RoadSpec;
use opencrg::DataFormat;
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args().nth(1).unwrap_or_else(|| "fuzz/corpus".into());
    let dir = Path::new(&dir);
    let roads = [
        RoadSpec::straight(4.0, 2.0, 0.5, 0.5).with_elevation(|u, v| 0.1 * u + v),
        RoadSpec::straight(6.0, 2.0, 0.5, 1.0).with_heading(|u| 0.05 * u).with_slope(|_| 0.01).with_bank(|_| 0.02),
        RoadSpec::straight(3.0, 2.0, 0.5, 0.5).with_sections(vec![-1.0, -0.25, 1.0]).with_elevation(|u, _| u),
    ];
    let mut n = 0;
    for spec in &roads {
        let road = spec.build()?;
        for format in [DataFormat::Lrfi, DataFormat::Ldfi, DataFormat::Krbi, DataFormat::Kdbi] {
            let mut bytes = Vec::new();
            opencrg::writer::write_to(&road, &mut bytes, format)?;
            std::fs::write(dir.join(format!("header/seed{n}")), &bytes)?;
            let marker = [b'$'; 80];
            if let Some(at) = bytes.windows(80).position(|w| w == marker) {
                let data = &bytes[at + 81..];
                let target = if format.is_text() { "text_reader" } else { "binary_reader" };
                let flag = u8::from(matches!(format, DataFormat::Ldfi | DataFormat::Kdbi));
                let mut seed = vec![flag];
                seed.extend_from_slice(data);
                std::fs::write(dir.join(format!("{target}/seed{n}")), seed)?;
            }
            n += 1;
        }
    }
    let demo = std::fs::read("examples/data/demo_road.crg")?;
    std::fs::write(dir.join("header/demo_road"), demo)?;
    for (i, seed) in [vec![3u8, 10, 5, 2, 21, 0, 0, 0, 0, 0, 0, 0, 64], vec![1u8, 30, 200, 0, 1, 1]].iter().enumerate()
    {
        std::fs::write(dir.join(format!("evaluation/seed{i}")), seed)?;
    }
    Ok(())
}
