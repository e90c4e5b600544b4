//! The command's figures as SVG (text as text: titles, axis titles with units, tick
//! labels, class letters, legends) and as PNG (the SVG's size, antialiased), and the
//! guide's pictures equal to what `docs/figures.sh` draws with this command.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("opencrg-figures-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn opencrg(args: &[&str]) {
    let out = Command::new(env!("CARGO_BIN_EXE_opencrg")).args(args).output().unwrap();
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
}

/// A `<text>` element: where it is anchored and what it says.
#[derive(Debug)]
struct Text {
    x: f64,
    y: f64,
    content: String,
}

fn attribute(tag: &str, name: &str) -> Option<String> {
    let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    Some(tag[start..].split('"').next()?.to_string())
}

/// Every text element of an SVG document.
fn texts(svg: &str) -> Vec<Text> {
    let mut found = Vec::new();
    let mut rest = svg;
    while let Some(start) = rest.find("<text") {
        let tag_end = start + rest[start..].find('>').unwrap();
        let close = tag_end + rest[tag_end..].find("</text>").unwrap();
        let tag = &rest[start..tag_end];
        let content = rest[tag_end + 1..close].trim().replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&");
        let number = |name| attribute(tag, name).and_then(|v| v.parse::<f64>().ok()).unwrap();
        found.push(Text { x: number("x"), y: number("y"), content });
        rest = &rest[close..];
    }
    found
}

/// The number a tick label shows: plain, or a power of ten with a superscript exponent.
fn value(label: &str) -> Option<f64> {
    if let Ok(v) = label.parse::<f64>() {
        return Some(v);
    }
    let exponent: String = label
        .strip_prefix("10")?
        .chars()
        .map(|c| match c {
            '\u{207B}' => Some('-'),
            '\u{00B9}' => Some('1'),
            '\u{00B2}' => Some('2'),
            '\u{00B3}' => Some('3'),
            c => char::from_digit(u32::from(c).checked_sub(0x2070)?, 10),
        })
        .collect::<Option<String>>()?;
    Some(10f64.powi(exponent.parse().ok()?))
}

fn is_decade(v: f64) -> bool {
    (v.log10() - v.log10().round()).abs() < 1e-9
}

/// The tick labels of the figure's axes: numeric labels sharing a y (a horizontal axis)
/// or an x (a vertical one) without a wide gap between them (panels one above the other
/// share their axes' x), two or more of them, each axis's values in order.
fn axes(texts: &[Text]) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let mut rows: BTreeMap<i64, Vec<(f64, f64)>> = BTreeMap::new();
    let mut columns: BTreeMap<i64, Vec<(f64, f64)>> = BTreeMap::new();
    for t in texts {
        if let Some(v) = value(&t.content) {
            rows.entry(t.y.round() as i64).or_default().push((t.x, v));
            columns.entry(t.x.round() as i64).or_default().push((t.y, v));
        }
    }
    let ordered = |groups: BTreeMap<i64, Vec<(f64, f64)>>, gap: f64| -> Vec<Vec<f64>> {
        let mut axes = Vec::new();
        for mut g in groups.into_values() {
            g.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut axis: Vec<f64> = Vec::new();
            for (k, p) in g.iter().enumerate() {
                if k > 0 && p.0 - g[k - 1].0 > gap {
                    axes.push(std::mem::take(&mut axis));
                }
                axis.push(p.1);
            }
            axes.push(axis);
        }
        axes.retain(|a| a.len() >= 2);
        axes
    };
    (ordered(rows, 300.0), ordered(columns, 100.0))
}

/// The image's width, height and RGBA pixels.
fn decode(path: &Path) -> (u32, u32, Vec<[u8; 4]>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.color_type, info.bit_depth), (png::ColorType::Rgba, png::BitDepth::Eight), "{}", path.display());
    let pixels = buf[..info.buffer_size()].chunks(4).map(|p| [p[0], p[1], p[2], p[3]]).collect();
    (info.width, info.height, pixels)
}

/// Draws the figure of `args` (whose output name ends in `stem`) as SVG and as PNG; checks
/// that the PNG has the SVG's size and antialiased edges (pixels blended between a
/// drawing's colour and the white ground); returns the SVG's texts.
fn both(d: &Path, args: &[&str], stem: &str) -> Vec<Text> {
    let (svg, png) = (d.join(format!("{stem}.svg")), d.join(format!("{stem}.png")));
    for out in [&svg, &png] {
        let args: Vec<&str> = args.iter().map(|a| if *a == "OUT" { out.to_str().unwrap() } else { a }).collect();
        opencrg(&args);
    }
    let document = std::fs::read_to_string(&svg).unwrap();
    assert!(document.starts_with("<svg"), "{stem}: {}", &document[..60.min(document.len())]);
    let size = |name| attribute(&document[..document.find('>').unwrap()], name).unwrap().parse::<u32>().unwrap();
    let (width, height, pixels) = decode(&png);
    assert_eq!((width, height), (size("width"), size("height")), "{stem}");
    assert!(pixels.iter().all(|p| p[3] == 255), "{stem}: transparent pixels");
    // Antialiasing: the edges of black text and lines on white blend into many grey
    // levels (drawn without it, the figures hold fewer than ten: black, white and the
    // flat greys of grids, frames and class lines).
    let greys: std::collections::BTreeSet<u8> =
        pixels.iter().filter(|p| p[0] == p[1] && p[1] == p[2]).map(|p| p[0]).collect();
    assert!(greys.len() >= 24, "{stem}: {} grey levels, not antialiased", greys.len());
    texts(&document)
}

fn has(texts: &[Text], content: &str) -> bool {
    texts.iter().any(|t| t.content == content)
}

#[test]
fn every_figure_comes_as_svg_with_its_text_and_as_antialiased_png() {
    let d = dir("all");
    let road = root().join("examples/data/demo_road.crg");
    let road = road.to_str().unwrap();

    // The top view: x and y axes, the colour bar, each with four tick labels or more.
    let top = both(&d, &["render", road, "OUT"], "top");
    assert!(top.iter().any(|t| t.content.starts_with("demo_road.crg")), "{top:?}");
    for title in ["x [m]", "y [m]", "z [m]"] {
        assert!(has(&top, title), "top view: no axis title {title}");
    }
    let (rows, columns) = axes(&top);
    assert!(rows.iter().any(|r| r.len() >= 4 && r.windows(2).all(|w| w[0] < w[1])), "x axis: {rows:?}");
    assert!(columns.iter().filter(|c| c.len() >= 4).count() >= 2, "y axis and colour bar: {columns:?}");
    assert!(top.iter().any(|t| t.content.ends_with(" m") && value(&t.content[..t.content.len() - 2]).is_some()));

    // Sections across and along the road.
    for (section, along, words) in [("u=60", "v [m]", "across the road at u = 60 m"), ("v=0.5", "u [m]", "along")] {
        let figure = both(&d, &["render", road, "OUT", "--profile", section], &format!("profile-{}", &section[..1]));
        assert!(figure.iter().any(|t| t.content.starts_with("demo_road.crg") && t.content.contains(words)));
        assert!(has(&figure, along) && has(&figure, "z [m]"), "{section}: {figure:?}");
        let (rows, columns) = axes(&figure);
        assert!(rows.iter().any(|r| r.len() >= 4), "{section}: {rows:?}");
        assert!(columns.iter().any(|c| c.len() >= 4), "{section}: {columns:?}");
    }

    // The roughness figure: log-log densities with decade labels, the class letters,
    // a legend entry per track in both panels, the IRI's linear axes.
    let rough = both(&d, &["roughness", road, "--plot", "OUT"], "roughness");
    for title in ["n [cycles/m]", "Gd(n) [m³]", "u [m]", "IRI [m/km]"] {
        assert!(has(&rough, title), "roughness: no axis title {title}");
    }
    for letter in ["A", "B", "C", "D", "E", "F", "G", "H"] {
        assert!(has(&rough, letter), "roughness: no class letter {letter}");
    }
    for v in ["-0.85", "0", "0.85"] {
        let entries = rough.iter().filter(|t| t.content.starts_with(&format!("v = {v} m"))).count();
        assert_eq!(entries, 2, "legend entries of the track at v = {v}");
    }
    let (rows, columns) = axes(&rough);
    let decades = |axis: &Vec<f64>| axis.iter().filter(|v| is_decade(**v)).count() == axis.len() && axis.len() >= 3;
    assert!(rows.iter().any(decades), "n axis: {rows:?}");
    assert!(columns.iter().any(decades), "Gd axis: {columns:?}");
    assert!(rows.iter().any(|r| r.len() >= 4 && !decades(r)), "u axis: {rows:?}");
    assert!(columns.iter().any(|c| c.len() >= 4 && !decades(c)), "IRI axis: {columns:?}");
}

#[test]
fn the_guides_pictures_are_what_the_command_draws() {
    guides_pictures_drawn("docs", &["demo_road.png", "demo_map.png", "mode_genuine.png"]);
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_maps_the_guides_town_is_what_the_command_draws() {
    guides_pictures_drawn("docs-shared", &["town03.png"]);
}

/// Draws the guide's pictures with docs/figures.sh (`required` among them) and compares
/// each with the one in docs/.
fn guides_pictures_drawn(folder: &str, required: &[&str]) {
    let d = dir(folder);
    let status = Command::new("bash")
        .arg(root().join("docs/figures.sh"))
        .arg(&d)
        .env("OPENCRG", env!("CARGO_BIN_EXE_opencrg"))
        .status()
        .unwrap();
    assert!(status.success());
    let drawn: Vec<PathBuf> = std::fs::read_dir(&d).unwrap().map(|e| e.unwrap().path()).collect();
    assert!(drawn.len() >= 4, "{drawn:?}");
    for name in required {
        assert!(drawn.iter().any(|p| p.ends_with(name)), "{name} not drawn: {drawn:?}");
    }
    for new in drawn {
        let name = new.file_name().unwrap().to_str().unwrap().to_string();
        let (w, h, pixels) = decode(&new);
        let (w0, h0, shipped) = decode(&root().join("docs").join(&name));
        assert_eq!((w, h), (w0, h0), "docs/{name} differs in size from what docs/figures.sh draws: run it");
        // Rounding may move an antialiased edge by a level or two on another processor.
        let differ =
            pixels.iter().zip(&shipped).filter(|(a, b)| a.iter().zip(b.iter()).any(|(p, q)| p.abs_diff(*q) > 24));
        let count = differ.count();
        assert!(
            count * 1000 <= pixels.len(),
            "docs/{name}: {count} of {} pixels differ from what docs/figures.sh draws: run it",
            pixels.len()
        );
    }
}
