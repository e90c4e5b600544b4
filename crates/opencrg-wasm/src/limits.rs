//! How much the module may take for one request.

/// The most memory a view's mesh may take (WebAssembly's memory is 4 GiB at most).
pub(crate) const VIEW_MEMORY: u64 = 1 << 30;
