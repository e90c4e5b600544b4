//! The command's figures. Each is drawn once, with plotters on its SVG back end (axes,
//! ticks at 1-2-5 steps, grids, legends; text stays text), and written as SVG or, for
//! any other extension, rasterised to PNG by resvg with the embedded DejaVu Sans
//! (antialiased lines and text). A figure may carry a raster under its drawing: the
//! pixels of a top view, embedded in the SVG as a PNG image.

mod raster;
mod ticks;

pub use opencrg_tools::drawing::{decade_label, tick_label, ticks};
pub use ticks::round_length;

use plotters::chart::MeshStyle;
use plotters::coord::ranged1d::Ranged;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::{CoordTranslate, Shift};
use plotters::prelude::*;
use std::path::Path;

/// The family every text of a figure names; resvg renders it with DejaVu Sans, SVG
/// viewers with their own sans-serif face.
pub const FAMILY: &str = "sans-serif";
/// Text sizes in plotters' points (the SVG's pixels are 1/1.24 of them): titles, axis
/// titles, tick labels and legends.
pub const TITLE: f64 = 20.0;
/// Axis titles.
pub const AXIS: f64 = 17.0;
/// Tick labels and legends.
pub const LABEL: f64 = 15.0;

/// The drawing area of a figure being drawn.
pub type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// Pixels placed under a figure's drawing, one per unit of the figure.
pub struct Image {
    /// Top left corner in the figure.
    pub x: u32,
    /// Top left corner in the figure.
    pub y: u32,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGBA, row by row from the top; alpha 0 or 255.
    pub rgba: Vec<u8>,
}

/// A finished figure.
pub struct Figure {
    width: u32,
    height: u32,
    /// The SVG elements plotters drew, without the document around them.
    body: String,
    image: Option<Image>,
}

/// Makes `plotters` measure text with DejaVu Sans (what resvg draws it with).
fn register_font() -> Result<(), String> {
    static REGISTERED: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| register_font_bytes(FontStyle::Normal) && register_font_bytes(FontStyle::Bold));
    if ok {
        Ok(())
    } else {
        Err("the embedded font could not be read".into())
    }
}

fn register_font_bytes(style: FontStyle) -> bool {
    let bytes = match style {
        FontStyle::Bold => dejavu::sans::bold(),
        _ => dejavu::sans::regular(),
    };
    plotters::style::register_font(FAMILY, style, bytes).is_ok()
}

/// Text style of `size` pixels.
pub fn font(size: f64) -> TextStyle<'static> {
    (FAMILY, size).into_font().into()
}

/// The grid's lines at the labelled ticks and between them.
const GRID: RGBColor = RGBColor(205, 205, 205);
const GRID_FINE: RGBColor = RGBColor(238, 238, 238);

/// An axis mesh's text in the figures' sizes: tick labels and axis titles.
pub fn lettered<'m, 'a, 'b, X: Ranged, Y: Ranged>(
    mesh: &'m mut MeshStyle<'a, 'b, X, Y, SVGBackend<'a>>,
) -> &'m mut MeshStyle<'a, 'b, X, Y, SVGBackend<'a>> {
    mesh.label_style(font(LABEL)).axis_desc_style(font(AXIS))
}

/// An axis over a..b whose ticks (and the finer grid's lines) lie at the drawing rules'
/// round steps, as many as the axis asks for at most.
#[derive(Clone)]
pub struct Ruled(RangedCoordf64);

/// The axis a..b ticked by the drawing rules.
pub fn ruled(a: f64, b: f64) -> Ruled {
    Ruled((a..b).into())
}

impl Ranged for Ruled {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.0.map(value, limit)
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        let range = self.0.range();
        ticks(range.start, range.end, hint.max_num_points())
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.0.range()
    }
}

/// [`lettered`], and the grid in the figures' greys.
pub fn gridded<'m, 'a, 'b, X: Ranged, Y: Ranged>(
    mesh: &'m mut MeshStyle<'a, 'b, X, Y, SVGBackend<'a>>,
) -> &'m mut MeshStyle<'a, 'b, X, Y, SVGBackend<'a>> {
    lettered(mesh).bold_line_style(GRID).light_line_style(GRID_FINE)
}

/// The chart's legend of its labelled series, in its upper right corner.
pub fn legend<'a, CT: CoordTranslate>(chart: &mut ChartContext<'a, SVGBackend<'a>, CT>) -> Result<(), String> {
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.9))
        .border_style(RGBColor(160, 160, 160))
        .label_font(font(LABEL))
        .draw()
        .map_err(failed)
}

/// A drawing error of plotters, as the command's message.
pub fn failed<E: std::fmt::Display>(e: E) -> String {
    format!("drawing the figure: {e}")
}

impl Figure {
    /// Draws a figure of `width` x `height` pixels with `draw`, over `image` if given.
    pub fn draw(
        width: u32,
        height: u32,
        image: Option<Image>,
        draw: impl FnOnce(&Area) -> Result<(), String>,
    ) -> Result<Figure, String> {
        register_font()?;
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area();
            draw(&root)?;
            root.present().map_err(failed)?;
        }
        // plotters writes <svg ...> elements </svg>; the document is made anew around them.
        let start = svg.find('>').map_or(0, |i| i + 1);
        let end = svg.rfind("</svg>").unwrap_or(svg.len());
        Ok(Figure { width, height, body: svg[start..end].trim().to_string(), image })
    }

    /// The SVG document of the drawing, with `ground` the white ground and the image
    /// under it (the PNG path draws those itself).
    fn document(&self, ground: bool) -> Result<String, String> {
        let (w, h) = (self.width, self.height);
        let mut out = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" \
             width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n"
        );
        if ground {
            out.push_str(&format!("<rect width=\"{w}\" height=\"{h}\" fill=\"#FFFFFF\"/>\n"));
            if let Some(image) = &self.image {
                out.push_str(&raster::svg_image(image)?);
            }
        }
        out.push_str(&self.body);
        out.push_str("\n</svg>\n");
        Ok(out)
    }

    /// The SVG document: white ground, the image, the drawing.
    pub fn svg(&self) -> Result<String, String> {
        self.document(true)
    }

    /// The picture as PNG bytes: the image, then the drawing rasterised over it.
    pub fn png(&self) -> Result<Vec<u8>, String> {
        raster::png(self.width, self.height, self.image.as_ref(), &self.document(false)?)
    }

    /// Writes the figure: SVG for a `.svg` path, PNG otherwise; nothing is left behind
    /// when drawing fails.
    pub fn write(&self, path: &Path) -> Result<(), String> {
        let svg = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("svg"));
        let bytes = if svg { self.svg()?.into_bytes() } else { self.png()? };
        std::fs::write(path, bytes).map_err(|e| format!("{}: {e}", path.display()))
    }
}
