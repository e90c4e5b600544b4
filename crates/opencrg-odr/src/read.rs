//! `.xodr` files to [`Map`]: OpenDRIVE 1.4 to 1.9 as tools write them. Elements this
//! library does not use are skipped; a file that is not XML, is not OpenDRIVE, or gives an
//! element without a required attribute or with a value that is not a number is refused
//! with the file, the line and the element named.

use crate::geometry::{Geometry, Shape, MAX_SPIRAL_TURN};
use crate::lanes::{Height, Lane, LaneSection, Lanes, Material};
use crate::map::{CrgMode, CrgOrientation, CrgPurpose, CrgRecord, Header, Junction, Map, Road, ShapeGroup};
use crate::profile::{Cubic, Profile};
use crate::xml::{Node, Tree};
use opencrg_core::{Error, Location, Result};
use std::path::{Path, PathBuf};

/// Where the reader is: the file, and where its lines start (for line numbers).
struct Reader<'a> {
    path: &'a Path,
    folder: PathBuf,
    line_starts: Vec<usize>,
}

impl Reader<'_> {
    /// The 1-based line of the element's start.
    fn line(&self, node: Node) -> usize {
        self.line_starts.partition_point(|&start| start <= node.start())
    }

    fn refuse(&self, node: Node, field: &str, message: impl Into<String>) -> Error {
        Error::Format {
            path: self.path.to_path_buf(),
            location: Location::Line(self.line(node)),
            field: format!("<{}> {field}", node.name()),
            message: message.into(),
        }
    }

    /// A number attribute; `default` when absent (`None`: required).
    fn number(&self, node: Node, name: &str, default: Option<f64>) -> Result<f64> {
        match node.attribute(name) {
            None => default.ok_or_else(|| self.refuse(node, name, "required, missing")),
            Some(text) => match text.trim_ascii().parse::<f64>() {
                Ok(x) if x.is_finite() => Ok(x),
                _ => Err(self.refuse(node, name, format!("'{text}' is not a finite number"))),
            },
        }
    }

    fn text(&self, node: Node, name: &str) -> Result<String> {
        node.attribute(name).map(str::to_string).ok_or_else(|| self.refuse(node, name, "required, missing"))
    }

    fn cubic(&self, node: Node, s_name: &str) -> Result<Cubic> {
        Ok(Cubic {
            s: self.number(node, s_name, Some(0.0))?,
            a: self.number(node, "a", Some(0.0))?,
            b: self.number(node, "b", Some(0.0))?,
            c: self.number(node, "c", Some(0.0))?,
            d: self.number(node, "d", Some(0.0))?,
        })
    }

    fn cubics(&self, parent: Option<Node>, tag: &str, s_name: &str) -> Result<Vec<Cubic>> {
        children(parent, tag).map(|n| self.cubic(n, s_name)).collect()
    }

    fn geometry(&self, node: Node) -> Result<Geometry> {
        let shape_node = node
            .children()
            .next()
            .ok_or_else(|| self.refuse(node, "shape", "no line, arc, spiral, poly3 or paramPoly3 inside"))?;
        let n = |name: &str| self.number(shape_node, name, Some(0.0));
        let shape = match shape_node.name() {
            "line" => Shape::Line,
            "arc" => Shape::Arc { curvature: self.number(shape_node, "curvature", None)? },
            "spiral" => Shape::Spiral {
                start: self.number(shape_node, "curvStart", None)?,
                end: self.number(shape_node, "curvEnd", None)?,
            },
            "poly3" => Shape::Poly3 { coefficients: [n("a")?, n("b")?, n("c")?, n("d")?] },
            "paramPoly3" => {
                let range = shape_node.attribute("pRange").or(node.attribute("pRange")).unwrap_or("normalized");
                Shape::ParamPoly3 {
                    u: [n("aU")?, n("bU")?, n("cU")?, n("dU")?],
                    v: [n("aV")?, n("bV")?, n("cV")?, n("dV")?],
                    normalized: !range.eq_ignore_ascii_case("arcLength"),
                }
            }
            other => return Err(self.refuse(shape_node, "", format!("'{other}' is not a reference line shape"))),
        };
        let length = self.number(node, "length", None)?;
        if length < 0.0 {
            return Err(self.refuse(node, "length", format!("{length} is negative")));
        }
        if let Shape::Spiral { start, end } = shape {
            let turn = start.abs().max(end.abs()) * length;
            if turn > MAX_SPIRAL_TURN {
                let message = format!("turns by up to {turn:.4e} rad over its {length} m: more than ten full circles");
                return Err(self.refuse(shape_node, "", message));
            }
        }
        Ok(Geometry {
            s: self.number(node, "s", None)?,
            x: self.number(node, "x", None)?,
            y: self.number(node, "y", None)?,
            hdg: self.number(node, "hdg", None)?,
            length,
            shape,
        })
    }

    fn lane(&self, node: Node) -> Result<Lane> {
        let id = self.text(node, "id")?;
        let id: i32 =
            id.trim().parse().map_err(|_| self.refuse(node, "id", format!("'{id}' is not a whole number")))?;
        let mut width = Vec::new();
        let mut border = Vec::new();
        let mut heights = Vec::new();
        let mut materials = Vec::new();
        for c in node.children() {
            match c.name() {
                "width" => width.push(self.cubic(c, "sOffset")?),
                "border" => border.push(self.cubic(c, "sOffset")?),
                "height" => heights.push(Height {
                    s_offset: self.number(c, "sOffset", Some(0.0))?,
                    inner: self.number(c, "inner", Some(0.0))?,
                    outer: self.number(c, "outer", Some(0.0))?,
                }),
                "material" => materials.push(Material {
                    s_offset: self.number(c, "sOffset", Some(0.0))?,
                    friction: c.attribute("friction").map(|_| self.number(c, "friction", None)).transpose()?,
                    surface: c.attribute("surface").map(str::to_string),
                }),
                _ => {}
            }
        }
        for list in [&mut width, &mut border] {
            list.sort_by(|a, b| a.s.total_cmp(&b.s));
        }
        heights.sort_by(|a, b| a.s_offset.total_cmp(&b.s_offset));
        materials.sort_by(|a, b| a.s_offset.total_cmp(&b.s_offset));
        Ok(Lane {
            id,
            kind: node.attribute("type").unwrap_or("none").to_string(),
            level: matches!(node.attribute("level"), Some("true" | "1")),
            width,
            border,
            heights,
            materials,
        })
    }

    fn lane_section(&self, node: Node) -> Result<LaneSection> {
        let side = |name: &str, outwards_desc: bool| -> Result<Vec<Lane>> {
            let mut lanes: Vec<Lane> =
                children(child(node, name), "lane").map(|l| self.lane(l)).collect::<Result<_>>()?;
            lanes.sort_by_key(|l| if outwards_desc { -l.id } else { l.id });
            Ok(lanes)
        };
        Ok(LaneSection { s: self.number(node, "s", None)?, left: side("left", false)?, right: side("right", true)? })
    }

    fn crg(&self, node: Node) -> Result<CrgRecord> {
        let file = self.text(node, "file")?;
        let word = |name: &str, default: Option<&str>| -> Result<String> {
            match node.attribute(name).or(default) {
                Some(w) => Ok(w.to_string()),
                None => Err(self.refuse(node, name, "required, missing")),
            }
        };
        let mode = match word("mode", None)?.as_str() {
            "attached" => CrgMode::Attached,
            "attached0" => CrgMode::Attached0,
            "genuine" => CrgMode::Genuine,
            "global" => CrgMode::Global,
            other => {
                return Err(self.refuse(node, "mode", format!("'{other}': attached, attached0, genuine or global")))
            }
        };
        let orientation = match word("orientation", Some("same"))?.as_str() {
            "same" => CrgOrientation::Same,
            "opposite" => CrgOrientation::Opposite,
            other => return Err(self.refuse(node, "orientation", format!("'{other}': same or opposite"))),
        };
        let purpose = match word("purpose", Some("elevation"))?.as_str() {
            "elevation" => CrgPurpose::Elevation,
            "friction" => CrgPurpose::Friction,
            other => return Err(self.refuse(node, "purpose", format!("'{other}': elevation or friction"))),
        };
        let global = mode == CrgMode::Global;
        let path = PathBuf::from(&file);
        Ok(CrgRecord {
            path: if path.is_absolute() { path } else { self.folder.join(path) },
            file,
            s_start: self.number(node, "sStart", if global { Some(0.0) } else { None })?,
            s_end: self.number(node, "sEnd", if global { Some(f64::INFINITY) } else { None })?,
            mode,
            orientation,
            purpose,
            s_offset: self.number(node, "sOffset", Some(0.0))?,
            t_offset: self.number(node, "tOffset", Some(0.0))?,
            z_offset: self.number(node, "zOffset", Some(0.0))?,
            z_scale: self.number(node, "zScale", Some(1.0))?,
            h_offset: self.number(node, "hOffset", Some(0.0))?,
            x_offset: self.number(node, "xOffset", Some(0.0))?,
            y_offset: self.number(node, "yOffset", Some(0.0))?,
            given: node.attributes().map(|(name, _)| name.to_string()).collect(),
            line: self.line(node),
        })
    }

    /// The `<CRG>` records of every `<surface>` of a road or junction, in the file's order.
    fn crg_records(&self, parent: Node) -> Result<Vec<CrgRecord>> {
        children(Some(parent), "surface").flat_map(|s| children(Some(s), "CRG")).map(|c| self.crg(c)).collect()
    }

    /// Refuses a record the road runs on beyond its length (to the next record's s, or to
    /// the road's end for the last) where that would cost without bound: a spiral whose
    /// curvature, changing on as within it, would turn by more than [`MAX_SPIRAL_TURN`]
    /// there; a cubic curve followed on for more than its own length and a metre (each
    /// point of it is found by the arc length from its start). Lines and arcs run on in
    /// closed form.
    fn check_reach(&self, plan: &[(Geometry, Node)], road_length: f64) -> Result<()> {
        for (k, (g, node)) in plan.iter().enumerate() {
            let (until, what) = match plan.get(k + 1) {
                Some((next, _)) => (next.s, "the next record"),
                None => (road_length, "the road's end"),
            };
            let reach = until - g.s;
            if !(reach > g.length) {
                continue;
            }
            let beyond = format!(
                "runs on {} m beyond its {} m to {what} at s = {} m",
                metres(reach - g.length),
                metres(g.length),
                metres(until)
            );
            let refused = match g.shape {
                Shape::Line | Shape::Arc { .. } => None,
                Shape::Spiral { start, end } => {
                    let rate = if g.length > 0.0 { (end - start) / g.length } else { 0.0 };
                    let turn = start.abs().max((start + rate * reach).abs()) * reach;
                    (!(turn <= MAX_SPIRAL_TURN))
                        .then(|| format!("{beyond}, turning by up to {turn:.4e} rad: more than ten full circles"))
                }
                Shape::Poly3 { .. } | Shape::ParamPoly3 { .. } => (!(reach <= 2.0 * g.length + 1.0))
                    .then(|| format!("{beyond}: a cubic curve is followed on for at most its own length and a metre")),
            };
            if let Some(message) = refused {
                return Err(self.refuse(*node, "length", message));
            }
        }
        Ok(())
    }

    fn road(&self, node: Node) -> Result<Road> {
        let id = self.text(node, "id")?;
        let length = self.number(node, "length", None)?;
        let mut plan: Vec<(Geometry, Node)> =
            children(child(node, "planView"), "geometry").map(|g| Ok((self.geometry(g)?, g))).collect::<Result<_>>()?;
        plan.sort_by(|a, b| a.0.s.total_cmp(&b.0.s));
        self.check_reach(&plan, length)?;
        let plan = plan.into_iter().map(|(g, _)| g).collect();
        let lateral = child(node, "lateralProfile");
        let mut shape: Vec<ShapeGroup> = Vec::new();
        for n in children(lateral, "shape") {
            let s = self.number(n, "s", None)?;
            let cubic = Cubic { s: self.number(n, "t", None)?, ..self.cubic(n, "t")? };
            match shape.iter_mut().find(|g| g.s == s) {
                Some(g) => g.along_t.push(cubic),
                None => shape.push(ShapeGroup { s, along_t: vec![cubic] }),
            }
        }
        shape.sort_by(|a, b| a.s.total_cmp(&b.s));
        for g in &mut shape {
            g.along_t.sort_by(|a, b| a.s.total_cmp(&b.s));
        }
        let lanes_node = child(node, "lanes");
        let mut sections: Vec<LaneSection> =
            children(lanes_node, "laneSection").map(|l| self.lane_section(l)).collect::<Result<_>>()?;
        sections.sort_by(|a, b| a.s.total_cmp(&b.s));
        Ok(Road {
            name: node.attribute("name").unwrap_or("").to_string(),
            junction: node.attribute("junction").filter(|j| !j.is_empty() && *j != "-1").map(str::to_string),
            plan,
            elevation: Profile::new(self.cubics(child(node, "elevationProfile"), "elevation", "s")?),
            superelevation: Profile::new(self.cubics(lateral, "superelevation", "s")?),
            shape,
            lanes: Lanes { offset: Profile::new(self.cubics(lanes_node, "laneOffset", "s")?), sections },
            crg: self.crg_records(node)?,
            line: self.line(node),
            id,
            length,
        })
    }

    fn junction(&self, node: Node) -> Result<Junction> {
        Ok(Junction {
            id: self.text(node, "id")?,
            name: node.attribute("name").unwrap_or("").to_string(),
            connecting_roads: children(Some(node), "connection")
                .filter_map(|c| c.attribute("connectingRoad").map(str::to_string))
                .collect(),
            crg: self.crg_records(node)?,
            line: self.line(node),
        })
    }
}

/// The first child element called `tag`.
fn child<'t, 'a>(node: Node<'t, 'a>, tag: &str) -> Option<Node<'t, 'a>> {
    node.children().find(|c| c.name() == tag)
}

/// The child elements called `tag` (none when there is no parent).
fn children<'t, 'a: 't>(parent: Option<Node<'t, 'a>>, tag: &'t str) -> impl Iterator<Item = Node<'t, 'a>> + 't {
    parent.into_iter().flat_map(move |p| p.children().filter(move |c| c.name() == tag))
}

impl Map {
    /// Reads the map in `path`.
    pub fn load(path: impl AsRef<Path>) -> Result<Map> {
        let path = path.as_ref();
        let text = std::fs::read(path).map_err(|source| Error::reading(path, source))?;
        Map::from_bytes(&text, path)
    }

    /// Reads a map from `bytes`, named `path` in messages (relative CRG files resolve
    /// against its folder).
    pub fn from_bytes(bytes: &[u8], path: &Path) -> Result<Map> {
        let refuse = |line: usize, field: &str, message: String| Error::Format {
            path: path.to_path_buf(),
            location: if line == 0 { Location::File } else { Location::Line(line) },
            field: field.to_string(),
            message,
        };
        let text = std::str::from_utf8(bytes).map_err(|e| refuse(0, "text", format!("not UTF-8 ({e})")))?;
        let line_starts: Vec<usize> =
            std::iter::once(0).chain(memchr::memchr_iter(b'\n', bytes).map(|i| i + 1)).collect();
        let line = |offset: usize| line_starts.partition_point(|&start| start <= offset);
        let tree = Tree::parse(text).map_err(|e| refuse(line(e.offset), "XML", e.message))?;
        let root = tree.root();
        if root.name() != "OpenDRIVE" {
            return Err(refuse(line(root.start()), "root", format!("<{}> is not <OpenDRIVE>", root.name())));
        }
        let reader = Reader { path, folder: path.parent().map(Path::to_path_buf).unwrap_or_default(), line_starts };
        let mut header = Header::default();
        let (mut roads, mut junctions) = (Vec::new(), Vec::new());
        for node in root.children() {
            match node.name() {
                "header" => {
                    header = Header {
                        rev_major: reader.number(node, "revMajor", Some(1.0))? as u32,
                        rev_minor: reader.number(node, "revMinor", Some(0.0))? as u32,
                        name: node.attribute("name").unwrap_or("").to_string(),
                        geo_reference: child(node, "geoReference").and_then(|g| g.text()).map(|t| t.trim().to_string()),
                    }
                }
                "road" => roads.push(reader.road(node)?),
                "junction" => junctions.push(reader.junction(node)?),
                _ => {}
            }
        }
        Ok(Map::new(path.to_path_buf(), header, roads, junctions))
    }
}

/// A length for a message: to a tenth of a millimetre up to a million kilometres, in
/// exponent form beyond.
fn metres(x: f64) -> String {
    if x.abs() < 1e9 {
        let fixed = format!("{x:.4}");
        fixed.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{x:.4e}")
    }
}
