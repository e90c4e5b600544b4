//! Mutexes that outlive a panic: the tables stay usable after a call that panicked
//! (and was refused by the panic guard) while holding a lock.

/// Locks a mutex, recovering the data if an earlier panic poisoned it.
pub fn lock<T>(m: &std::sync::Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}
