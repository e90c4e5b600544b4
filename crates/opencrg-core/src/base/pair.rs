//! Two doubles side by side, written with one store: the one place where how a pair is
//! stored differs by platform.
//!
//! A processor hands a value still in its store buffer to a later load (store-to-load
//! forwarding) only when one store holds everything the load reads. The compiler reads
//! neighbouring doubles with one 16-byte load where it computes with both, but writes
//! them with two 8-byte stores when they come from two registers; such a load then waits
//! until both stores have reached the cache. A contact point shared by the wheels meets
//! this at every call (each reads the position the call before wrote): the wait cost
//! about an eighth of an x/y search. [`Pair::set`] writes both halves with one store.

/// Two doubles, read together and written with [`Pair::set`].
#[derive(Debug, Clone, Copy, Default, PartialEq)]
#[repr(C)]
pub(crate) struct Pair(pub(crate) [f64; 2]);

impl Pair {
    /// Writes `a` and `b` with one store.
    #[inline(always)]
    pub(crate) fn set(&mut self, a: f64, b: f64) {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::{_mm_set_pd, _mm_storeu_pd};
            // SAFETY: SSE2 is part of every x86_64 target; the store writes the 16 bytes
            // of the array.
            unsafe { _mm_storeu_pd(self.0.as_mut_ptr(), _mm_set_pd(b, a)) }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            // Elsewhere the compiler writes a pair of registers with one instruction
            // (`stp` on 64-bit Arm).
            self.0 = [a, b];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Pair;

    #[test]
    fn set_writes_both_halves_in_order() {
        let mut p = Pair::default();
        p.set(1.5, -2.25);
        assert_eq!(p.0, [1.5, -2.25]);
        p.set(f64::NAN, 0.0);
        assert!(p.0[0].is_nan());
        assert_eq!(p.0[1].to_bits(), 0.0f64.to_bits());
    }
}
