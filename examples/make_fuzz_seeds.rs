//! Writes seed inputs for the fuzz targets (see fuzz/seed.sh) from roads the project
//! generates: whole files for the header target, data sections for the readers.

use opencrg_core::synth::RoadSpec;
use opencrg_core::DataFormat;
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args().nth(1).unwrap_or_else(|| "fuzz/corpus".into());
    let dir = Path::new(&dir);
    for target in [
        "header",
        "text_reader",
        "binary_reader",
        "evaluation",
        "point_files",
        "map_section",
        "formula",
        "tools",
        "odr_map",
    ] {
        std::fs::create_dir_all(dir.join(target))?;
    }
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
            opencrg_core::writer::write_to(&road, &mut bytes, format)?;
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
    point_file_seeds(&dir.join("point_files"))?;
    // The small OpenDRIVE maps of ../shared (read from there, never copied into the
    // repository).
    if let Ok(maps) = std::fs::read_dir("../shared/opendrive/esmini") {
        for entry in maps.flatten() {
            let p = entry.path();
            if p.extension().is_some_and(|e| e == "xodr") && entry.metadata().is_ok_and(|m| m.len() < 40_000) {
                std::fs::copy(&p, dir.join("odr_map").join(entry.file_name()))?;
            }
        }
    }
    let sections = [
        "GELL_NM = 'WGS84'\nPROJ_NM = 'UTM_32U'",
        "LELL_NM = BESSELDHDN\nPROJ_NM = GK3_4",
        "LELL_NM = 'BESSELDHDN'\nTRAN_NM = 'HN7'\nTRAN_DS = -5.2379e-6\nTRAN_RX = 3.4911e-6\nTRAN_RY = 5.391e-7\n\
         TRAN_RZ = -8.3432e-6\nTRAN_TX = -604.7365\nTRAN_TY = -72.3946\nTRAN_TZ = -424.402\nPROJ_NM = GK3_4",
        "LELL_NM = USERDEFINED\nLELL_A = 6378000\nLELL_B = 6356000\nTRAN_NM = HL7\nTRAN_TX = 10\n\
         PROJ_NM = TM\nPROJ_F0 = 0.9999\nPROJ_P0 = 0.8\nPROJ_L0 = 0.2\nPROJ_E0 = 200000\nPROJ_N0 = -100000",
        "LELL_NM = GRS1980AUTHALICSPHERE\nTRAN_NM = HS7\nTRAN_TZ = 3\nPROJ_NM = TM_11",
    ];
    for (i, text) in sections.iter().enumerate() {
        std::fs::write(dir.join(format!("map_section/seed{i}")), text)?;
    }
    for (i, text) in ["0.01*sin(2*pi*u/5) + -v^2/4 - 1e-3", "sqrt(abs(u))*exp(-v)", "((u))^2^0.5", "ln(u+1)/tan(v)"]
        .iter()
        .enumerate()
    {
        std::fs::write(dir.join(format!("formula/seed{i}")), text)?;
    }
    for (i, seed) in
        [vec![20u8, 3, 0, 7, 8], vec![40u8, 250, 6, 0, 7, 8, 9, 1, 9, 8, 0, 9, 7, 7, 8], vec![9u8, 1, 10, 8]]
            .iter()
            .enumerate()
    {
        std::fs::write(dir.join(format!("tools/seed{i}")), seed)?;
    }
    Ok(())
}

/// Small point files of each kind the reader takes, each behind the byte that picks its
/// kind in the `point_files` target (0 CSV, 1 XYZ, 2 PLY, 3 LAS).
fn point_file_seeds(dir: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let points: Vec<[f64; 3]> =
        (0..40).map(|i| [(i % 8) as f64 * 0.5, (i / 8) as f64 * 0.5 - 1.0, 0.01 * i as f64]).collect();
    let mut csv = b"\x00x,y,z\n".to_vec();
    let mut xyz = b"\x01".to_vec();
    let mut ply_text = format!("\x02ply\nformat ascii 1.0\nelement vertex {}\n", points.len()).into_bytes();
    let mut ply_binary =
        format!("\x02ply\nformat binary_little_endian 1.0\nelement vertex {}\n", points.len()).into_bytes();
    for head in [&mut ply_text, &mut ply_binary] {
        head.extend_from_slice(b"property double x\nproperty double y\nproperty double z\nend_header\n");
    }
    for p in &points {
        csv.extend_from_slice(format!("{},{},{}\n", p[0], p[1], p[2]).as_bytes());
        xyz.extend_from_slice(format!("{} {} {}\n", p[0], p[1], p[2]).as_bytes());
        ply_text.extend_from_slice(format!("{} {} {}\n", p[0], p[1], p[2]).as_bytes());
        for c in p {
            ply_binary.extend_from_slice(&c.to_le_bytes());
        }
    }
    let mut las = vec![3u8];
    {
        let mut writer = las::Writer::new(std::io::Cursor::new(Vec::new()), las::Header::default())?;
        for p in &points {
            writer.write_point(las::Point { x: p[0], y: p[1], z: p[2], ..Default::default() })?;
        }
        las.extend_from_slice(writer.into_inner()?.get_ref());
    }
    for (name, bytes) in [("csv", csv), ("xyz", xyz), ("ply_text", ply_text), ("ply_binary", ply_binary), ("las", las)]
    {
        std::fs::write(dir.join(name), bytes)?;
    }
    Ok(())
}
