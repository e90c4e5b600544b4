//! From SVG to pixels with resvg and the embedded font, and a figure's image as an SVG
//! element.

use super::Image;
use base64::Engine;
use resvg::tiny_skia::{Pixmap, PixmapPaint, PixmapRef, Transform};
use resvg::usvg;

/// The image's pixels as a pixmap, without a copy (premultiplied as they stand: each is
/// opaque or fully transparent).
fn pixmap(image: &Image) -> Result<PixmapRef<'_>, String> {
    PixmapRef::from_bytes(&image.rgba, image.width, image.height)
        .ok_or_else(|| "an image of the wrong size".to_string())
}

/// The image as an `<image>` element holding a PNG, drawn without smoothing.
pub fn svg_image(image: &Image) -> Result<String, String> {
    let png = pixmap(image)?.encode_png().map_err(|e| format!("encoding the image: {e}"))?;
    Ok(format!(
        "<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" preserveAspectRatio=\"none\" \
         style=\"image-rendering:pixelated\" xlink:href=\"data:image/png;base64,{}\"/>\n",
        image.x,
        image.y,
        image.width,
        image.height,
        base64::engine::general_purpose::STANDARD.encode(png)
    ))
}

/// The options that make usvg find DejaVu Sans for every sans-serif text.
fn options() -> usvg::Options<'static> {
    let mut options = usvg::Options { font_family: "DejaVu Sans".into(), ..Default::default() };
    let fonts = options.fontdb_mut();
    fonts.load_font_data(dejavu::sans::regular().to_vec());
    fonts.load_font_data(dejavu::sans::bold().to_vec());
    fonts.set_sans_serif_family("DejaVu Sans");
    options
}

/// `document` rasterised at one pixel per unit over a white ground and `image`, as PNG.
pub fn png(width: u32, height: u32, image: Option<&Image>, document: &str) -> Result<Vec<u8>, String> {
    let tree = usvg::Tree::from_str(document, &options()).map_err(|e| format!("rasterising the figure: {e}"))?;
    let mut canvas = Pixmap::new(width, height).ok_or("a figure without pixels")?;
    canvas.fill(resvg::tiny_skia::Color::WHITE);
    if let Some(image) = image {
        let pixels = pixmap(image)?;
        canvas.draw_pixmap(
            image.x as i32,
            image.y as i32,
            pixels,
            &PixmapPaint::default(),
            Transform::identity(),
            None,
        );
    }
    resvg::render(&tree, Transform::identity(), &mut canvas.as_mut());
    canvas.encode_png().map_err(|e| format!("encoding the figure: {e}"))
}
