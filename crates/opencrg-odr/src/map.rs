//! The map as data: roads (reference line, elevation, superelevation, lateral shape,
//! lanes, CRG records), junctions, and the records that lay CRG files on them.

use crate::geometry::Geometry;
use crate::lanes::Lanes;
use crate::profile::{Cubic, Profile};
use std::collections::BTreeMap;
use std::path::PathBuf;

/// How a CRG record lays its file on the road (`mode`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CrgMode {
    /// The CRG's grid rides on the road's surface (its own reference line is disregarded).
    Attached,
    /// The CRG's full height along the road's s/t, replacing the road's height.
    Attached0,
    /// The CRG in its own x/y, placed at a point of the road.
    Genuine,
    /// The CRG in the map's x/y.
    Global,
}

/// Which way the CRG's u runs along the road (`orientation`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CrgOrientation {
    /// u along s.
    Same,
    /// u against s, v against t.
    Opposite,
}

/// What the CRG's values mean (`purpose`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CrgPurpose {
    /// Heights.
    Elevation,
    /// Friction coefficients.
    Friction,
}

/// One `<CRG>` record of a road's or a junction's `<surface>`.
#[derive(Debug, Clone, PartialEq)]
pub struct CrgRecord {
    /// The file as written.
    pub file: String,
    /// The file, resolved against the map's folder.
    pub path: PathBuf,
    /// Where on the road it starts and ends (s).
    pub s_start: f64,
    /// See `s_start`.
    pub s_end: f64,
    /// How it is laid on the road.
    pub mode: CrgMode,
    /// Which way its u runs.
    pub orientation: CrgOrientation,
    /// What its values mean.
    pub purpose: CrgPurpose,
    /// Where its u/v origin sits in s/t.
    pub s_offset: f64,
    /// See `s_offset`.
    pub t_offset: f64,
    /// Height shift of its values.
    pub z_offset: f64,
    /// Scale of its values.
    pub z_scale: f64,
    /// Heading offset (genuine and global).
    pub h_offset: f64,
    /// Shift of a global record.
    pub x_offset: f64,
    /// See `x_offset`.
    pub y_offset: f64,
    /// The attributes the record gives, by name (for the checker's rules).
    pub given: Vec<String>,
    /// Its line in the map file.
    pub line: usize,
}

/// One group of the lateral shape (`<shape>` records at one s): heights along t.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeGroup {
    /// Where the group stands.
    pub s: f64,
    /// Polynomials in t - their own t (kept in `Cubic::s`), sorted by t.
    pub along_t: Vec<Cubic>,
}

/// A road of the map.
#[derive(Debug, Clone, PartialEq)]
pub struct Road {
    /// Its id.
    pub id: String,
    /// Its name.
    pub name: String,
    /// Its length (m).
    pub length: f64,
    /// The junction it connects roads in, if it is a connecting road.
    pub junction: Option<String>,
    /// Its reference line, sorted by s.
    pub plan: Vec<Geometry>,
    /// Height of the reference line along s.
    pub elevation: Profile,
    /// Roll of the cross section along s (rad).
    pub superelevation: Profile,
    /// The lateral shape, sorted by s.
    pub shape: Vec<ShapeGroup>,
    /// Its lanes.
    pub lanes: Lanes,
    /// Its CRG records, in the file's order.
    pub crg: Vec<CrgRecord>,
    /// Its line in the map file.
    pub line: usize,
}

/// A junction: the roads connecting others in it, its CRG records.
#[derive(Debug, Clone, PartialEq)]
pub struct Junction {
    /// Its id.
    pub id: String,
    /// Its name.
    pub name: String,
    /// The ids of its connecting roads.
    pub connecting_roads: Vec<String>,
    /// Its CRG records.
    pub crg: Vec<CrgRecord>,
    /// Its line in the map file.
    pub line: usize,
}

/// What the map's `<header>` says.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Header {
    /// OpenDRIVE's major revision.
    pub rev_major: u32,
    /// OpenDRIVE's minor revision.
    pub rev_minor: u32,
    /// The map's name.
    pub name: String,
    /// The `<geoReference>` text, if any.
    pub geo_reference: Option<String>,
}

/// An OpenDRIVE map.
#[derive(Debug, Clone, PartialEq)]
pub struct Map {
    /// The file it was read from.
    pub path: PathBuf,
    /// Its header.
    pub header: Header,
    /// Its roads, in the file's order.
    pub roads: Vec<Road>,
    /// Its junctions, in the file's order.
    pub junctions: Vec<Junction>,
    /// Each road's index by id (a B-tree, not a hash map: no random state, whose source
    /// would make the Windows DLL import bcryptprimitives.dll).
    by_id: BTreeMap<String, usize>,
}

impl Map {
    /// A map of these parts.
    pub(crate) fn new(path: PathBuf, header: Header, roads: Vec<Road>, junctions: Vec<Junction>) -> Map {
        let by_id = roads.iter().enumerate().map(|(i, r)| (r.id.clone(), i)).collect();
        Map { path, header, roads, junctions, by_id }
    }

    /// The road with this id.
    pub fn road(&self, id: &str) -> Option<&Road> {
        self.by_id.get(id).map(|&i| &self.roads[i])
    }

    /// The index of the road with this id in [`Map::roads`].
    pub fn road_index(&self, id: &str) -> Option<usize> {
        self.by_id.get(id).copied()
    }

    /// The CRG files the map's records name (their `file` attributes as written), each
    /// once, roads' records before junctions', in the file's order: what must be at hand
    /// to lay them on.
    pub fn crg_file_names(&self) -> Vec<&str> {
        let records = self.roads.iter().flat_map(|r| &r.crg).chain(self.junctions.iter().flat_map(|j| &j.crg));
        let mut names: Vec<&str> = Vec::new();
        for record in records {
            if !names.contains(&record.file.as_str()) {
                names.push(&record.file);
            }
        }
        names
    }

    /// The roads' lengths added up (m), those that are not a positive number left out:
    /// what the work of sampling the whole map is shared by.
    pub fn length(&self) -> f64 {
        self.roads.iter().map(|r| r.length).filter(|l| l.is_finite() && *l > 0.0).sum()
    }
}
