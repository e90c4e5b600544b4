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

/// `opencrg view`: the 3D view of the road (or a part) as one HTML page.
pub(crate) fn run(
    road: &Path,
    output: &Path,
    (u, v): (crate::export::Range, crate::export::Range),
    max_vertices: usize,
    options: &crate::eval_options::EvalOptions,
    budget: &opencrg_core::Budget,
) -> Result<(), String> {
    let cp = crate::eval_options::contact_point(road, options)?;
    let shown = opencrg_tools::view::road_view(&cp, &crate::files::file_name(road), u, v, max_vertices, budget)
        .map_err(|e| format!("{}: {e}", road.display()))?;
    eprintln!("{}", write(&shown, output)?);
    Ok(())
}
