/*
 * A stand-in for Windows' bcryptprimitives.dll, for running the Windows build's programs
 * under wine 8 (Debian 12's), which lacks it: Windows 10 and later have it, and Rust's
 * standard library takes its random numbers from its ProcessPrng. Used by the tests
 * only (c-tests/cross/run.sh); never shipped.
 */
#include <windows.h>
#include <ntsecapi.h>

BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T len)
{
    while (len > 0) {
        ULONG n = len > 0x10000000 ? 0x10000000 : (ULONG)len;
        if (!RtlGenRandom(data, n))
            return FALSE;
        data += n;
        len -= n;
    }
    return TRUE;
}
