//! LAS and LAZ point clouds (through the `las` crate, with the `point-clouds` feature;
//! without it such files are refused, saying so).

use super::generate::Points;

#[cfg(feature = "point-clouds")]
mod read {
    use super::super::point_files::bad;
    use super::Points;
    use opencrg_core::{Error, Result};
    use std::path::Path;

    fn las_error(path: &Path) -> impl Fn(las::Error) -> Error + '_ {
        move |e| bad(path, 0, "LAS", e.to_string())
    }

    /// The points of a LAS or LAZ file.
    pub(crate) fn file(path: &Path) -> Result<Points> {
        let reader = las::Reader::from_path(path).map_err(las_error(path))?;
        let size = std::fs::metadata(path).map_or(0, |m| m.len());
        read_las(reader, path, size)
    }

    /// The points of LAS or LAZ `bytes`, read as a file called `name`.
    pub(crate) fn bytes(bytes: &[u8], name: &Path) -> Result<Points> {
        let reader = las::Reader::new(std::io::Cursor::new(bytes.to_vec())).map_err(las_error(name))?;
        read_las(reader, name, bytes.len() as u64)
    }

    /// The points of a LAS/LAZ reader over `size` bytes.
    fn read_las(mut reader: las::Reader, path: &Path, size: u64) -> Result<Points> {
        let err = las_error(path);
        // Room for what the file can hold at most (a point takes a byte at least, even
        // compressed), not for what its header claims.
        let n = reader.header().number_of_points().min(size) as usize;
        let mut points = Points { x: Vec::with_capacity(n), y: Vec::with_capacity(n), z: None };
        let mut z = Vec::with_capacity(n);
        let mut chunk = las::PointDataBuilder::new().for_header(reader.header()).build();
        // Chunks of 16 MB whatever the record length the header claims (up to 64 kB a point).
        let per_chunk = ((16u64 << 20) / u64::from(reader.header().point_format().len()).max(1)).max(1);
        while reader.fill_points(per_chunk, &mut chunk).map_err(&err)? > 0 {
            points.x.extend(chunk.x());
            points.y.extend(chunk.y());
            z.extend(chunk.z());
        }
        points.z = Some(z);
        Ok(points)
    }
}

#[cfg(not(feature = "point-clouds"))]
mod read {
    use super::super::point_files::bad;
    use super::Points;
    use opencrg_core::Result;
    use std::path::Path;

    fn refused(path: &Path) -> opencrg_core::Error {
        bad(
            path,
            0,
            "LAS",
            "LAS and LAZ files are read with opencrg-tools' feature point-clouds, which this build lacks",
        )
    }

    pub(crate) fn file(path: &Path) -> Result<Points> {
        Err(refused(path))
    }

    pub(crate) fn bytes(_bytes: &[u8], name: &Path) -> Result<Points> {
        Err(refused(name))
    }
}

pub(crate) use read::{bytes as read_bytes, file as read_file};
