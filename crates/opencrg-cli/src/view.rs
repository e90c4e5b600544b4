//! `opencrg view` and `opencrg odr view`: the toolkit's 3D view written to one file.

use opencrg_tools::mesh_files::write_whole;
use opencrg_tools::view::View;
use std::io::Write;
use std::path::Path;

/// Writes `view` to `out`; what was written.
pub fn write(view: &View, out: &Path) -> Result<String, String> {
    write_whole(out, |w| w.write_all(view.page.as_bytes())).map_err(|e| e.to_string())?;
    Ok(format!("{}: {} vertices, {} triangles", out.display(), view.vertices, view.triangles))
}
