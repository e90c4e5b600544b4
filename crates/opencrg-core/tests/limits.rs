//! A request the system cannot give memory for is refused and leaves things as they were.

use opencrg_core::synth::RoadSpec;
use opencrg_core::ContactPoint;
use std::sync::Arc;

#[test]
fn a_search_history_beyond_memory_is_refused_and_the_old_one_kept() {
    let mut cp = ContactPoint::new(Arc::new(RoadSpec::straight(60.0, 4.0, 0.1, 0.25).build().unwrap()));
    cp.set_history(5).unwrap();
    let e = cp.set_history(usize::MAX / 2).unwrap_err().to_string();
    assert!(e.contains("search history") && e.contains("refused the memory"), "{e}");
    assert_eq!(cp.search_history().size, 5);
    assert!(cp.uv_to_z(10.0, 0.5).is_ok());
}
