/*
 * Linked with lld-link against opencrg.lib, the import library in the format MSVC's
 * linker writes and reads, as a program built by MSVC would be, but without a C runtime
 * (none is at hand here): an entry of its own, no arguments. Loads road.crg from the
 * working folder, evaluates a point there and back; the exit status tells what failed:
 * 0 nothing, 1 the load, 2 the contact point, 3 an evaluation, 4 the answer.
 */
#include "crgBaseLib.h"

/* Every program using floating point under MSVC's conventions defines this (normally
 * the C runtime does). */
int _fltused = 0;

int opencrg_entry(void)
{
    double z = 0.0, u = 0.0, v = 0.0, x = 0.0, y = 0.0;
    int id, cp;
    crgMsgSetLevel(dCrgMsgLevelNone);
    id = crgLoaderReadFile("road.crg");
    if (id <= 0)
        return 1;
    cp = crgContactPointCreate(id);
    if (cp < 0)
        return 2;
    if (!crgEvaluv2xy(cp, 10.0, 0.5, &x, &y) || !crgEvalxy2uv(cp, x, y, &u, &v) || !crgEvaluv2z(cp, u, v, &z))
        return 3;
    /* x/y and back: the same point within a micrometre, and a finite elevation. */
    if (u - 10.0 > 1e-6 || 10.0 - u > 1e-6 || v - 0.5 > 1e-6 || 0.5 - v > 1e-6 || crgIsNan(&z))
        return 4;
    crgMemRelease();
    return 0;
}
