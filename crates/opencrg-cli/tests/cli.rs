//! The `opencrg` command on roads these tests generate: info against the road's known
//! figures, check on a good and a broken file, convert round trips through all four
//! formats, eval against the library, render pictures, and bad input.

use opencrg_core::synth::RoadSpec;
use opencrg_core::{ContactPoint, Road};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::Arc;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("opencrg-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// 30 m along heading 0.3 from (5, 7), v from -1.5 to 1.5, z = 0.02 u + 0.1 v (from -0.15
/// to 0.75), NaN in one cell, options and modifiers in the file.
fn spec() -> RoadSpec {
    RoadSpec::straight(30.0, 3.0, 0.5, 0.25)
        .starting_at(5.0, 7.0, 0.3)
        .with_heading(|_| 0.3)
        .with_elevation(|u, v| if u == 10.0 && v == 0.0 { f64::NAN } else { 0.02 * u + 0.1 * v })
        .with_header_text("$ROAD_CRG_OPTS\nBORDER_MODE_V = 1\n$\n$ROAD_CRG_MODS\nSCALE_Z_GRID = 2.0\n$\n")
}

fn write_road(d: &Path) -> PathBuf {
    let p = d.join("road.crg");
    std::fs::write(&p, spec().to_crg()).unwrap();
    p
}

fn opencrg(args: &[&str], stdin: Option<&str>) -> Output {
    opencrg_with(args, stdin, &[])
}

/// `opencrg` with environment variables set.
fn opencrg_with(args: &[&str], stdin: Option<&str>, env: &[(&str, &str)]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_opencrg"))
        .args(args)
        .envs(env.iter().copied())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(stdin.unwrap_or("").as_bytes()).unwrap();
    child.wait_with_output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A road read in place: `info` says its grid was not scanned (in text and as null in
/// JSON), and with `--scan` reports what the road read into memory reports.
#[test]
fn info_scans_a_road_read_in_place_when_asked() {
    let d = dir("info-in-place");
    let road = d.join("road.crg");
    spec().write(&road, opencrg_core::DataFormat::Krbi).unwrap();
    let road = road.to_str().unwrap();
    let run = |args: &[&str], mode: &str| {
        let out = opencrg_with(args, None, &[("OPENCRG_IN_PLACE", mode)]);
        assert!(out.status.success(), "{}", text(&out.stderr));
        text(&out.stdout)
    };
    let memory = run(&["info", road], "never");
    assert!(memory.contains("NaN cells      1"), "{memory}");
    let placed = run(&["info", road], "always");
    assert!(placed.contains("elevation      not scanned") && !placed.contains("NaN cells"), "{placed}");
    assert_eq!(run(&["info", road, "--scan"], "always"), memory);
    let j: serde_json::Value = serde_json::from_str(&run(&["info", road, "--json"], "always")).unwrap();
    assert!(j["nan_cells"].is_null() && j["elevation"]["min"].is_null() && j["in_place"] == true, "{j}");
    let j: serde_json::Value = serde_json::from_str(&run(&["info", road, "--json", "--scan"], "always")).unwrap();
    assert_eq!(j["nan_cells"], 1);
}

#[test]
fn info_reports_the_known_figures() {
    let d = dir("info");
    let road = write_road(&d);
    let out = opencrg_with(&["info", road.to_str().unwrap(), "--json"], None, &[("OPENCRG_IN_PLACE", "never")]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(j["format"], "KDBI");
    assert_eq!(j["cross_sections"], 61);
    assert_eq!(j["long_sections"], 13);
    assert_eq!((j["u"]["first"].as_f64(), j["u"]["last"].as_f64()), (Some(0.0), Some(30.0)));
    assert_eq!((j["v"]["right"].as_f64(), j["v"]["left"].as_f64()), (Some(-1.5), Some(1.5)));
    let near = |v: &serde_json::Value, x: f64| (v.as_f64().unwrap() - x).abs() < 1e-6;
    assert!(near(&j["elevation"]["min"], -0.15) && near(&j["elevation"]["max"], 0.75), "{}", j["elevation"]);
    assert!(near(&j["reference_line"]["start"]["x"], 5.0) && near(&j["reference_line"]["start"]["y"], 7.0));
    assert!(near(&j["reference_line"]["end"]["x"], 5.0 + 30.0 * 0.3f64.cos()));
    assert!(near(&j["reference_line"]["end"]["y"], 7.0 + 30.0 * 0.3f64.sin()));
    assert_eq!(j["nan_cells"], 1);
    assert_eq!(j["options"]["border mode v"], 1);
    assert_eq!(j["modifiers"]["modifier z scale"], 2.0);
    // The text form carries the same figures.
    let out = opencrg(&["info", road.to_str().unwrap()], None);
    let t = text(&out.stdout);
    assert!(t.contains("61 cross sections x 13 long sections") && t.contains("-0.1500 .. 0.7500 m"), "{t}");
}

#[test]
fn check_passes_a_good_road_and_refuses_a_broken_one() {
    let d = dir("check");
    let road = write_road(&d);
    let out = opencrg(&["check", road.to_str().unwrap()], None);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // The same road with a modifier the check refuses; the binary data stays as it was.
    let broken = d.join("broken.crg");
    let original = spec().to_crg();
    let separator: Vec<u8> = [b'$'; 80].iter().chain(b"\n").copied().collect();
    let header_end = original.windows(81).position(|w| w == separator).unwrap() + 81;
    let mut file = text(&original[..header_end]).replace("SCALE_Z_GRID = 2.0", "SCALE_LENGTH = -1.0").into_bytes();
    file.extend_from_slice(&original[header_end..]);
    std::fs::write(&broken, file).unwrap();
    let out = opencrg(&["check", broken.to_str().unwrap()], None);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("SCALE_LENGTH"), "{}", text(&out.stderr));
}

#[test]
fn convert_round_trips_through_every_format() {
    let d = dir("convert");
    let start = write_road(&d);
    let original = Road::load(&start).unwrap();
    let mut from = start.clone();
    for (k, format) in ["LRFI", "KRBI", "LDFI", "KDBI"].iter().enumerate() {
        let to = d.join(format!("step{k}.crg"));
        // The names as files spell them, and in lower and mixed case.
        let asked = [format.to_string(), format.to_lowercase(), format[..2].to_string() + &format[2..].to_lowercase()];
        let out =
            opencrg(&["convert", from.to_str().unwrap(), to.to_str().unwrap(), "--format", &asked[(k + 2) % 3]], None);
        assert!(out.status.success(), "{format}: {}", text(&out.stderr));
        let back = Road::load(&to).unwrap();
        assert_eq!(back.format().name(), *format);
        let (a, b) = (original.grid(), back.grid());
        assert_eq!((a.nu, a.nv), (b.nu, b.nv));
        for (x, y) in a.values().iter().zip(b.values()) {
            assert!((x.is_nan() && y.is_nan()) || (x - y).abs() <= 1e-6 * x.abs().max(1.0), "{format}: {x} vs {y}");
        }
        assert_eq!(back.u_range(), original.u_range());
        assert_eq!(back.options(), original.options(), "{format}: options kept");
        assert_eq!(back.modifiers(), original.modifiers(), "{format}: modifiers kept");
        assert!(
            back.header().comments.iter().any(|c| c.contains("generated by opencrg_core::synth")),
            "{format}: comments kept"
        );
        from = to;
    }
}

#[test]
fn eval_prints_the_library_answers() {
    let d = dir("eval");
    let road = write_road(&d);
    let out =
        opencrg(&["eval", road.to_str().unwrap(), "--border-mode-v", "keep"], Some("3 0.5\n# comment\n12.25, -0.75\n"));
    assert!(out.status.success(), "{}", text(&out.stderr));
    let t = text(&out.stdout);
    let lines: Vec<&str> = t.lines().collect();
    assert_eq!(lines[0], "u,v,x,y,z,phi,curv");
    assert_eq!(lines.len(), 3);
    // The same answers from the library, prepared as the C API prepares roads.
    let mut r = Road::load(&road).unwrap();
    r.check().unwrap();
    r.apply_modifiers();
    let mut cp = ContactPoint::new(Arc::new(r));
    cp.set_option_int(opencrg_core::settings::opt::BORDER_MODE_V, 2).unwrap();
    for (line, (u, v)) in lines[1..].iter().zip([(3.0, 0.5), (12.25, -0.75)]) {
        let f: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        let (x, y) = cp.uv_to_xy(u, v).unwrap();
        let z = cp.uv_to_z(u, v).unwrap();
        let (phi, curv) = cp.uv_to_pk(u, v).unwrap();
        assert_eq!(f, vec![u, v, x, y, z, phi, curv]);
    }
    // x/y input.
    let out = opencrg(&["eval", road.to_str().unwrap(), "--xy"], Some("5 7\n"));
    let t = text(&out.stdout);
    assert!(t.starts_with("x,y,u,v,z,phi,curv\n5,7,"), "{t}");
    // Huge and tiny numbers in powers of ten, not hundreds of digits.
    let out = opencrg(&["eval", road.to_str().unwrap()], Some("1e300 -2.5e-300\n"));
    let t = text(&out.stdout);
    assert!(t.lines().nth(1).is_some_and(|l| l.starts_with("1e300,-2.5e-300,") && l.len() < 200), "{t}");
    // A bad line: one line on stderr, exit status 2.
    let out = opencrg(&["eval", road.to_str().unwrap()], Some("1 2\nabc\n"));
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(text(&out.stderr).trim().lines().count(), 1, "{}", text(&out.stderr));
    assert!(text(&out.stderr).contains("stdin:2"));
}

/// A picture's width, height and RGB pixels (alpha dropped).
fn png_size(path: &Path) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    buf.truncate(info.buffer_size());
    let channels = info.line_size / info.width as usize;
    let rgb = buf.chunks(channels).flat_map(|p| p[..3].to_vec()).collect();
    (info.width, info.height, rgb)
}

#[test]
fn render_draws_the_road_and_its_sections() {
    let d = dir("render");
    let road = write_road(&d);
    let picture = d.join("top.png");
    let out = opencrg(&["render", road.to_str().unwrap(), picture.to_str().unwrap(), "--size", "400"], None);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let (w, h, pixels) = png_size(&picture);
    assert!(w > 400 && h > 100, "{w} x {h}");
    // Coloured pixels (the road and the colour bar), not only white and black.
    let coloured = pixels.chunks(3).filter(|p| !(p[0] == p[1] && p[1] == p[2])).count();
    assert!(coloured > 2000, "{coloured} coloured pixels");
    // The cell without elevation is drawn in grey, and the figure says what grey means.
    let svg = d.join("top.svg");
    let out = opencrg(&["render", road.to_str().unwrap(), svg.to_str().unwrap(), "--size", "400"], None);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(std::fs::read_to_string(&svg).unwrap().contains("no data"));
    for section in ["u=15", "v=0.5"] {
        let p = d.join(format!("profile-{}.png", &section[..1]));
        let out = opencrg(&["render", road.to_str().unwrap(), p.to_str().unwrap(), "--profile", section], None);
        assert!(out.status.success(), "{section}: {}", text(&out.stderr));
        let (w, h, pixels) = png_size(&p);
        assert_eq!((w, h), (900, 440));
        let line = pixels.chunks(3).filter(|p| p == &[30, 90, 200]).count();
        assert!(line > 500, "{section}: {line} pixels of the line");
    }
    let out = opencrg(&["render", road.to_str().unwrap(), picture.to_str().unwrap(), "--profile", "w=1"], None);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn bad_input_gives_one_line_and_status_2() {
    let d = dir("bad");
    let garbage = d.join("garbage.crg");
    std::fs::write(&garbage, b"\x00\x01 not a road\n$$$$\nxx").unwrap();
    for args in [
        vec!["info", garbage.to_str().unwrap()],
        vec!["check", garbage.to_str().unwrap()],
        vec!["render", garbage.to_str().unwrap(), "/tmp/never.png"],
        vec!["info", "/no/such/file.crg"],
    ] {
        let out = opencrg(&args, None);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = text(&out.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("opencrg: ") && !err.contains("panicked"), "{err}");
    }
}

/// A 200 m road whose every long section is the same wavy profile.
fn rough_road(d: &Path) -> PathBuf {
    let p = d.join("rough.crg");
    let spec = RoadSpec::straight(200.0, 3.0, 0.1, 0.5)
        .with_elevation(|u, _| 0.004 * (u * std::f64::consts::TAU / 7.0).sin() + 0.002 * (u * 1.9).sin());
    std::fs::write(&p, spec.to_crg()).unwrap();
    p
}

#[test]
fn roughness_reports_the_library_figures() {
    let d = dir("roughness");
    let road = rough_road(&d);
    let r = Arc::new(Road::load(&road).unwrap());
    let expected = opencrg_tools::roughness::roughness(&r, &[-0.85, 0.5], 50.0).unwrap();
    let out = opencrg(
        &["roughness", road.to_str().unwrap(), "--track", "-0.85", "--track", "0.5", "--segment", "50", "--json"],
        None,
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let tracks = json["tracks"].as_array().unwrap();
    assert_eq!(tracks.len(), 2);
    // (serde_json reads numbers back to within an ulp.)
    let close = |j: &serde_json::Value, x: f64| (j.as_f64().unwrap() / x - 1.0).abs() < 1e-12;
    for (t, e) in tracks.iter().zip(&expected) {
        assert_eq!(t["v"].as_f64(), Some(e.v));
        assert!(close(&t["iri"], e.iri) && e.iri > 0.0, "{} against {}", t["iri"], e.iri);
        assert!(close(&t["psd"]["gd_n0"], e.psd.gd_n0), "{} against {}", t["psd"]["gd_n0"], e.psd.gd_n0);
        assert_eq!(t["psd"]["class"].as_str(), Some(e.psd.class.to_string().as_str()));
        assert_eq!(t["segments"].as_array().unwrap().len(), 4);
    }
    // The table names every track; the plot is a picture.
    let png = d.join("roughness.png");
    let out = opencrg(&["roughness", road.to_str().unwrap(), "--plot", png.to_str().unwrap()], None);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let table = text(&out.stdout);
    for v in ["-0.850", "0.000", "0.850"] {
        assert!(table.contains(v), "{table}");
    }
    assert_eq!(png_size(&png).0, 900);
    // A track beside the road: one line naming it (after the load's warnings), status 2.
    let out = opencrg(&["roughness", road.to_str().unwrap(), "--track", "4"], None);
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    let last = err.lines().last().unwrap_or("");
    assert!(last.contains("v = 4 m") && last.contains("outside") && last.contains("rough.crg"), "{err}");
    assert!(err.lines().filter(|l| !l.contains("warning")).count() == 1, "{err}");
}

#[test]
fn export_writes_meshes_and_maps() {
    let d = dir("export");
    let road = write_road(&d);
    let r = road.to_str().unwrap();
    for (name, extra) in [
        ("m.obj", vec![]),
        ("m.stl", vec!["--u", "5:20"]),
        ("m.ply", vec!["--v", "-1:1"]),
        ("h.png", vec![]),
        ("n.png", vec!["--normal-map"]),
        ("s.stl", vec!["--max-error", "0.05"]),
    ] {
        let out = d.join(name);
        let mut args = vec!["export", r, out.to_str().unwrap()];
        args.extend(extra);
        let o = opencrg(&args, None);
        assert!(o.status.success(), "{name}: {}", text(&o.stderr));
        assert!(out.metadata().unwrap().len() > 100, "{name}");
    }
    // The STL of u 5..20 at 0.5 m: 31 nodes along, 13 sections across, 2 triangles a cell
    // (the road's one NaN node at u = 10 takes the cells around it with it).
    let stl = std::fs::read(d.join("m.stl")).unwrap();
    let triangles = u32::from_le_bytes(stl[80..84].try_into().unwrap()) as usize;
    assert_eq!(stl.len(), 84 + 50 * triangles);
    assert!((2 * 30 * 12 - 18..2 * 30 * 12).contains(&triangles), "{triangles}");
    // Simplified within 5 cm: fewer triangles than the full mesh of the whole road.
    let full = std::fs::read(d.join("m.obj")).unwrap();
    let full_triangles = full.split(|&b| b == b'\n').filter(|l| l.starts_with(b"f ")).count();
    let stl = std::fs::read(d.join("s.stl")).unwrap();
    let simplified = u32::from_le_bytes(stl[80..84].try_into().unwrap()) as usize;
    assert!(simplified > 0 && simplified < full_triangles, "{simplified} of {full_triangles}");
    // The height map: 16-bit grey, one pixel per node, the z range in its text.
    let png = std::fs::read(d.join("h.png")).unwrap();
    assert_eq!(&png[12..16], b"IHDR");
    assert_eq!((u32::from_be_bytes(png[16..20].try_into().unwrap()), png[24], png[25]), (61, 16, 0));
    assert!(png.windows(6).any(|w| w == b"z_min\0"));
    for (args, expected) in [
        (vec!["export", r, "x.gltf"], "unknown export format"),
        (vec!["export", r, "x.obj", "--normal-map"], "must be a .png"),
        (vec!["export", r, "x.obj", "--u", "100:200"], "fewer than two grid nodes"),
        (vec!["export", r, "x.obj", "--u", "a:b"], "expected FROM:TO"),
        (vec!["export", r, "x.obj", "--max-error", "0"], "positive number"),
        (vec!["export", r, "x.png", "--max-error", "0.01"], "only for a mesh"),
    ] {
        let o = opencrg(&args, None);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = text(&o.stderr);
        assert!(err.contains(expected) && err.lines().last().unwrap().starts_with("opencrg: "), "{err}");
    }
    assert!(!Path::new("x.obj").exists() && !Path::new("x.gltf").exists());
}

/// A road in UTM zone 32U near 48 N 11.7 E; `keywords` adds WGS 84 start keywords.
fn georeferenced_road(d: &Path, keywords: &str) -> PathBuf {
    let header = format!(
        "$ROAD_CRG\nREFERENCE_LINE_OFFSET_X = 691000.0\nREFERENCE_LINE_OFFSET_Y = 5322000.0\n\
         REFERENCE_LINE_OFFSET_PHI = 0.2\n{keywords}$\n$ROAD_CRG_MPRO\nPROJ_NM = 'UTM_32U'\n$\n"
    );
    let p = d.join("earth.crg");
    std::fs::write(
        &p,
        RoadSpec::straight(40.0, 3.0, 0.5, 0.5).starting_at(2.0, 1.0, 0.5).with_header_text(&header).to_crg(),
    )
    .unwrap();
    p
}

#[test]
fn info_check_and_geojson_place_the_road_on_the_earth() {
    let d = dir("earth");
    let path = georeferenced_road(&d, "");
    let road = Road::load(&path).unwrap();
    let earth = opencrg_core::Earth::of(&road).unwrap();
    let l = road.reference_line();
    let [lat, lon, _] = earth.xyz_to_llh(&road, [l.x[0], l.y[0], l.z_at(0)]).unwrap();
    let info = text(&opencrg(&["info", path.to_str().unwrap()], None).stdout);
    assert!(info.contains(&format!("lat {lat:.9}, lon {lon:.9}")), "{info}");
    assert!(info.contains("UTM_32U on WGS84, NOP to WGS84"), "{info}");

    let out = d.join("earth.geojson");
    let done = opencrg(&["export", path.to_str().unwrap(), out.to_str().unwrap()], None);
    assert!(done.status.success(), "{}", text(&done.stderr));
    let doc: serde_json::Value = serde_json::from_slice(&std::fs::read(&out).unwrap()).unwrap();
    let line = doc["features"][0]["geometry"]["coordinates"].as_array().unwrap();
    assert_eq!(line.len(), l.n);
    assert!((line[0][0].as_f64().unwrap() - lon).abs() < 1e-12 && (line[0][1].as_f64().unwrap() - lat).abs() < 1e-12);
    let ring = doc["features"][1]["geometry"]["coordinates"][0].as_array().unwrap();
    assert_eq!((ring.len(), &ring[0]), (2 * l.n + 1, &ring[2 * l.n]));

    // WGS 84 keywords 30 m off the projected start: check warns, naming both places.
    let far = format!("REFERENCE_LINE_START_LAT = {}\nREFERENCE_LINE_START_LON = {lon}\n", lat + 30.0 / 111_195.0);
    let path = georeferenced_road(&d, &far);
    let checked = opencrg(&["check", path.to_str().unwrap()], None);
    let warning = text(&checked.stderr);
    assert!(
        warning.contains("WGS 84 start") && warning.contains("CHECK_PRO") && warning.contains("reference line's start")
    );
    let near = format!("REFERENCE_LINE_START_LAT = {lat}\nREFERENCE_LINE_START_LON = {lon}\n");
    let path = georeferenced_road(&d, &near);
    let quiet = text(&opencrg(&["check", path.to_str().unwrap()], None).stderr);
    assert!(!quiet.contains("WGS 84"), "{quiet}");

    // A road without a projection: one line, status 2, no file.
    let plain = write_road(&d);
    let refused = d.join("plain.geojson");
    let done = opencrg(&["export", plain.to_str().unwrap(), refused.to_str().unwrap()], None);
    assert_eq!(done.status.code(), Some(2));
    assert_eq!(text(&done.stderr).lines().count(), 1, "{}", text(&done.stderr));
    assert!(!refused.exists());
    std::fs::remove_dir_all(&d).unwrap();
}

/// A curved line through points 2 m apart (y = 10 sin(x / 25)), climbing 2 %.
fn line_csv(d: &Path) -> PathBuf {
    let p = d.join("line.csv");
    let mut text = String::from("x,y,z\n");
    for i in 0..=60 {
        let x = 2.0 * i as f64;
        text.push_str(&format!("{x},{},{}\n", 10.0 * (x / 25.0).sin(), 0.02 * x));
    }
    std::fs::write(&p, text).unwrap();
    p
}

fn ok(args: &[&str]) -> String {
    let out = opencrg(args, None);
    assert!(out.status.success(), "{args:?}: {}", text(&out.stderr));
    text(&out.stdout)
}

/// The command's comparison of two roads: (largest difference, nodes compared).
fn difference(a: &Path, b: &Path) -> (f64, u64) {
    let j: serde_json::Value =
        serde_json::from_str(&ok(&["compare", a.to_str().unwrap(), b.to_str().unwrap(), "--json"])).unwrap();
    (j["max_difference"].as_f64().unwrap(), j["compared"].as_u64().unwrap())
}

#[test]
fn road_tools_keep_the_surface_where_it_was() {
    let d = dir("tools");
    let s = |p: &Path| p.to_str().unwrap().to_string();
    let line = line_csv(&d);
    let road = d.join("road.crg");
    ok(&[
        "generate",
        &s(&road),
        "--refline",
        &s(&line),
        "--width",
        "4",
        "--u-inc",
        "0.1",
        "--v-inc",
        "0.25",
        "--surface",
        "0.01*sin(2*u)*cos(v) + 0.02*v",
    ]);
    let r = Road::load(&road).unwrap();
    assert!(r.header().comments.iter().any(|c| c.contains("generated by opencrg")));
    assert_eq!(r.grid().nv, 17);
    let p = |name: &str| d.join(name);
    ok(&["cut", &s(&road), &s(&p("cut.crg")), "--u", "10:60", "--v", "-1:1.5", "--format", "KRBI"]);
    assert_eq!(Road::load(p("cut.crg")).unwrap().format(), opencrg_core::DataFormat::Krbi);
    ok(&["flip", &s(&road), &s(&p("flip.crg"))]);
    ok(&["cut", &s(&road), &s(&p("a.crg")), "--u", "0:45.5"]);
    ok(&["cut", &s(&road), &s(&p("b.crg")), "--u", "45.5:500"]);
    ok(&["append", &s(&p("a.crg")), &s(&p("b.crg")), &s(&p("ab.crg"))]);
    ok(&["resample", &s(&road), &s(&p("fine.crg")), "--u-inc", "0.05"]);
    ok(&["slope", &s(&road), &s(&p("applied.crg")), "--apply"]);
    ok(&["banking", &s(&p("applied.crg")), &s(&p("banked.crg")), "--extract"]);
    // The two cuts appended: the road with its turn at the joint taken out, the same surface
    // in u and v.
    let (whole, joined) =
        (opencrg_core::ContactPoint::new(std::sync::Arc::new(r.clone())), Road::load(p("ab.crg")).unwrap());
    let joined = opencrg_core::ContactPoint::new(std::sync::Arc::new(joined));
    for u in [1.0, 30.0, 45.5, 60.0, 90.0] {
        for v in [-1.9, 0.0, 1.9] {
            let (a, b) = (whole.uv_to_z(u, v).unwrap(), joined.uv_to_z(u, v).unwrap());
            assert!((a - b).abs() < 1e-4, "ab.crg at u {u} v {v}: {a} {b}");
        }
    }
    for (made, reverse) in
        [("cut.crg", false), ("flip.crg", true), ("fine.crg", false), ("applied.crg", true), ("banked.crg", true)]
    {
        let (worst, n) = difference(&road, &p(made));
        assert!(n > 1000 && worst < 1e-4, "{made}: {worst} over {n}");
        if reverse {
            let (worst, _) = difference(&p(made), &road);
            assert!(worst < 1e-4, "{made} against the road: {worst}");
        }
    }
    // The filtered surface differs, and compare says by how much.
    ok(&["filter", &s(&road), &s(&p("limited.crg")), "--limit", "-0.01:0.01"]);
    let (worst, _) = difference(&road, &p("limited.crg"));
    assert!(worst > 0.01 && worst < 0.04, "{worst}");
    let out = opencrg(&["compare", &s(&road), &s(&p("limited.crg")), "--tolerance", "0.001"], None);
    assert_eq!(out.status.code(), Some(1));
}

#[test]
fn a_point_cloud_becomes_a_road() {
    let d = dir("import");
    let s = |p: &Path| p.to_str().unwrap().to_string();
    let cloud = d.join("cloud.xyz");
    let mut points = String::new();
    for i in 0..400 {
        for j in 0..60 {
            let (x, y) = (i as f64 * 0.1 + 0.03 * ((i * j) % 7) as f64 / 7.0, -3.0 + j as f64 * 0.1);
            points.push_str(&format!("{x} {y} {}\n", 5.0 + 0.02 * x + 0.05 * (y / 2.0).sin()));
        }
    }
    std::fs::write(&cloud, points).unwrap();
    let out_road = d.join("scan.crg");
    ok(&["import", &s(&cloud), &s(&out_road), "--u-inc", "0.2", "--v-inc", "0.2"]);
    let r = Arc::new(Road::load(&out_road).unwrap());
    let cp = ContactPoint::new(r.clone());
    let (mut worst, mut n) = (0.0f64, 0);
    for iu in 0..r.grid().nu {
        for &v in &r.grid().v {
            let u = r.reference_line().u_at(iu);
            let (x, y) = cp.uv_to_xy(u, v).unwrap();
            let z = cp.uv_to_z(u, v).unwrap();
            if !z.is_nan() {
                worst = worst.max((z - (5.0 + 0.02 * x + 0.05 * (y / 2.0).sin())).abs());
                n += 1;
            }
        }
    }
    assert!(n > 2000 && worst < 0.002, "{worst} over {n}");
    // A line beyond the cloud: one line, status 2, nothing written.
    let line = d.join("far.csv");
    std::fs::write(&line, "x y\n100 0\n200 0\n").unwrap();
    let far = d.join("far.crg");
    let out = opencrg(
        &["import", &s(&cloud), &s(&far), "--refline", &s(&line), "--width", "2", "--u-inc", "0.5", "--v-inc", "0.5"],
        None,
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("beyond the cloud"), "{}", text(&out.stderr));
    assert!(!far.exists());
}

#[test]
fn road_tools_refuse_bad_input_in_one_line() {
    let d = dir("tools-bad");
    let s = |p: &Path| p.to_str().unwrap().to_string();
    let road = write_road(&d);
    let out_path = d.join("out.crg");
    let no_xy = d.join("no_xy.csv");
    std::fs::write(&no_xy, "a,b\n1,2\n3,4\n").unwrap();
    for args in [
        vec!["cut".to_string(), s(&road), s(&out_path), "--u".into(), "100:200".into()],
        vec!["resample".into(), s(&road), s(&out_path), "--u-inc".into(), "0".into()],
        vec!["filter".into(), s(&road), s(&out_path), "--median".into(), "4".into()],
        vec![
            "generate".into(),
            s(&out_path),
            "--refline".into(),
            s(&no_xy),
            "--width".into(),
            "3".into(),
            "--u-inc".into(),
            "0.1".into(),
            "--v-inc".into(),
            "0.5".into(),
        ],
        vec![
            "generate".into(),
            s(&out_path),
            "--refline".into(),
            s(&no_xy),
            "--width".into(),
            "3".into(),
            "--u-inc".into(),
            "0.1".into(),
            "--v-inc".into(),
            "0.5".into(),
            "--surface".into(),
            "u +".into(),
        ],
    ] {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = opencrg(&args, None);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let e = text(&out.stderr);
        assert_eq!(e.lines().count(), 1, "{args:?}: {e}");
        assert!(!out_path.exists(), "{args:?}");
    }
}

#[test]
fn a_group_of_commands_names_every_one_of_them() {
    let help = ok(&["odr", "--help"]);
    let summary = help.lines().next().unwrap();
    let commands: Vec<&str> = help
        .split("Commands:")
        .nth(1)
        .unwrap()
        .lines()
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        // Command lines are indented by two spaces, their wrapped text by more.
        .filter(|l| l.starts_with("  ") && !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|&c| c != "help")
        .collect();
    assert!(commands.len() >= 6, "{help}");
    for c in commands {
        assert!(
            summary.contains(c),
            "`opencrg odr --help` names {c} among its commands but not in its first line: {summary}"
        );
    }
}

/// `opencrg fmu` packs with the binaries of a folder named, and refuses in one line what
/// it cannot pack, writing nothing.
#[test]
fn fmu_packs_a_road_and_refuses_in_one_line() {
    let d = dir("fmu");
    let road = write_road(&d);
    let binaries = d.join("binaries/x86_64-linux");
    std::fs::create_dir_all(&binaries).unwrap();
    std::fs::write(binaries.join("libopencrg_fmi.so"), b"a stand-in").unwrap();
    let folder = d.join("binaries");
    let out = d.join("road.fmu");
    let args = ["fmu", road.to_str().unwrap(), out.to_str().unwrap(), "--binaries", folder.to_str().unwrap()];
    let done = opencrg(&[&args[..], &["--wheels", "2", "--fmi", "3"]].concat(), None);
    assert!(done.status.success(), "{}", text(&done.stderr));
    let said = text(&done.stderr);
    assert!(said.contains("FMI 3.0") && said.contains("2 wheels") && said.contains("x86_64-linux"), "{said}");
    assert!(out.metadata().unwrap().len() > 1000);
    let refused = d.join("refused.fmu");
    for extra in [vec!["--wheels", "0"], vec!["--wheels", "1000"], vec!["--fmi", "4"]] {
        let mut args = args.to_vec();
        args[2] = refused.to_str().unwrap();
        let done = opencrg(&[&args[..], &extra[..]].concat(), None);
        assert_eq!(done.status.code(), Some(2), "{extra:?}");
        assert_eq!(text(&done.stderr).trim().lines().count(), 1, "{extra:?}: {}", text(&done.stderr));
        assert!(!refused.exists());
    }
    let empty = d.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let done = opencrg(
        &["fmu", road.to_str().unwrap(), refused.to_str().unwrap(), "--binaries", empty.to_str().unwrap()],
        None,
    );
    assert_eq!(done.status.code(), Some(2));
    assert!(text(&done.stderr).contains("no FMU binary"), "{}", text(&done.stderr));
    let done =
        opencrg(&["fmu", "/no/such/road.crg", refused.to_str().unwrap(), "--binaries", folder.to_str().unwrap()], None);
    assert_eq!(done.status.code(), Some(2));
    assert!(text(&done.stderr).contains("/no/such/road.crg"), "{}", text(&done.stderr));
    assert!(!refused.exists());
}
