//! The id tables the classic API demands: data sets and contact points.
//!
//! Data sets live in one table behind a lock. Contact points live in a table of slots
//! ([`Slots`]: each its own lock and its owner's lock-free path), so evaluation on
//! different contact points from different threads never waits on a shared lock.
//! Closures run under a lock are `Send`, so that they cannot send a message (see
//! [`crate::entry`]).

use crate::lock::lock;
use crate::slots::Slots;
use opencrg_core::{ContactPoint, Road};
use std::ffi::c_int;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// A loaded data set.
pub struct DataSet {
    pub id: c_int,
    pub road: Arc<Road>,
}

static DATASETS: Mutex<Vec<DataSet>> = Mutex::new(Vec::new());

/// The contact points, by id, with the data set each was made from.
static CPS: Slots<CpEntry> = Slots::new();

/// A contact point and its performance statistics.
struct CpEntry {
    cp: ContactPoint,
    stats: PerfStat,
}

/// The calls on one contact point and the time they took, counted while active
/// (`crgContactPointActivatePerfStat`).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PerfStat {
    /// Whether calls are counted.
    pub active: bool,
    /// The calls counted.
    pub calls: u64,
    /// Their time, in nanoseconds.
    pub nanos: u64,
    /// The longest of them, in nanoseconds.
    pub longest: u64,
}

/// How many contact points have active statistics: the evaluation calls take the counted
/// way only while there is one.
static COUNTED_CPS: AtomicUsize = AtomicUsize::new(0);

/// Whether any contact point's calls are being counted.
#[inline(always)]
pub fn counting() -> bool {
    COUNTED_CPS.load(Ordering::Relaxed) != 0
}

/// Forgets the statistics of a contact point that is deleted.
fn forget_stats(e: &CpEntry) {
    if e.stats.active {
        COUNTED_CPS.fetch_sub(1, Ordering::Relaxed);
    }
}

/// Adds a road; returns its id (one more than the largest id in use).
pub fn add_dataset(road: Road) -> c_int {
    let mut sets = lock(&DATASETS);
    let id = sets.iter().map(|d| d.id).max().unwrap_or(0) + 1;
    sets.push(DataSet { id, road: Arc::new(road) });
    id
}

/// Runs `f` on a data set; `None` for an unknown id.
pub fn with_dataset<R>(id: c_int, f: impl FnOnce(&mut DataSet) -> R + Send) -> Option<R> {
    let mut sets = lock(&DATASETS);
    sets.iter_mut().find(|d| d.id == id).map(f)
}

/// Changes a data set's road; contact points of that data set follow the change.
pub fn modify_road<R>(id: c_int, f: impl FnOnce(&mut Road) -> R + Send) -> Option<R> {
    let (result, road) = with_dataset(id, |d| {
        let r = f(Arc::make_mut(&mut d.road));
        (r, d.road.clone())
    })?;
    for_each_cp_of(Some(id), |cp| {
        if !Arc::ptr_eq(cp.road(), &road) {
            cp.set_road(road.clone());
        }
    });
    Some(result)
}

/// Removes a data set and its contact points.
///
/// The contact points go while the data set table is still locked: once the lock is
/// released the id may be given to a new data set (ids are one more than the largest in
/// use), and the new data set's contact points must not be taken for the old one's.
pub fn release_dataset(id: c_int) -> bool {
    let mut sets = lock(&DATASETS);
    let before = sets.len();
    sets.retain(|d| d.id != id);
    let removed = sets.len() != before;
    if removed {
        delete_cps_of(Some(id));
    }
    removed
}

/// Ids of every data set.
pub fn dataset_ids() -> Vec<c_int> {
    lock(&DATASETS).iter().map(|d| d.id).collect()
}

/// Creates a contact point on a data set; its id (the largest free one, else a new
/// one), or -1.
pub fn create_cp(dataset: c_int) -> c_int {
    let Some(road) = with_dataset(dataset, |d| d.road.clone()) else { return -1 };
    CPS.create(dataset, CpEntry { cp: ContactPoint::new(road), stats: PerfStat::default() })
}

/// Runs `f` on a contact point; `None` for an unknown id.
#[inline]
pub fn with_cp<R>(id: c_int, f: impl FnOnce(&mut ContactPoint) -> R + Send) -> Option<R> {
    CPS.with_mut(id, |e| f(&mut e.cp))
}

/// Changes the performance statistics of a contact point (`f` on them) and gives them;
/// `None` for an unknown id.
pub fn perf_stat(id: c_int, f: impl FnOnce(&mut PerfStat) + Send) -> Option<PerfStat> {
    CPS.with_mut(id, |e| {
        let was_active = e.stats.active;
        f(&mut e.stats);
        match (was_active, e.stats.active) {
            (false, true) => COUNTED_CPS.fetch_add(1, Ordering::Relaxed),
            (true, false) => COUNTED_CPS.fetch_sub(1, Ordering::Relaxed),
            _ => 0,
        };
        e.stats
    })
}

/// Adds one call that took `nanos` to a contact point's statistics, when they are active.
pub fn count_call(id: c_int, nanos: u64) {
    CPS.with_mut(id, |e| {
        if e.stats.active {
            e.stats.calls += 1;
            e.stats.nanos = e.stats.nanos.saturating_add(nanos);
            e.stats.longest = e.stats.longest.max(nanos);
        }
    });
}

/// Runs `f` on a contact point when this thread owns it; `None` (without running
/// `f`) otherwise: the first try of the hottest entry points, with no lock and no
/// call. `f` must not panic (this runs outside any panic guard).
#[inline(always)]
pub fn with_owned_cp_mut<R>(id: c_int, f: impl FnOnce(&mut ContactPoint) -> R + Send) -> Option<R> {
    CPS.with_owned_mut(id, |e| f(&mut e.cp))
}

/// Deletes one contact point.
pub fn delete_cp(id: c_int) -> bool {
    CPS.delete(id).inspect(forget_stats).is_some()
}

/// Runs `f` on every contact point of a data set (`None`: of every data set).
fn for_each_cp_of(dataset: Option<c_int>, mut f: impl FnMut(&mut ContactPoint) + Send) {
    CPS.for_each_of(dataset, |e| f(&mut e.cp));
}

/// Deletes the contact points of one data set, or all of them (and empties the table).
pub fn delete_cps_of(dataset: Option<c_int>) {
    CPS.delete_of(dataset, forget_stats);
}

/// Applies `f` to every contact point; what it gives for each, in the order of their ids.
pub fn update_all_cps<R: Send>(mut f: impl FnMut(&mut ContactPoint) -> R + Send) -> Vec<R> {
    let mut out = Vec::new();
    for_each_cp_of(None, |cp| out.push(f(cp)));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::owner::OWNER_STREAK;
    use crate::thread_id::thread_id;
    use opencrg_core::settings::opt;
    use opencrg_core::synth::RoadSpec;

    fn new_cp() -> c_int {
        let road = RoadSpec::straight(10.0, 2.0, 0.5, 0.5).build().expect("a valid road");
        create_cp(add_dataset(road))
    }

    fn counter(cp: &ContactPoint) -> f64 {
        cp.options().get_double(opt::BORDER_OFFSET_U).unwrap_or(0.0)
    }

    /// Adds one to a counter kept in the contact point's options, by reading and
    /// writing it back (two steps: a second thread inside at the same time loses updates).
    fn bump(cp: &mut ContactPoint) {
        let v = counter(cp);
        // A wide window between the two steps, so that an overlap would show.
        for _ in 0..200 {
            std::hint::spin_loop();
        }
        cp.set_option_double(opt::BORDER_OFFSET_U, v + 1.0).expect("a double option");
    }

    #[test]
    fn a_thread_using_a_contact_point_becomes_its_owner() {
        // Where membarrier is refused nobody may become owner; the test then checks that.
        let owner_path = crate::barrier::available();
        if !owner_path {
            eprintln!("membarrier is not available here: checking that every call takes the lock");
        }
        let id = new_cp();
        let s = CPS.slot(id as usize).expect("a slot");
        assert_eq!(s.cell.owner(), 0);
        for _ in 0..OWNER_STREAK {
            with_cp(id, bump);
        }
        let expected_owner = if owner_path { thread_id() } else { 0 };
        assert_eq!(s.cell.owner(), expected_owner);
        std::thread::spawn(move || with_cp(id, bump)).join().expect("no panic");
        assert_eq!(s.cell.owner(), 0, "another thread's access revokes the ownership");
        assert_eq!(with_cp(id, |cp| counter(cp)), Some(f64::from(OWNER_STREAK + 1)));
        assert!(delete_cp(id));
        assert_eq!(with_cp(id, |cp| counter(cp)), None);
    }

    #[test]
    fn the_counted_way_is_taken_while_a_contact_point_counts() {
        // Other tests run in parallel but never activate statistics.
        let (a, b) = (new_cp(), new_cp());
        assert!(!counting());
        perf_stat(a, |s| s.active = true);
        perf_stat(b, |s| s.active = true);
        perf_stat(b, |s| s.active = true);
        assert_eq!(COUNTED_CPS.load(Ordering::Relaxed), 2, "activating twice counts once");
        count_call(a, 40);
        count_call(a, 60);
        assert_eq!(perf_stat(a, |_| {}).map(|s| (s.calls, s.nanos, s.longest)), Some((2, 100, 60)));
        perf_stat(a, |s| s.active = false);
        count_call(a, 40);
        assert_eq!(perf_stat(a, |_| {}).map(|s| s.calls), Some(2), "not counted while inactive");
        assert!(counting(), "b still counts");
        assert!(delete_cp(b));
        assert!(!counting(), "deleting a counting contact point ends the counted way");
        assert!(delete_cp(a));
    }

    #[test]
    fn a_released_id_given_again_keeps_the_new_contact_points() {
        // Each thread loads, makes a contact point, checks it and releases, over and
        // over: ids are given again at once, so a release that removed contact points
        // after giving up the table would now and then take another thread's.
        let road = RoadSpec::straight(10.0, 2.0, 0.5, 0.5).build().expect("a valid road");
        std::thread::scope(|scope| {
            for _ in 0..8 {
                let road = road.clone();
                scope.spawn(move || {
                    for _ in 0..2_000 {
                        let set = add_dataset(road.clone());
                        let cp = create_cp(set);
                        assert!(cp >= 0);
                        std::thread::yield_now();
                        assert!(with_cp(cp, |_| ()).is_some(), "contact point {cp} of data set {set} lost");
                        assert!(release_dataset(set));
                    }
                });
            }
        });
    }

    #[test]
    fn threads_sharing_a_contact_point_never_overlap() {
        let id = new_cp();
        let (threads, rounds) = (4u32, 20_000u32);
        std::thread::scope(|scope| {
            for t in 0..threads {
                scope.spawn(move || {
                    for i in 0..rounds {
                        with_cp(id, bump);
                        // Runs of calls long enough to take ownership, then a switch.
                        if (i + t) % 50 == 0 {
                            std::thread::yield_now();
                        }
                    }
                });
            }
        });
        assert_eq!(with_cp(id, |cp| counter(cp)), Some(f64::from(threads * rounds)));
    }
}
