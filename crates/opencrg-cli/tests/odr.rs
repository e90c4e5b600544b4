//! `opencrg odr`: info on a shared map, check on a clean and a broken map, eval on a map
//! with CRG records (plane CRG files, answers against closed forms).

use opencrg_core::synth::RoadSpec;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("opencrg-cli-{}-odr-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn opencrg(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_opencrg"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(stdin.as_bytes()).unwrap();
    child.wait_with_output().unwrap()
}

fn shared(rel: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/opendrive").join(rel).display().to_string()
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_maps_info_counts_the_map() {
    let out = opencrg(&["odr", "info", &shared("carla/Town01.xodr"), "--json"], "");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!((j["roads"].as_u64(), j["junctions"].as_u64()), (Some(98), Some(12)));
    assert!(j["length"].as_f64().unwrap() > 3000.0);
    let out = opencrg(&["odr", "info", "/nonexistent.xodr"], "");
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn info_counts_the_demo_map_and_render_draws_it() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/data/demo_map.xodr");
    let text = std::fs::read_to_string(&file).unwrap();
    let out = opencrg(&["odr", "info", file.to_str().unwrap(), "--json"], "");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let count = |tag: &str| text.matches(tag).count() as u64;
    assert_eq!((j["roads"].as_u64(), j["junctions"].as_u64()), (Some(count("<road ")), Some(count("<junction "))));
    assert_eq!(j["crg_records"].as_array().map(Vec::len), Some(text.matches("<CRG ").count()));
    let png = dir("render_demo").join("map.png");
    let out = opencrg(&["odr", "render", file.to_str().unwrap(), png.to_str().unwrap(), "--size", "200"], "");
    assert!(out.status.success() && png.exists(), "{}", String::from_utf8_lossy(&out.stderr));
}

/// A straight road 60 m along x from the origin with one lane each side (4 m, friction
/// 0.8), and `records`.
fn map(d: &Path, records: &str) -> String {
    let text = format!(
        r#"<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="main" length="60" junction="-1">
<planView><geometry s="0" x="0" y="0" hdg="0" length="60"><line/></geometry></planView>
<elevationProfile><elevation s="0" a="1" b="0.01" c="0" d="0"/></elevationProfile>
<lanes><laneSection s="0">
<left><lane id="1" type="driving"><width sOffset="0" a="4" b="0" c="0" d="0"/><material sOffset="0" friction="0.8"/></lane></left>
<center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="4" b="0" c="0" d="0"/><material sOffset="0" friction="0.8"/></lane></right>
</laneSection></lanes>
<surface>{records}</surface>
</road></OpenDRIVE>"#
    );
    let p = d.join("map.xodr");
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

#[test]
fn check_names_the_road_and_the_record() {
    let d = dir("check");
    let spec = RoadSpec::straight(10.0, 4.0, 0.5, 0.5).with_elevation(|u, v| 0.01 * u + 0.02 * v);
    std::fs::write(d.join("plane.crg"), spec.to_crg()).unwrap();
    let clean = map(&d, r#"<CRG file="plane.crg" sStart="5" sEnd="15" mode="attached" orientation="same"/>"#);
    let out = opencrg(&["odr", "check", &clean], "");
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
    let broken = map(
        &d,
        r#"<CRG file="plane.crg" sStart="5" sEnd="75" mode="attached" orientation="same"/>
<CRG file="plane.crg" sStart="0" sEnd="10" mode="attached" orientation="same" purpose="friction" zScale="2"/>
<CRG file="gone.crg" sStart="0" sEnd="10" mode="genuine" orientation="opposite"/>"#,
    );
    let out = opencrg(&["odr", "check", &broken], "");
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    for words in [
        "road main, CRG record 'plane.crg': sStart 5 and sEnd 75",
        "mode attached is not allowed for friction",
        "sets no zScale",
        "orientation opposite only",
        "'gone.crg': the CRG file cannot be used",
    ] {
        assert!(text.contains(words), "'{words}' not in:\n{text}");
    }
    assert!(text.lines().all(|l| l.contains("map.xodr:line ")), "{text}");
}

#[test]
fn eval_answers_with_the_crg_records_laid_on() {
    let d = dir("eval");
    let (a, b, c) = (0.01, -0.02, 0.005);
    let spec =
        RoadSpec::straight(20.0, 4.0, 0.25, 0.25).with_slope(|_| 0.05).with_elevation(move |u, v| a * u + b * v + c);
    std::fs::write(d.join("bumps.crg"), spec.to_crg()).unwrap();
    let mu = RoadSpec::straight(20.0, 8.0, 0.5, 0.5).with_elevation(|_, v| 0.6 + 0.01 * v);
    std::fs::write(d.join("mu.crg"), mu.to_crg()).unwrap();
    let m = map(
        &d,
        r#"<CRG file="bumps.crg" sStart="10" sEnd="30" mode="attached" orientation="same" sOffset="10"/>
<CRG file="mu.crg" sStart="10" sEnd="30" mode="attached0" purpose="friction" sOffset="10"/>"#,
    );
    let points: [(f64, f64); 4] = [(15.0, 1.0), (25.0, -1.5), (40.0, 2.0), (15.0, 30.0)];
    let input: String = points.iter().map(|(x, y)| format!("{x} {y}\n")).collect();
    let out = opencrg(&["odr", "eval", &m], &input);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), points.len());
    for (line, &(x, y)) in lines.iter().zip(&points) {
        let f: Vec<&str> = line.split_whitespace().collect();
        if y.abs() > 4.0 {
            assert_eq!(*line, "nan nan - nan nan");
            continue;
        }
        let (z, mu, road, s, t): (f64, f64, &str, f64, f64) =
            (f[0].parse().unwrap(), f[1].parse().unwrap(), f[2], f[3].parse().unwrap(), f[4].parse().unwrap());
        assert_eq!(road, "main");
        assert!((s - x).abs() < 1e-3 && (t - y).abs() < 1e-3, "{line}");
        let own = 1.0 + 0.01 * x;
        if (10.0..=30.0).contains(&x) {
            let (u, v) = (x - 10.0, y);
            assert!((z - (own + a * u + b * v + c)).abs() < 1e-3, "{line}");
            assert!((mu - (0.6 + 0.01 * v)).abs() < 1e-6, "{line}");
        } else {
            assert!((z - own).abs() < 1e-3, "{line}");
            assert_eq!(mu, 0.8);
        }
    }
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_maps_render_draws_the_map() {
    let d = dir("render");
    let out = d.join("town.png");
    let status =
        opencrg(&["odr", "render", &shared("esmini/fabriksgatan.xodr"), out.to_str().unwrap(), "--size", "300"], "");
    assert!(status.status.success(), "{}", String::from_utf8_lossy(&status.stderr));
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&out).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    // The map's 300 px on its longer side, the margins, the colour and scale bars' room.
    let longer = info.width.max(info.height);
    assert!((300..=300 + 200).contains(&longer), "{} x {}", info.width, info.height);
    // Road pixels (not white) and the background (white) both present.
    let pixels: Vec<&[u8]> = buf[..info.buffer_size()].chunks(info.line_size / info.width as usize).collect();
    assert!(pixels.iter().any(|p| p[..3] != [255, 255, 255]) && pixels.iter().any(|p| p[..3] == [255, 255, 255]));
    let refused =
        opencrg(&["odr", "render", &shared("esmini/fabriksgatan.xodr"), out.to_str().unwrap(), "--size", "4"], "");
    assert_eq!(refused.status.code(), Some(2));
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_maps_export_writes_the_lanes_as_parts_of_one_mesh() {
    let d = dir("export");
    let glb = d.join("map.glb");
    let map = shared("esmini/fabriksgatan.xodr");
    let out = opencrg(&["odr", "export", &map, glb.to_str().unwrap()], "");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let bytes = std::fs::read(&glb).unwrap();
    assert_eq!(&bytes[..4], b"glTF");
    let json_len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
    let doc: serde_json::Value = serde_json::from_slice(&bytes[20..20 + json_len]).unwrap();
    let primitives = doc["meshes"][0]["primitives"].as_array().unwrap();
    assert!(primitives.len() > 10, "{} primitives", primitives.len());
    for p in primitives {
        let a = &p["attributes"];
        for name in ["POSITION", "NORMAL", "TEXCOORD_0", "_FRICTION", "_ROAD", "_LANE", "_S", "_T"] {
            assert!(a[name].is_u64(), "{name} missing: {p}");
        }
        let extras = &p["extras"];
        assert!(extras["road"].is_string() && extras["lane"].is_i64() && extras["type"].is_string(), "{extras}");
        assert!(extras["type"] != "none");
    }
    // One road, as OBJ: its lanes as groups.
    let road = opencrg_odr::Map::load(&map).unwrap().roads[0].id.clone();
    let obj = d.join("road.obj");
    let out = opencrg(&["odr", "export", &map, obj.to_str().unwrap(), "--roads", &road, "--lanes", "driving"], "");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&obj).unwrap();
    let groups: Vec<&str> = text.lines().filter(|l| l.starts_with("g ")).collect();
    assert!(!groups.is_empty() && groups.iter().all(|g| g.starts_with(&format!("g road_{road}_lane_"))), "{groups:?}");
    // Refused: an unknown road, an unknown format, a bound that is no bound; nothing written.
    for (args, what) in
        [(vec!["--roads", "no-such-road"], "no road 'no-such-road'"), (vec!["--max-error", "-1"], "positive number")]
    {
        let target = d.join("refused.glb");
        let mut all = vec!["odr", "export", &map, target.to_str().unwrap()];
        all.extend(args);
        let out = opencrg(&all, "");
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&out.stderr).contains(what), "{}", String::from_utf8_lossy(&out.stderr));
        assert!(!target.exists());
    }
    let out = opencrg(&["odr", "export", &map, d.join("map.xyz").to_str().unwrap()], "");
    assert_eq!(out.status.code(), Some(2));
}
