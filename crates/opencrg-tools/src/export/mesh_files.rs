//! Meshes as files: Wavefront OBJ (text, with normals and texture coordinates), binary
//! STL, binary PLY (double positions, float normals and texture coordinates), binary
//! glTF 2.0 (`.glb`: y up, positions relative to the node's translation). Written to
//! a temporary file beside the target and renamed into place: a failed write leaves no
//! half-written file.

use crate::export::mesh::Mesh;
use opencrg_core::{Error, Result};
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

/// The mesh file formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshFormat {
    /// Wavefront OBJ.
    Obj,
    /// Binary STL (single precision, no normals per vertex).
    Stl,
    /// Binary little-endian PLY.
    Ply,
    /// Binary glTF 2.0 (`.glb`).
    Glb,
}

impl MeshFormat {
    /// The format a file name's extension names (in any case), if any.
    pub fn from_path(path: &Path) -> Option<Self> {
        match path.extension()?.to_str()?.to_ascii_lowercase().as_str() {
            "obj" => Some(MeshFormat::Obj),
            "stl" => Some(MeshFormat::Stl),
            "ply" => Some(MeshFormat::Ply),
            "glb" => Some(MeshFormat::Glb),
            _ => None,
        }
    }
}

/// Writes `mesh` to `path` in `format`.
pub fn write_mesh(mesh: &Mesh, path: &Path, format: MeshFormat) -> Result<()> {
    write_whole(path, |out| write_mesh_to(mesh, out, format))
}

/// Writes a file whole or not at all: `write` fills a temporary file beside `path`, which
/// is then renamed to it; on any error the temporary file is removed and `path` untouched.
pub fn write_whole(path: &Path, write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>) -> Result<()> {
    let mut tmp_name = path.file_name().unwrap_or_default().to_os_string();
    tmp_name.push(".part");
    let tmp = path.with_file_name(tmp_name);
    let written = (|| {
        let mut out = BufWriter::with_capacity(1 << 20, File::create(&tmp)?);
        write(&mut out)?;
        out.into_inner().map_err(|e| e.into_error())?.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if written.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    written.map_err(|source| Error::writing(path, source))
}

/// Writes `mesh` in `format` to any writer.
pub fn write_mesh_to(mesh: &Mesh, out: &mut impl Write, format: MeshFormat) -> io::Result<()> {
    match format {
        MeshFormat::Obj => obj(mesh, out),
        MeshFormat::Stl => stl(mesh, out),
        MeshFormat::Ply => ply(mesh, out),
        MeshFormat::Glb => crate::export::gltf::glb(mesh, out),
    }
}

fn obj(mesh: &Mesh, out: &mut impl Write) -> io::Result<()> {
    writeln!(out, "# road surface written by opencrg {}", env!("CARGO_PKG_VERSION"))?;
    for p in &mesh.positions {
        writeln!(out, "v {} {} {}", p[0], p[1], p[2])?;
    }
    for n in &mesh.normals {
        writeln!(out, "vn {} {} {}", n[0], n[1], n[2])?;
    }
    for t in &mesh.texcoords {
        writeln!(out, "vt {} {}", t[0], t[1])?;
    }
    let face = |out: &mut dyn Write, t: &[u32; 3]| {
        let [a, b, c] = t.map(|i| i + 1);
        writeln!(out, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}")
    };
    if mesh.groups.is_empty() {
        for t in &mesh.triangles {
            face(out, t)?;
        }
    }
    for g in &mesh.groups {
        writeln!(out, "g {}", g.name.replace(char::is_whitespace, "_"))?;
        for t in &mesh.triangles[g.triangles.clone()] {
            face(out, t)?;
        }
    }
    Ok(())
}

fn stl(mesh: &Mesh, out: &mut impl Write) -> io::Result<()> {
    let mut header = [0u8; 80];
    let text = format!("road surface written by opencrg {}", env!("CARGO_PKG_VERSION"));
    header[..text.len()].copy_from_slice(text.as_bytes());
    out.write_all(&header)?;
    let count =
        u32::try_from(mesh.triangles.len()).map_err(|_| io::Error::other("more triangles than STL can count"))?;
    out.write_all(&count.to_le_bytes())?;
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let (e, f) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
        let n = [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]];
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let n = if len > 0.0 { n.map(|x| x / len) } else { [0.0, 0.0, 1.0] };
        for vector in [n, a, b, c] {
            for x in vector {
                out.write_all(&(x as f32).to_le_bytes())?;
            }
        }
        out.write_all(&[0, 0])?;
    }
    Ok(())
}

fn ply(mesh: &Mesh, out: &mut impl Write) -> io::Result<()> {
    let extra: String = mesh.values.iter().map(|v| format!("property float {}\n", v.name)).collect();
    write!(
        out,
        "ply\nformat binary_little_endian 1.0\ncomment road surface written by opencrg {}\n\
         element vertex {}\nproperty double x\nproperty double y\nproperty double z\n\
         property float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\n{extra}\
         element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
        env!("CARGO_PKG_VERSION"),
        mesh.positions.len(),
        mesh.triangles.len()
    )?;
    for (i, ((p, n), t)) in mesh.positions.iter().zip(&mesh.normals).zip(&mesh.texcoords).enumerate() {
        for x in p {
            out.write_all(&x.to_le_bytes())?;
        }
        for x in n.iter().chain(t).chain(mesh.values.iter().map(|v| &v.values[i])) {
            out.write_all(&x.to_le_bytes())?;
        }
    }
    for t in &mesh.triangles {
        out.write_all(&[3])?;
        for i in t {
            out.write_all(&i.to_le_bytes())?;
        }
    }
    Ok(())
}
