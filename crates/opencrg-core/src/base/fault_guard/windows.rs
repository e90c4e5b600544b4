//! Windows: an in-page error (the device could not read the page: a disk error, a network
//! share gone) reading inside a guarded mapping replaces the whole view by memory that
//! reads as zeros, page by page as it is touched; any other exception goes on to the
//! other handlers. (Windows itself refuses to cut short a mapped file; under wine, a read
//! of a file cut short from outside arrives as an access violation, answered alike.)
//!
//! Windows maps no other memory over part of a view, so the view is unmapped and its
//! address range reserved again at once; a thread reading the range meanwhile or after
//! meets an access violation there, which commits a page of zeros for it. The range stays
//! reserved after the mapping is dropped (address space only, and only after a fault), so
//! that the view's own unmapping, which then finds no view, can never reach another
//! mapping made at that address since.

use super::table;
use std::ffi::c_void;
use std::sync::atomic::{AtomicU8, Ordering};

/// `EXCEPTION_POINTERS`.
#[repr(C)]
struct ExceptionPointers {
    record: *const ExceptionRecord,
    context: *mut c_void,
}

/// `EXCEPTION_RECORD`.
#[repr(C)]
struct ExceptionRecord {
    code: u32,
    flags: u32,
    next: *const ExceptionRecord,
    address: *mut c_void,
    parameters: u32,
    information: [usize; 15],
}

type Handler = unsafe extern "system" fn(*mut ExceptionPointers) -> i32;

#[link(name = "kernel32")]
extern "system" {
    fn AddVectoredExceptionHandler(first: u32, handler: Handler) -> *mut c_void;
    fn UnmapViewOfFile(base: *const c_void) -> i32;
    fn VirtualAlloc(address: *mut c_void, size: usize, kind: u32, protect: u32) -> *mut c_void;
    fn VirtualFree(address: *mut c_void, size: usize, kind: u32) -> i32;
    fn GetModuleHandleExW(flags: u32, name: *const u16, module: *mut *mut c_void) -> i32;
}

const EXCEPTION_ACCESS_VIOLATION: u32 = 0xC000_0005;
const EXCEPTION_IN_PAGE_ERROR: u32 = 0xC000_0006;
const EXCEPTION_CONTINUE_EXECUTION: i32 = -1;
const EXCEPTION_CONTINUE_SEARCH: i32 = 0;
const MEM_COMMIT: u32 = 0x1000;
const MEM_RESERVE: u32 = 0x2000;
const MEM_DECOMMIT: u32 = 0x4000;
const PAGE_NOACCESS: u32 = 0x01;
const PAGE_READONLY: u32 = 0x02;
const GET_MODULE_HANDLE_EX_FLAG_PIN: u32 = 0x1;
const GET_MODULE_HANDLE_EX_FLAG_FROM_ADDRESS: u32 = 0x4;
/// The page size of every processor Windows runs on.
const PAGE: usize = 4096;

/// What became of a guarded mapping's view.
const MAPPED: u8 = 0;
const REPLACING: u8 = 1;
const REPLACED: u8 = 2;
/// The range could not be reserved again: faults in it end the process.
const LOST: u8 = 3;

#[allow(clippy::declare_interior_mutable_const)] // each entry of the table is its own
const VIEW_MAPPED: AtomicU8 = AtomicU8::new(MAPPED);
/// The state of the view of each slot of the table.
static VIEWS: [AtomicU8; table::SLOTS] = [VIEW_MAPPED; table::SLOTS];
static INSTALL: std::sync::Once = std::sync::Once::new();

/// Installs the handler once.
pub(super) fn install() {
    INSTALL.call_once(|| {
        keep_loaded();
        // SAFETY: the handler has the signature the call documents and stays loaded.
        unsafe { AddVectoredExceptionHandler(1, on_fault) };
    });
}

/// Marks the library holding this code as never to be unloaded (its handler stays
/// installed after an FMU or a Python module is released).
fn keep_loaded() {
    let mut module = std::ptr::null_mut();
    // SAFETY: with FROM_ADDRESS the name is an address inside the module; the call writes
    // the module's handle, pinned, into `module`.
    unsafe {
        GetModuleHandleExW(
            GET_MODULE_HANDLE_EX_FLAG_FROM_ADDRESS | GET_MODULE_HANDLE_EX_FLAG_PIN,
            on_fault as *const u16,
            &mut module,
        )
    };
}

/// Gives back the pages of zeros of a replaced view when its mapping is no longer
/// guarded (the range stays reserved, see the module's text).
pub(super) fn forget(slot: usize) {
    if VIEWS[slot].swap(MAPPED, Ordering::AcqRel) == REPLACED {
        let (start, len) = table::range(slot);
        // SAFETY: the range is the reservation `on_fault` made in place of the view, which
        // nobody reads any more (the mapping is being dropped).
        unsafe { VirtualFree(start as *mut c_void, len, MEM_DECOMMIT) };
    }
}

/// The vectored exception handler: a read that faults inside a guarded mapping reads
/// zeros from then on, and the mapping is marked.
unsafe extern "system" fn on_fault(pointers: *mut ExceptionPointers) -> i32 {
    // SAFETY: the system hands the handler valid exception pointers.
    let record = unsafe { &*(*pointers).record };
    let read = record.parameters >= 2 && record.information[0] == 0;
    if !(read && (record.code == EXCEPTION_IN_PAGE_ERROR || record.code == EXCEPTION_ACCESS_VIOLATION)) {
        return EXCEPTION_CONTINUE_SEARCH;
    }
    let addr = record.information[1];
    let Some((slot, start, len)) = table::fault_at(addr) else {
        return EXCEPTION_CONTINUE_SEARCH;
    };
    let view = &VIEWS[slot];
    if view.compare_exchange(MAPPED, REPLACING, Ordering::AcqRel, Ordering::Acquire).is_ok() {
        // SAFETY: the view at `start` is this library's and registered; its readers are
        // told through `faulted` and read zeros from the reservation made in its place.
        let again = unsafe {
            UnmapViewOfFile(start as *const c_void);
            VirtualAlloc(start as *mut c_void, len, MEM_RESERVE, PAGE_NOACCESS)
        };
        view.store(if again as usize == start { REPLACED } else { LOST }, Ordering::Release);
    }
    // The thread replacing the view is done within a few system calls.
    let state = loop {
        match view.load(Ordering::Acquire) {
            REPLACING => std::hint::spin_loop(),
            state => break state,
        }
    };
    if state != REPLACED {
        return EXCEPTION_CONTINUE_SEARCH;
    }
    // SAFETY: the page lies in the range reserved in place of the view.
    let page = unsafe { VirtualAlloc((addr & !(PAGE - 1)) as *mut c_void, PAGE, MEM_COMMIT, PAGE_READONLY) };
    if page.is_null() {
        EXCEPTION_CONTINUE_SEARCH
    } else {
        EXCEPTION_CONTINUE_EXECUTION
    }
}
