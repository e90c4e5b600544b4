//! Reading maps: every map of `../shared/opendrive/` loads with all its roads; broken and
//! incomplete files are refused naming the file, the line and the element; what this
//! library does not use is skipped; CRG records are read with their defaults.

use opencrg_odr::{CrgMode, CrgOrientation, CrgPurpose, Map, Shape};
use std::path::Path;

fn shared(rel: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/opendrive").join(rel)
}

#[test]
#[ignore = "needs ../shared beside the checkout; test.sh runs it: cargo test -- --ignored shared_"]
fn shared_maps_load_whole() {
    for (file, roads, junctions) in
        [("carla/Town01.xodr", 98, 12), ("carla/Town03.xodr", 279, 34), ("esmini/fabriksgatan.xodr", 16, 1)]
    {
        let map = Map::load(shared(file)).unwrap();
        assert_eq!((map.roads.len(), map.junctions.len()), (roads, junctions), "{file}");
        for road in &map.roads {
            assert!(!road.plan.is_empty(), "{file} road {}", road.id);
            // The reference line records join up (within the maps' own rounding, up to a few mm).
            for pair in road.plan.windows(2) {
                let end = pair[0].pose(pair[0].length);
                let gap = (end.x - pair[1].x).hypot(end.y - pair[1].y);
                assert!(gap < 1e-2, "{file} road {} at s {}: gap {gap}", road.id, pair[1].s);
            }
        }
    }
    let tunnels = Map::load(shared("esmini/tunnels.xodr")).unwrap();
    assert!(tunnels.roads.iter().all(|r| r.junction.is_none()));
    let multi = Map::load(shared("esmini/multi_intersections.xodr")).unwrap();
    let connecting = multi.roads.iter().filter(|r| r.junction.is_some()).count();
    let listed: usize = multi.junctions.iter().map(|j| j.connecting_roads.len()).sum();
    assert!(connecting > 0 && listed >= connecting, "{connecting} {listed}");
}

fn refusal(text: &str) -> String {
    Map::from_bytes(text.as_bytes(), Path::new("bad.xodr")).unwrap_err().to_string()
}

const ROAD_START: &str = "<?xml version=\"1.0\"?>\n<OpenDRIVE>\n<header revMajor=\"1\" revMinor=\"8\"/>\n";

#[test]
fn broken_maps_are_refused_with_file_line_and_element() {
    let e = refusal("<OpenDRIVE><road id=\"1\" length=\"10\"></OpenDRIVE>");
    assert!(e.starts_with("bad.xodr:1") && e.contains("XML"), "{e}");
    let e = refusal("<?xml version=\"1.0\"?>\n<osm/>");
    assert!(e.contains("bad.xodr:2") && e.contains("<osm>"), "{e}");
    let e = refusal(&format!("{ROAD_START}<road id=\"7\">\n</road>\n</OpenDRIVE>"));
    assert!(e.contains("bad.xodr:4") && e.contains("<road> length") && e.contains("missing"), "{e}");
    let e = refusal(&format!(
        "{ROAD_START}<road id=\"7\" length=\"10\"><planView>\n<geometry s=\"0\" x=\"0\" y=\"zero\" hdg=\"0\" length=\"10\"><line/></geometry>\n</planView></road></OpenDRIVE>"
    ));
    assert!(e.contains("bad.xodr:5") && e.contains("<geometry> y") && e.contains("'zero'"), "{e}");
    let e = refusal(&format!(
        "{ROAD_START}<road id=\"7\" length=\"10\"><planView><geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"10\"><clothoid/></geometry></planView></road></OpenDRIVE>"
    ));
    assert!(e.contains("'clothoid'"), "{e}");
    let e = refusal(&format!(
        "{ROAD_START}<road id=\"7\" length=\"10\"><surface><CRG file=\"a.crg\" sStart=\"0\" sEnd=\"5\" mode=\"glued\"/></surface></road></OpenDRIVE>"
    ));
    assert!(e.contains("<CRG> mode") && e.contains("'glued'"), "{e}");
    // A spiral turning through more than ten full circles (a length 1e7 instead of 10):
    // refused when read, not evaluated for minutes.
    let spiral = |length: &str| {
        format!(
            "{ROAD_START}<road id=\"7\" length=\"{length}\"><planView><geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"{length}\">\n\
             <spiral curvStart=\"0\" curvEnd=\"1\"/></geometry></planView></road></OpenDRIVE>"
        )
    };
    let e = refusal(&spiral("1e7"));
    assert!(e.contains("bad.xodr:5") && e.contains("<spiral>") && e.contains("ten full circles"), "{e}");
    assert!(Map::from_bytes(spiral("10").as_bytes(), Path::new("ok.xodr")).is_ok());
    // A road running on far beyond its last spiral (length 20020 for 2 km of records, as
    // a fuzzer wrote it): the spiral would go on turning there; refused, naming the
    // record. A road a little longer than its records, and one reaching past a line, read.
    let beyond = |length: &str, shape: &str| {
        format!(
            "{ROAD_START}<road id=\"7\" length=\"{length}\"><planView><geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"10\">\n\
             {shape}</geometry></planView></road></OpenDRIVE>"
        )
    };
    let spiral_record = "<spiral curvStart=\"0.008\" curvEnd=\"0\"/>";
    let e = refusal(&beyond("20020", spiral_record));
    assert!(e.contains("bad.xodr:4") && e.contains("<geometry> length") && e.contains("the road's end"), "{e}");
    assert!(Map::from_bytes(beyond("10.001", spiral_record).as_bytes(), Path::new("ok.xodr")).is_ok());
    assert!(Map::from_bytes(beyond("20020", "<line/>").as_bytes(), Path::new("ok.xodr")).is_ok());
    // A cubic curve followed on for more than its own length again (each point of it
    // found by the arc length from its start: seconds for a road of 100 km): refused.
    let cubic = "<paramPoly3 aU=\"0\" bU=\"10\" cU=\"1\" dU=\"0.5\" aV=\"0\" bV=\"0\" cV=\"2\" dV=\"-1\"/>";
    let e = refusal(&beyond("1e5", cubic));
    assert!(e.contains("bad.xodr:4") && e.contains("runs on 99990 m beyond its 10 m") && e.contains("cubic"), "{e}");
    assert!(refusal(&beyond("1e300", "<poly3 a=\"0\" b=\"0.1\" c=\"0\" d=\"0\"/>")).contains("1.0000e300 m"));
    assert!(Map::from_bytes(beyond("15", cubic).as_bytes(), Path::new("ok.xodr")).is_ok());
    assert!(Map::load("/nonexistent/map.xodr").unwrap_err().to_string().contains("cannot read"));
}

#[test]
fn unknown_elements_are_skipped_and_crg_records_read() {
    let text = format!(
        "{ROAD_START}<userData code=\"x\"/>\n<road id=\"r\" length=\"20\" junction=\"-1\"><type s=\"0\" type=\"town\"/>\n\
         <planView><geometry s=\"0\" x=\"1\" y=\"2\" hdg=\"0.5\" length=\"20\"><spiral curvStart=\"0\" curvEnd=\"0.01\"/></geometry></planView>\n\
         <objects><object id=\"o\"/></objects>\n\
         <surface><CRG file=\"cobbles.crg\" sStart=\"2\" sEnd=\"12\" mode=\"attached\" orientation=\"opposite\" tOffset=\"0.5\" zScale=\"2\"/>\n\
         <CRG file=\"/abs/mu.crg\" sStart=\"0\" sEnd=\"20\" mode=\"genuine\" purpose=\"friction\" hOffset=\"0.1\"/></surface>\n\
         </road>\n<junction id=\"j\"><connection id=\"0\" incomingRoad=\"r\" connectingRoad=\"c\" contactPoint=\"start\"/>\n\
         <surface><CRG file=\"junction.crg\" mode=\"global\"/></surface></junction>\n</OpenDRIVE>"
    );
    let map = Map::from_bytes(text.as_bytes(), Path::new("/maps/town.xodr")).unwrap();
    let road = map.road("r").unwrap();
    assert_eq!(road.plan[0].shape, Shape::Spiral { start: 0.0, end: 0.01 });
    assert_eq!(road.crg.len(), 2);
    let (a, b) = (&road.crg[0], &road.crg[1]);
    assert_eq!(
        (a.mode, a.orientation, a.purpose),
        (CrgMode::Attached, CrgOrientation::Opposite, CrgPurpose::Elevation)
    );
    assert_eq!((a.s_start, a.s_end, a.t_offset, a.z_scale, a.z_offset), (2.0, 12.0, 0.5, 2.0, 0.0));
    assert_eq!(a.path, Path::new("/maps/cobbles.crg"));
    assert_eq!((b.mode, b.purpose, b.h_offset), (CrgMode::Genuine, CrgPurpose::Friction, 0.1));
    assert_eq!(b.path, Path::new("/abs/mu.crg"));
    assert_eq!(a.line, 8);
    let j = &map.junctions[0];
    assert_eq!(
        (j.connecting_roads.clone(), j.crg[0].mode, j.crg[0].s_end),
        (vec!["c".to_string()], CrgMode::Global, f64::INFINITY)
    );
    assert_eq!(map.crg_file_names(), ["cobbles.crg", "/abs/mu.crg", "junction.crg"]);
}

#[test]
fn the_surface_follows_elevation_superelevation_shape_and_lane_heights() {
    let text = format!(
        "{ROAD_START}<road id=\"r\" length=\"100\"><planView><geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"100\"><line/></geometry></planView>\n\
         <elevationProfile><elevation s=\"0\" a=\"1\" b=\"0.02\" c=\"0\" d=\"0\"/></elevationProfile>\n\
         <lateralProfile><superelevation s=\"0\" a=\"0.05\" b=\"0\" c=\"0\" d=\"0\"/></lateralProfile>\n\
         <lanes><laneOffset s=\"0\" a=\"0.5\" b=\"0\" c=\"0\" d=\"0\"/><laneSection s=\"0\"><left><lane id=\"1\" type=\"sidewalk\"><width sOffset=\"0\" a=\"2\" b=\"0\" c=\"0\" d=\"0\"/>\n\
         <height sOffset=\"0\" inner=\"0.1\" outer=\"0.2\"/><height sOffset=\"50\" inner=\"0\" outer=\"0\"/></lane></left><center><lane id=\"0\"/></center>\n\
         <right><lane id=\"-1\" type=\"driving\"><width sOffset=\"0\" a=\"3.5\" b=\"0\" c=\"0\" d=\"0\"/><material sOffset=\"0\" friction=\"0.8\"/></lane></right></laneSection></lanes>\n\
         </road></OpenDRIVE>"
    );
    let map = Map::from_bytes(text.as_bytes(), Path::new("m.xodr")).unwrap();
    let road = map.road("r").unwrap();
    let (s, r) = (10.0, 0.05f64);
    // On the driving lane: the tilted plane through the reference line.
    let p = road.surface_point(s, -2.0);
    assert!((p[0] - s).abs() < 1e-12 && (p[1] + 2.0 * r.cos()).abs() < 1e-12);
    assert!((p[2] - (1.0 + 0.02 * s - 2.0 * r.sin())).abs() < 1e-12);
    assert_eq!(road.lane_at(s, -2.0).unwrap().lane.id, -1);
    assert_eq!(road.lane_at(s, -2.0).unwrap().lane.friction_at(s), Some(0.8));
    // On the sidewalk (t 0.5 to 2.5): 0.1 to 0.2 m above the cross section, held until s = 50.
    let h = road.height_above_section(s, 1.5);
    assert!((h - 0.15).abs() < 1e-12, "{h}");
    assert_eq!(road.height_above_section(60.0, 1.5), 0.0);
    let p = road.surface_point(s, 1.5);
    assert!((p[2] - (1.0 + 0.02 * s + 1.5 * r.sin() + 0.15 * r.cos())).abs() < 1e-12);
    assert!(road.lane_at(s, 3.0).is_none() && road.lane_at(s, -4.5).is_none());
}
