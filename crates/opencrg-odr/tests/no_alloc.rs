//! A wheel's queries allocate nothing once its probe has met the road: the ground along
//! a road with an attached CRG file, counted by a global allocator that counts.

use opencrg_core::synth::RoadSpec;
use opencrg_odr::Surface;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is passed to the system allocator unchanged; only counted.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: the caller's layout, as the system allocator requires it.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` came from `alloc` above with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: as for `dealloc`, and the new size the caller asks for.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

#[test]
fn a_wheel_along_a_road_allocates_nothing() {
    let dir = std::env::temp_dir().join(format!("opencrg-odr-{}-no-alloc", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let crg = RoadSpec::straight(200.0, 4.0, 0.1, 0.1).with_elevation(|u, v| 0.004 * (u * 3.0).sin() + 0.002 * v);
    std::fs::write(dir.join("bumps.crg"), crg.to_crg()).unwrap();
    let map = r#"<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="r" length="300" junction="-1">
<planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry>
<geometry s="100" x="100" y="0" hdg="0" length="200"><spiral curvStart="0" curvEnd="0.005"/></geometry></planView>
<elevationProfile><elevation s="0" a="1" b="0.02" c="0" d="0"/></elevationProfile>
<lateralProfile><superelevation s="0" a="0.03" b="0" c="0" d="0"/></lateralProfile>
<lanes><laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/><height sOffset="0" inner="0" outer="0.02"/></lane></left>
<center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/><material sOffset="0" friction="0.9"/></lane></right></laneSection></lanes>
<surface><CRG file="bumps.crg" sStart="50" sEnd="250" mode="attached" orientation="same" sOffset="50"/></surface>
</road></OpenDRIVE>"#;
    std::fs::write(dir.join("map.xodr"), map).unwrap();
    let surface = Arc::new(Surface::load(dir.join("map.xodr")).unwrap());
    let road = &surface.map().roads[0];
    let points: Vec<(f64, f64)> = (0..12_000)
        .map(|i| {
            let p = road.surface_point(30.0 + i as f64 * 0.02, if i % 2 == 0 { 1.2 } else { -1.7 });
            (p[0], p[1])
        })
        .collect();
    let (mut left, mut right) = (surface.probe(), surface.probe());
    // The first queries find the road and make the contact point on the CRG file.
    for &(x, y) in &points[..200] {
        let _ = left.ground(x, y);
        let _ = right.ground(x, y);
    }
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    let mut found = 0;
    for (i, &(x, y)) in points.iter().enumerate().skip(200) {
        let probe = if i % 2 == 0 { &mut left } else { &mut right };
        found += usize::from(probe.ground(x, y).is_some_and(|g| g.z.is_finite()));
    }
    let allocations = ALLOCATIONS.load(Ordering::Relaxed) - before;
    assert_eq!(found, points.len() - 200);
    assert_eq!(allocations, 0, "{allocations} allocations in {} queries", points.len() - 200);
}
