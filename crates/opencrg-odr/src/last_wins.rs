//! Which CRG record holds where: of each purpose, the last record whose `sStart`..`sEnd`
//! holds s wins (in the file's order, a road's own before its junction's). Found at one s,
//! at many s in one sweep, and the records that hold nowhere left out.

use crate::crg::Layer;
use crate::map::{CrgPurpose, CrgRecord};
use std::collections::{BTreeMap, BinaryHeap};

/// The last of `layers` with `purpose` that holds at s (the last record wins).
pub(crate) fn layer_at(layers: &[Layer], purpose: CrgPurpose, s: f64) -> Option<usize> {
    layers.iter().rposition(|l| l.record.purpose == purpose && l.record.s_start <= s && s <= l.record.s_end)
}

/// Of `records`, the last with `purpose` that holds at each of `points` (s, ascending), as
/// [`layer_at`] finds it, in one sweep: the records by start, the last one started on top
/// of a heap until it ends.
pub(crate) fn last_holding(
    records: &[&CrgRecord],
    purpose: CrgPurpose,
    points: impl Iterator<Item = f64>,
) -> Vec<Option<usize>> {
    let mut by_start: Vec<usize> = (0..records.len()).filter(|&i| records[i].purpose == purpose).collect();
    by_start.sort_by(|&a, &b| records[a].s_start.total_cmp(&records[b].s_start));
    let (mut started, mut next) = (BinaryHeap::new(), 0);
    points
        .map(|s| {
            while next < by_start.len() && records[by_start[next]].s_start <= s {
                started.push(by_start[next]);
                next += 1;
            }
            while started.peek().is_some_and(|&i| !(s <= records[i].s_end)) {
                started.pop();
            }
            started.peek().copied()
        })
        .collect()
}

/// An f64's place in the order of all f64 (for the keys of a B-tree).
fn order(x: f64) -> u64 {
    let bits = x.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

/// `records` (in the order they apply) less those that never hold: of each purpose the
/// last record whose range holds s wins, so a record whose range later ones of its
/// purpose cover is never seen (a junction's many records on every connecting road).
pub(crate) fn visible<T>(records: Vec<T>, record: impl Fn(&T) -> &CrgRecord) -> Vec<T> {
    // Per purpose, the union of the later records' ranges: disjoint ranges by start.
    let mut covered: [BTreeMap<u64, (f64, f64)>; 2] = Default::default();
    let mut keep = vec![false; records.len()];
    for (i, r) in records.iter().map(&record).enumerate().rev() {
        let union = &mut covered[usize::from(r.purpose == CrgPurpose::Friction)];
        let (mut lo, mut hi) = (r.s_start, r.s_end);
        // The covered range starting last at or before lo: covering the record, or joined.
        if let Some((_, &(start, end))) = union.range(..=order(lo)).next_back() {
            if hi <= end {
                continue;
            }
            if lo <= end {
                lo = start;
            }
        }
        keep[i] = true;
        while let Some((&key, &(_, end))) = union.range(order(lo)..=order(hi)).next() {
            union.remove(&key);
            hi = hi.max(end);
        }
        union.insert(order(lo), (lo, hi));
    }
    records.into_iter().zip(keep).filter_map(|(r, keep)| keep.then_some(r)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::map::{CrgMode, CrgOrientation};

    fn record(purpose: CrgPurpose, s_start: f64, s_end: f64, line: usize) -> CrgRecord {
        CrgRecord {
            file: String::new(),
            path: Default::default(),
            s_start,
            s_end,
            mode: CrgMode::Attached0,
            orientation: CrgOrientation::Same,
            purpose,
            s_offset: 0.0,
            t_offset: 0.0,
            z_offset: 0.0,
            z_scale: 1.0,
            h_offset: 0.0,
            x_offset: 0.0,
            y_offset: 0.0,
            given: Vec::new(),
            line,
        }
    }

    /// Random records (ranges over 0..100, both purposes): the sweep finds at every s the
    /// record the last-record-wins rule names, and the records left out as never holding
    /// are exactly those that hold nowhere.
    #[test]
    fn the_last_record_wins_by_sweep_and_the_hidden_ones_go() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for round in 0..200 {
            let n = 1 + round % 40;
            let records: Vec<CrgRecord> = (0..n)
                .map(|i| {
                    let purpose = if next() < 0.7 { CrgPurpose::Elevation } else { CrgPurpose::Friction };
                    let a = (next() * 100.0).round();
                    let b = if next() < 0.1 { f64::INFINITY } else { a + (next() * 40.0).round() };
                    record(purpose, a, b, i)
                })
                .collect();
            let refs: Vec<&CrgRecord> = records.iter().collect();
            let points: Vec<f64> = (-2..=300).map(|k| k as f64 * 0.5).collect();
            let rule =
                |p: CrgPurpose, s: f64| refs.iter().rposition(|r| r.purpose == p && r.s_start <= s && s <= r.s_end);
            let mut seen = vec![false; n];
            for p in [CrgPurpose::Elevation, CrgPurpose::Friction] {
                let swept = last_holding(&refs, p, points.iter().copied());
                for (&s, &found) in points.iter().zip(&swept) {
                    assert_eq!(found, rule(p, s), "round {round} s {s}");
                    if let Some(i) = found {
                        seen[i] = true;
                    }
                }
            }
            // The points are the ranges' ends and the halves between: every record that
            // holds anywhere holds at one of them.
            let kept: Vec<usize> = visible(refs.clone(), |r| r).iter().map(|r| r.line).collect();
            let holding: Vec<usize> = (0..n).filter(|&i| seen[i]).collect();
            assert_eq!(kept, holding, "round {round}");
        }
    }
}
