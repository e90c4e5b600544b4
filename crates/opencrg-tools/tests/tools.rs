//! The road tools keep the surface where it was: z at the same x/y after cut, flip,
//! append, resample and the channel moves; lines through points and gridded clouds
//! land where the points say.

use opencrg_core::synth::RoadSpec;
use opencrg_core::{Budget, ContactPoint, Road};
use opencrg_tools::{self as tools, ChannelAction, Filter, Import, Layout, LineChannel, Points};
use std::sync::Arc;

/// The default memory limit of the tools.
fn machine() -> Budget {
    Budget::machine()
}

const UNEVEN_V: [f64; 11] = [-3.0, -2.5, -1.7, -1.0, -0.2, 0.0, 0.3, 1.1, 2.0, 2.4, 3.0];

/// A curved, climbing, banked road with unevenly spaced long sections and a rough surface.
fn winding_road() -> Arc<Road> {
    let road = RoadSpec::straight(200.0, 6.0, 0.1, 0.5)
        .starting_at(10.0, -5.0, 0.3)
        .with_heading(|u| 0.3 + 0.004 * u + 0.3 * (u / 40.0).sin())
        .with_slope(|u| 0.02 + 0.01 * (u / 30.0).cos())
        .with_bank(|u| 0.03 * (u / 50.0).sin())
        .with_sections(UNEVEN_V.to_vec())
        .with_elevation(|u, v| 0.01 * (u * 1.3).sin() * (v * 2.1).cos() + 0.002 * (u * 7.7).sin())
        .build()
        .unwrap();
    Arc::new(road)
}

/// The largest |z| difference between `made`'s surface at each of its grid nodes and
/// `source`'s surface at the same x/y, and how many nodes were compared.
fn worst_at_nodes(source: &Arc<Road>, made: &Road) -> (f64, usize) {
    let made = Arc::new(made.clone());
    let mut a = ContactPoint::new(source.clone());
    let b = ContactPoint::new(made.clone());
    let (mut worst, mut n) = (0.0f64, 0);
    for iu in 0..made.reference_line().n {
        let u = made.reference_line().u_at(iu);
        for &v in &made.grid().v {
            let (x, y) = b.uv_to_xy(u, v).unwrap();
            let zb = b.uv_to_z(u, v).unwrap();
            let za = a.xy_to_z(x, y).unwrap();
            worst = worst.max((za - zb).abs());
            n += 1;
        }
    }
    (worst, n)
}

#[test]
fn a_cut_keeps_its_nodes_where_they_were() {
    let road = winding_road();
    let cut = tools::cut(&road, (50.0, 120.0), Some((-2.0, 2.1))).unwrap();
    assert_eq!(cut.reference_line().n, 701);
    assert_eq!(cut.grid().v, vec![-1.7, -1.0, -0.2, 0.0, 0.3, 1.1, 2.0]);
    assert!((cut.u_range().0 - 50.0).abs() < 1e-9);
    let (worst, n) = worst_at_nodes(&road, &cut);
    assert_eq!(n, 701 * 7);
    assert!(worst < 1e-4, "{worst}");
    assert!(cut.header().comments.iter().any(|c| c.contains("cut by opencrg")));
}

#[test]
fn a_flipped_road_is_the_same_surface_driven_the_other_way() {
    let road = winding_road();
    let flipped = tools::flip(&road).unwrap();
    let (worst, _) = worst_at_nodes(&road, &flipped);
    assert!(worst < 1e-4, "{worst}");
    let (l, f) = (road.reference_line(), flipped.reference_line());
    assert!((f.x[0] - l.x[l.n - 1]).abs() < 1e-6 && (f.y[0] - l.y[l.n - 1]).abs() < 1e-6);
    assert!((f.x[f.n - 1] - l.x[0]).abs() < 1e-6 && (f.y[f.n - 1] - l.y[0]).abs() < 1e-6);
    assert_eq!(flipped.grid().v.first(), Some(&-3.0));
    // Banking and slope turned: the left side (v > 0) is now the old right side.
    let back = tools::flip(&flipped).unwrap();
    let (worst, _) = worst_at_nodes(&road, &back);
    assert!(worst < 1e-4, "{worst}");
}

#[test]
fn two_cuts_appended_are_the_uncut_road() {
    let road = winding_road();
    let first = tools::cut(&road, (0.0, 93.0), None).unwrap();
    let second = Arc::new(tools::cut(&road, (93.0, 200.0), None).unwrap());
    // The second part starts with the heading of its first step, as the file format says
    // (the turn at u = 93 belongs to no part).
    let r = road.reference_line();
    let at_93 = 930;
    assert!((second.reference_line().heading_at(0) - r.heading_at(at_93 + 1)).abs() < 1e-12);
    let joined = tools::append(&first, &second, &machine()).unwrap();
    let j = joined.reference_line();
    assert_eq!(j.n, r.n);
    // The second part continues from the first's end, turning at the joint by the mean
    // of the turns beside it: on a line whose heading changes evenly, the turn it had.
    assert!((j.x[at_93] - r.x[at_93]).abs() < 1e-9 && (j.y[at_93] - r.y[at_93]).abs() < 1e-9);
    let (turn, was) = (j.heading_at(at_93 + 1) - j.heading_at(at_93), r.heading_at(at_93 + 1) - r.heading_at(at_93));
    let beside =
        (r.heading_at(at_93) - r.heading_at(at_93 - 1) + r.heading_at(at_93 + 2) - r.heading_at(at_93 + 1)) / 2.0;
    assert!((turn - beside).abs() < 1e-12 && (turn - was).abs() < 1e-6, "{turn} {beside} {was}");
    // The road as it was, in u/v and in x/y (the first part to the nanometre, but in its
    // last cell, whose cross sections turn towards the next step).
    let (a, b) = (ContactPoint::new(road.clone()), ContactPoint::new(Arc::new(joined)));
    for u in [0.0, 30.05, 92.9, 93.0, 120.5, 170.25, 199.9] {
        for v in [-2.9, 0.0, 1.3, 2.9] {
            let (za, zb) = (a.uv_to_z(u, v).unwrap(), b.uv_to_z(u, v).unwrap());
            assert!((za - zb).abs() < 1e-4, "u {u} v {v}: {za} {zb}");
            let ((xa, ya), (xb, yb)) = (a.uv_to_xy(u, v).unwrap(), b.uv_to_xy(u, v).unwrap());
            let within = if u < 93.0 { 1e-9 } else { 1e-4 };
            assert!((xa - xb).abs() < within && (ya - yb).abs() < within, "u {u} v {v}: {xa} {ya} {xb} {yb}");
        }
    }
}

#[test]
fn an_appended_road_continues_from_the_end_point_heading_and_height() {
    let road = winding_road();
    let other = Arc::new(RoadSpec::straight(30.0, 6.0, 0.2, 0.25).with_elevation(|u, _| 0.01 * u).build().unwrap());
    let joined = tools::append(&road, &other, &machine()).unwrap();
    let (l, j) = (road.reference_line(), joined.reference_line());
    // The other road's u increment is resampled to the first's.
    assert_eq!(j.n, l.n + 300);
    // The turn at the joint: half the first's last (the other road is straight).
    let last_turn = l.heading_at(l.n - 1) - l.heading_at(l.n - 2);
    assert!((j.heading_at(l.n) - l.heading_at(l.n - 1) - last_turn / 2.0).abs() < 1e-9);
    let step = (j.x[l.n] - l.x[l.n - 1]).hypot(j.y[l.n] - l.y[l.n - 1]);
    assert!((step - 0.1).abs() < 1e-9, "{step}");
    let cp = ContactPoint::new(Arc::new(joined));
    let end = l.u_last;
    let z_end = ContactPoint::new(road.clone()).uv_to_z(end, 0.0).unwrap();
    let z_after = cp.uv_to_z(end + 10.0, 0.0).unwrap();
    assert!((z_after - (z_end + 0.1 - 0.0)).abs() < 0.05, "{z_end} {z_after}");
    let far = Arc::new(RoadSpec::straight(30.0, 2.0, 0.1, 0.5).build().unwrap());
    let shifted = tools::cut(&far, (0.0, 30.0), None).unwrap();
    assert!(tools::append(&road, &Arc::new(shifted), &machine()).is_ok());
}

#[test]
fn resampling_keeps_the_surface_at_the_original_nodes_and_everywhere_at_its_own() {
    let road = winding_road();
    let finer = tools::resample(&road, Some(0.05), None, &machine()).unwrap();
    assert_eq!(finer.reference_line().n, 2 * road.reference_line().n - 1);
    assert_eq!(finer.u_range(), road.u_range(), "the same u range");
    let (worst, _) = worst_at_nodes(&road, &finer);
    assert!(worst < 1e-4, "at its own nodes: {worst}");
    // The new line bends smoothly through the old line's points, so its cross sections
    // there are turned by half an old corner: the old nodes 3 m aside lie between new
    // ones, on a surface interpolated from them.
    let (worst, _) = worst_at_nodes(&Arc::new(finer.clone()), &road);
    assert!(worst < 5e-4, "at the original nodes: {worst}");
    let coarser = tools::resample(&road, Some(0.37), Some(0.2), &machine()).unwrap();
    assert_eq!(coarser.increments(), (0.37, 0.2));
    let (worst, n) = worst_at_nodes(&road, &coarser);
    assert!(n > 500 * 30);
    assert!(worst < 1e-4, "at its own nodes: {worst}");
    // Its reference line's points lie on the old line.
    let mut cp = ContactPoint::new(road.clone());
    let l = coarser.reference_line();
    for i in (0..l.n).step_by(7) {
        let (_, v) = cp.xy_to_uv(l.x[i], l.y[i]).unwrap();
        assert!(v.abs() < 1e-3, "{v}");
    }
}

#[test]
fn slope_and_banking_move_between_line_and_grid_without_moving_the_surface() {
    let road = winding_road();
    for channel in [LineChannel::Slope, LineChannel::Banking] {
        let applied = tools::change_channel(&road, channel, ChannelAction::Apply).unwrap();
        let (worst, _) = worst_at_nodes(&road, &applied);
        assert!(worst < 1e-4, "{channel:?} applied: {worst}");
        let extracted = tools::change_channel(&applied, channel, ChannelAction::Extract).unwrap();
        let (worst, _) = worst_at_nodes(&road, &extracted);
        assert!(worst < 1e-4, "{channel:?} extracted: {worst}");
    }
    let flat = tools::change_channel(&road, LineChannel::Banking, ChannelAction::Remove).unwrap();
    assert!(!flat.reference_line().has_bank);
    assert!(tools::change_channel(&flat, LineChannel::Banking, ChannelAction::Remove).is_err());
    // The banking extracted from a banked grid is the banking that was applied.
    let applied = tools::change_channel(&road, LineChannel::Banking, ChannelAction::Apply).unwrap();
    let found = tools::change_channel(&applied, LineChannel::Banking, ChannelAction::Extract).unwrap();
    let b = found.reference_line().bank.clone().unwrap();
    let u = found.reference_line().u_at(700);
    assert!((b[700] - 0.03 * (u / 50.0).sin()).abs() < 2e-3, "{}", b[700]);
}

#[test]
fn filters_change_the_grid_as_they_say() {
    let spike = RoadSpec::straight(20.0, 2.0, 0.1, 0.1)
        .with_elevation(|u, v| {
            if (u - 10.0).abs() < 0.01 && v.abs() < 0.01 {
                1.0
            } else if u > 15.0 && v > 0.5 {
                f64::NAN
            } else {
                0.0
            }
        })
        .build()
        .unwrap();
    let median = tools::filter(&spike, Filter::Median(3), &machine()).unwrap();
    assert_eq!(median.grid().values().iter().filter(|z| **z > 0.5).count(), 0);
    let gauss = tools::filter(&spike, Filter::Gauss(0.1), &machine()).unwrap();
    let peak = gauss.grid().values().iter().copied().filter(|z| !z.is_nan()).fold(0.0f32, f32::max);
    assert!(peak > 0.05 && peak < 0.3, "{peak}");
    let limited = tools::filter(&spike, Filter::Limit(-0.1, 0.25), &machine()).unwrap();
    assert_eq!(limited.grid().values().iter().copied().filter(|z| !z.is_nan()).fold(0.0f32, f32::max), 0.25);
    assert!(spike.grid().values().iter().any(|z| z.is_nan()));
    let filled = tools::filter(&spike, Filter::FillNan, &machine()).unwrap();
    assert!(filled.grid().values().iter().all(|z| !z.is_nan()));
    assert!(tools::filter(&spike, Filter::Median(2), &machine()).is_err());
    assert!(tools::filter(&spike, Filter::Gauss(-1.0), &machine()).is_err());
}

/// y = 20 sin(x / 40) and z = 0.03 x, sampled every 2 m of x.
fn sine_points() -> Points {
    let x: Vec<f64> = (0..=150).map(|i| 2.0 * i as f64).collect();
    let y = x.iter().map(|x| 20.0 * (x / 40.0).sin()).collect();
    let z = x.iter().map(|x| 0.03 * x).collect();
    Points { x, y, z: Some(z) }
}

#[test]
fn a_generated_line_follows_the_smooth_curve_through_its_points() {
    let points = sine_points();
    let road = tools::generate(&points, Layout { width: 4.0, u_inc: 0.1, v_inc: 0.5 }, None, &machine()).unwrap();
    let l = road.reference_line();
    assert!(l.n > 3000);
    let mut worst = 0.0f64;
    for i in 0..l.n {
        // The distance to the curve, measured along the curve's normal.
        let (x, y) = (l.x[i], l.y[i]);
        let slope = 0.5 * (x / 40.0).cos();
        let off = (y - 20.0 * (x / 40.0).sin()) / (1.0 + slope * slope).sqrt();
        worst = worst.max(off.abs());
    }
    assert!(worst < 0.005, "{worst}");
    println!("generated line: {worst:.2e} m from the curve at most");
    // Cross sections exactly one increment apart, heading and curvature continuous.
    for i in 1..l.n {
        let d = (l.x[i] - l.x[i - 1]).hypot(l.y[i] - l.y[i - 1]);
        assert!((d - 0.1).abs() < 1e-9);
    }
    let cp = ContactPoint::new(Arc::new(road.clone()));
    let mut last = cp.uv_to_pk(0.05, 0.0).unwrap();
    for k in 1..3000 {
        let pk = cp.uv_to_pk(0.05 + k as f64 * 0.1, 0.0).unwrap();
        assert!((pk.0 - last.0).abs() < 0.01 && (pk.1 - last.1).abs() < 2e-3, "{k}: {last:?} {pk:?}");
        last = pk;
    }
    // The z column gives the slope.
    let z = l.z.as_ref().unwrap();
    for i in (0..l.n).step_by(50) {
        assert!((z[i] - 0.03 * l.x[i]).abs() < 0.005, "{} {}", z[i], l.x[i]);
    }
    let surfaced = tools::generate(
        &points,
        Layout { width: 4.0, u_inc: 0.1, v_inc: 0.5 },
        Some(&|u: f64, v: f64| 0.01 * u.sin() + v * 0.02),
        &machine(),
    )
    .unwrap();
    let (z0, z1) = (surfaced.grid().at(100, 0), surfaced.grid().at(100, 8));
    assert!(((z1 - z0) as f64 - 0.08).abs() < 1e-6);
}

#[test]
fn a_line_needs_points() {
    let one = Points { x: vec![1.0], y: vec![2.0], z: None };
    let layout = Layout { width: 4.0, u_inc: 0.1, v_inc: 0.5 };
    assert!(tools::generate(&one, layout, None, &machine()).unwrap_err().to_string().contains("at least two points"));
    let same = Points { x: vec![1.0, 1.0, 3.0], y: vec![2.0, 2.0, 3.0], z: None };
    assert!(tools::generate(&same, layout, None, &machine()).unwrap_err().to_string().contains("coincide"));
}

/// A known surface.
fn terrain(x: f64, y: f64) -> f64 {
    0.05 * (x / 3.0).sin() + 0.03 * (y / 2.0).cos() + 0.01 * x + 100.0
}

/// Points spread over [0, 100] x [-6, 6] (a jittered lattice 5 cm apart).
fn cloud() -> Points {
    let mut p = Points { z: Some(Vec::new()), ..Points::default() };
    let mut seed = 12345u64;
    let mut rand = move || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for i in 0..2000 {
        for j in 0..240 {
            let x = i as f64 * 0.05 + 0.04 * rand();
            let y = -6.0 + j as f64 * 0.05 + 0.04 * rand();
            p.x.push(x);
            p.y.push(y);
            p.z.as_mut().unwrap().push(terrain(x, y));
        }
    }
    p
}

#[test]
fn an_imported_cloud_gives_the_surface_it_was_sampled_from() {
    let cloud = cloud();
    let line = Points { x: vec![5.0, 30.0, 60.0, 95.0], y: vec![0.0, 1.5, -1.0, 0.5], z: None };
    let how = Import { refline: Some(line), width: Some(6.0), u_inc: 0.2, v_inc: 0.2, ..Import::default() };
    let road = Arc::new(tools::import(&cloud, &how, &|_, _, _| {}, &machine()).unwrap());
    let cp = ContactPoint::new(road.clone());
    let (mut worst, mut n) = (0.0f64, 0);
    let l = road.reference_line();
    for iu in 0..l.n {
        for &v in &road.grid().v {
            let u = l.u_at(iu);
            let z = cp.uv_to_z(u, v).unwrap();
            let (x, y) = cp.uv_to_xy(u, v).unwrap();
            worst = worst.max((z - terrain(x, y)).abs());
            n += 1;
        }
    }
    assert!(n > 400 * 30);
    assert!(worst < 0.002, "{worst}");
    // Without a line: one fitted through the cloud, as wide as the cloud reaches.
    let fitted =
        tools::import(&cloud, &Import { u_inc: 0.5, v_inc: 0.5, ..Import::default() }, &|_, _, _| {}, &machine())
            .unwrap();
    let w = fitted.v_range().1 - fitted.v_range().0;
    assert!(w > 10.0 && w <= 12.0, "{w}");
    // A line beyond the cloud.
    let beyond = Points { x: vec![50.0, 300.0], y: vec![0.0, 0.0], z: None };
    let how = Import { refline: Some(beyond), width: Some(4.0), u_inc: 0.5, v_inc: 0.5, ..Import::default() };
    let e = tools::import(&cloud, &how, &|_, _, _| {}, &machine()).unwrap_err().to_string();
    assert!(e.contains("beyond the cloud"), "{e}");
}

#[test]
fn a_cloud_with_stray_points_is_refused_at_once_and_imported_cropped() {
    // The cloud of the test above with two stray points 6,000 km away, as a scanner's
    // glitch leaves them.
    let mut cloud = cloud();
    cloud.x.extend([6.0e6, 20.0]);
    cloud.y.extend([0.0, -6.0e6]);
    cloud.z.as_mut().unwrap().extend([0.0, 0.0]);
    let how = Import { u_inc: 0.5, v_inc: 0.5, ..Import::default() };
    let started = std::time::Instant::now();
    let e = tools::import(&cloud, &how, &|_, _, _| {}, &Budget::with_bytes(200_000_000)).unwrap_err().to_string();
    assert!(started.elapsed().as_secs_f64() < 5.0, "refused after {:?}", started.elapsed());
    for words in ["the limit is", "all but 2 of the", "stray points?", "--crop "] {
        assert!(e.contains(words), "{words}: {e}");
    }
    // The crop the message proposes makes the road the cloud without them would make.
    let crop = e.rsplit("--crop ").next().unwrap().trim_end_matches(')');
    let (x, y) = crop.split_once(',').unwrap();
    let range = |r: &str| {
        let (a, b) = r.split_once(':').unwrap();
        (a.parse::<f64>().unwrap(), b.parse::<f64>().unwrap())
    };
    let cropped = Import { crop: Some([range(x), range(y)]), ..how.clone() };
    let road = tools::import(&cloud, &cropped, &|_, _, _| {}, &machine()).unwrap();
    let plain = tools::import(&self::cloud(), &how, &|_, _, _| {}, &machine()).unwrap();
    assert_eq!((road.grid().nu, road.grid().nv), (plain.grid().nu, plain.grid().nv));
    // A crop that leaves fewer than three points, or is no area, is refused.
    let e = tools::import(
        &cloud,
        &Import { crop: Some([(1e7, 2e7), (0.0, 1.0)]), ..how.clone() },
        &|_, _, _| {},
        &machine(),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("0 of the") && e.contains("at least three"), "{e}");
    let e = tools::import(&cloud, &Import { crop: Some([(5.0, 1.0), (0.0, 1.0)]), ..how }, &|_, _, _| {}, &machine())
        .unwrap_err()
        .to_string();
    assert!(e.contains("from the smaller to the larger"), "{e}");
}

#[test]
fn point_files_are_read_in_every_format() {
    let dir = std::env::temp_dir().join(format!("opencrg-points-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let pts: [(f64, f64, f64); 3] = [(1.0, 2.0, 3.0), (4.5, -1.25, 0.5), (7.0, 8.0, -9.0)];
    let csv = dir.join("p.csv");
    let mut text = String::from("id,Z,y,X\n");
    for (i, p) in pts.iter().enumerate() {
        text.push_str(&format!("{i},{},{},{}\n", p.2, p.1, p.0));
    }
    std::fs::write(&csv, text).unwrap();
    let xyz = dir.join("p.xyz");
    std::fs::write(&xyz, pts.iter().map(|p| format!("{} {} {}\n", p.0, p.1, p.2)).collect::<String>()).unwrap();
    let ply = dir.join("p.ply");
    let mut bytes = format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty double x\nproperty float y\nproperty double z\nproperty uchar red\nend_header\n",
        pts.len()
    )
    .into_bytes();
    for p in &pts {
        bytes.extend(p.0.to_le_bytes());
        bytes.extend((p.1 as f32).to_le_bytes());
        bytes.extend(p.2.to_le_bytes());
        bytes.push(7);
    }
    std::fs::write(&ply, bytes).unwrap();
    let ascii = dir.join("a.ply");
    let mut text = format!(
        "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
        pts.len()
    );
    for p in &pts {
        text.push_str(&format!("{} {} {}\n", p.0, p.1, p.2));
    }
    std::fs::write(&ascii, text).unwrap();
    let want = Points {
        x: pts.iter().map(|p| p.0).collect(),
        y: pts.iter().map(|p| p.1).collect(),
        z: Some(pts.iter().map(|p| p.2).collect()),
    };
    for f in [&csv, &xyz, &ply, &ascii] {
        assert_eq!(tools::read_points(f).unwrap(), want, "{}", f.display());
    }
    let no_xy = dir.join("bad.csv");
    std::fs::write(&no_xy, "a,b\n1,2\n").unwrap();
    let e = tools::read_points(&no_xy).unwrap_err().to_string();
    assert!(e.contains("bad.csv:1") && e.contains("x and y"), "{e}");
    let short = dir.join("short.csv");
    std::fs::write(&short, "1 2 3\n4\n").unwrap();
    assert!(tools::read_points(&short).unwrap_err().to_string().contains("short.csv:2"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn compare_finds_the_largest_difference_and_where() {
    let road = winding_road();
    let same = tools::compare(&road, &road, &|_, _, _| {}).unwrap();
    assert_eq!(same.compared, road.grid().values().len());
    assert!(same.max_difference < 1e-9);
    let bumped = Arc::new(tools::filter(&road, Filter::Limit(-0.005, 0.005), &machine()).unwrap());
    let c = tools::compare(&road, &bumped, &|_, _, _| {}).unwrap();
    assert!((c.max_difference - 0.007).abs() < 1e-3, "{c:?}");
    assert!(c.rms > 0.0 && c.rms < c.max_difference);
    let part = Arc::new(tools::cut(&road, (0.0, 100.0), None).unwrap());
    let c = tools::compare(&road, &part, &|_, _, _| {}).unwrap();
    assert!(c.only_first > 0 && c.max_difference < 1e-4, "{c:?}");
}

#[test]
fn bad_ranges_are_refused_and_the_input_left_alone() {
    let road = winding_road();
    let before = road.grid().values().to_vec();
    let e = tools::cut(&road, (300.0, 400.0), None).unwrap_err().to_string();
    assert!(e.contains("u range 300:400") && e.contains("fewer than two"), "{e}");
    assert!(tools::cut(&road, (10.0, 20.0), Some((5.0, 9.0))).is_err());
    assert!(tools::resample(&road, Some(500.0), None, &machine()).is_err());
    assert!(tools::resample(&road, Some(-1.0), None, &machine()).is_err());
    assert_eq!(road.grid().values(), &before[..]);
}
