//! Meshes as binary glTF 2.0 (`.glb`): one node holding one mesh, y up (glTF's x is the
//! road's x, its y the road's z, its z minus the road's y), positions relative to the
//! node's translation so that single precision keeps millimetres at survey coordinates;
//! normals and texture coordinates (u and v, scaled to 0..1) per vertex, and the mesh's
//! own values per vertex as attributes `_NAME`; triangles as 32-bit indices, one
//! primitive per group of the mesh (its name and what it is in the primitive's `extras`).

use crate::export::mesh::{json_string, Mesh, MeshGroup};
use std::io::{self, Write};

/// glTF's frame from the road's: (x, y, z) to (x, z, -y).
fn y_up(p: [f64; 3]) -> [f64; 3] {
    [p[0], p[2], -p[1]]
}

/// A JSON number: integers as such, others in Rust's shortest round-trip form.
fn num(x: f64) -> String {
    if x.is_finite() {
        format!("{x:?}")
    } else {
        "0".into()
    }
}

/// Writes `mesh` as a `.glb` file to `out`. Vertices without a position (NaN) are kept
/// (no triangle uses them) at the translation's origin.
pub(crate) fn glb(mesh: &Mesh, out: &mut impl Write) -> io::Result<()> {
    let n = mesh.positions.len();
    let Buffer { bin, total, origin, lo, hi, normals_at, texcoords_at, indices_at, values_at } = buffer(mesh);
    let f32s = |v: [f32; 3]| format!("[{},{},{}]", num(v[0].into()), num(v[1].into()), num(v[2].into()));
    // The parts: the mesh's groups with triangles, or one of every triangle.
    let whole = [MeshGroup { name: String::new(), triangles: 0..mesh.triangles.len(), extras: String::new() }];
    let groups: Vec<&MeshGroup> =
        if mesh.groups.is_empty() { whole.iter().collect() } else { mesh.groups.iter().collect() };
    let groups: Vec<&MeshGroup> = groups.into_iter().filter(|g| !g.triangles.is_empty()).collect();
    let mut views = vec![
        format!(r#"{{"buffer":0,"byteOffset":0,"byteLength":{},"target":34962}}"#, n * 12),
        format!(r#"{{"buffer":0,"byteOffset":{normals_at},"byteLength":{},"target":34962}}"#, n * 12),
        format!(r#"{{"buffer":0,"byteOffset":{texcoords_at},"byteLength":{},"target":34962}}"#, n * 8),
        format!(
            r#"{{"buffer":0,"byteOffset":{indices_at},"byteLength":{},"target":34963}}"#,
            mesh.triangles.len() * 12
        ),
    ];
    let mut accessors = vec![
        format!(
            r#"{{"bufferView":0,"componentType":5126,"count":{n},"type":"VEC3","min":{},"max":{}}}"#,
            f32s(lo),
            f32s(hi)
        ),
        format!(r#"{{"bufferView":1,"componentType":5126,"count":{n},"type":"VEC3"}}"#),
        format!(r#"{{"bufferView":2,"componentType":5126,"count":{n},"type":"VEC2"}}"#),
    ];
    let mut attributes = r#""POSITION":0,"NORMAL":1,"TEXCOORD_0":2"#.to_string();
    for (v, at) in mesh.values.iter().zip(&values_at) {
        attributes += &format!(r#","_{}":{}"#, v.name.to_ascii_uppercase(), accessors.len());
        accessors.push(format!(r#"{{"bufferView":{},"componentType":5126,"count":{n},"type":"SCALAR"}}"#, views.len()));
        views.push(format!(r#"{{"buffer":0,"byteOffset":{at},"byteLength":{},"target":34962}}"#, n * 4));
    }
    let mut primitives = Vec::new();
    for g in &groups {
        let extras = match (g.name.is_empty(), g.extras.is_empty()) {
            (true, true) => String::new(),
            (true, false) => format!(r#","extras":{{{}}}"#, g.extras),
            (false, true) => format!(r#","extras":{{"name":{}}}"#, json_string(&g.name)),
            (false, false) => format!(r#","extras":{{"name":{},{}}}"#, json_string(&g.name), g.extras),
        };
        primitives.push(format!(r#"{{"attributes":{{{attributes}}},"indices":{},"mode":4{extras}}}"#, accessors.len()));
        accessors.push(format!(
            r#"{{"bufferView":3,"byteOffset":{},"componentType":5125,"count":{},"type":"SCALAR"}}"#,
            g.triangles.start * 12,
            g.triangles.len() * 3
        ));
    }
    let json = format!(
        concat!(
            r#"{{"asset":{{"version":"2.0","generator":"opencrg {version}"}},"scene":0,"scenes":[{{"nodes":[0]}}],"#,
            r#""nodes":[{{"name":"road","mesh":0,"translation":[{tx},{ty},{tz}]}}],"#,
            r#""meshes":[{{"name":"road surface","primitives":[{primitives}]}}],"#,
            r#""buffers":[{{"byteLength":{total}}}],"bufferViews":[{views}],"accessors":[{accessors}]}}"#
        ),
        version = env!("CARGO_PKG_VERSION"),
        tx = num(origin[0]),
        ty = num(origin[1]),
        tz = num(origin[2]),
        primitives = primitives.join(","),
        total = total,
        views = views.join(","),
        accessors = accessors.join(","),
    );
    write_container(out, json, &bin)
}

/// A mesh's binary buffer and where its parts lie in it.
struct Buffer {
    bin: Vec<u8>,
    /// The byte length before the padding to 4 bytes.
    total: usize,
    /// The smallest coordinates of the vertices with a position (y up): the node's
    /// translation, which the positions are relative to.
    origin: [f64; 3],
    /// The positions' bounds.
    lo: [f32; 3],
    hi: [f32; 3],
    normals_at: usize,
    texcoords_at: usize,
    indices_at: usize,
    values_at: Vec<usize>,
}

/// Lays out the positions (y up, relative to the origin), normals, texture coordinates,
/// triangles and values of `mesh` in one little-endian buffer.
fn buffer(mesh: &Mesh) -> Buffer {
    let n = mesh.positions.len();
    // The origin: the smallest coordinates of the vertices with a position.
    let finite = mesh.positions.iter().filter(|p| p.iter().all(|c| c.is_finite())).map(|&p| y_up(p));
    let origin = finite.fold([f64::INFINITY; 3], |m, p| [m[0].min(p[0]), m[1].min(p[1]), m[2].min(p[2])]);
    let origin = origin.map(|c| if c.is_finite() { c } else { 0.0 });
    let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
    let mut bin = Vec::with_capacity(n * 32 + mesh.triangles.len() * 12);
    for p in &mesh.positions {
        let q = if p.iter().all(|c| c.is_finite()) { y_up(*p) } else { origin };
        for k in 0..3 {
            let c = (q[k] - origin[k]) as f32;
            lo[k] = lo[k].min(c);
            hi[k] = hi[k].max(c);
            bin.extend_from_slice(&c.to_le_bytes());
        }
    }
    let normals_at = bin.len();
    for nv in &mesh.normals {
        for c in [nv[0], nv[2], -nv[1]] {
            bin.extend_from_slice(&c.to_le_bytes());
        }
    }
    let texcoords_at = bin.len();
    for t in &mesh.texcoords {
        for c in t {
            bin.extend_from_slice(&c.to_le_bytes());
        }
    }
    let indices_at = bin.len();
    for t in &mesh.triangles {
        for i in t {
            bin.extend_from_slice(&i.to_le_bytes());
        }
    }
    let mut values_at = Vec::new();
    for v in &mesh.values {
        values_at.push(bin.len());
        for x in &v.values {
            bin.extend_from_slice(&x.to_le_bytes());
        }
    }
    let total = bin.len();
    while bin.len() % 4 != 0 {
        bin.push(0);
    }
    if n == 0 {
        (lo, hi) = ([0.0; 3], [0.0; 3]);
    }
    Buffer { bin, total, origin, lo, hi, normals_at, texcoords_at, indices_at, values_at }
}

/// Writes the binary glTF container: the header, the JSON chunk, the binary chunk.
fn write_container(out: &mut impl Write, json: String, bin: &[u8]) -> io::Result<()> {
    let mut json = json.into_bytes();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    let length = 12 + 8 + json.len() + 8 + bin.len();
    let length = u32::try_from(length).map_err(|_| io::Error::other("more than 4 GB: too large for one .glb file"))?;
    out.write_all(b"glTF")?;
    out.write_all(&2u32.to_le_bytes())?;
    out.write_all(&length.to_le_bytes())?;
    out.write_all(&(json.len() as u32).to_le_bytes())?;
    out.write_all(b"JSON")?;
    out.write_all(&json)?;
    out.write_all(&(bin.len() as u32).to_le_bytes())?;
    out.write_all(b"BIN\0")?;
    out.write_all(bin)
}
