/* Answers of the reference OpenCRG C library (built by ../shared/reference/build-references.sh)
 * for the CRG-mode tests of opencrg-odr.
 * usage: crg_reference_answers FILE.crg own|none < queries
 *   own : the file's own modifiers (it has a $ROAD_CRG_MODS section) applied;
 *   none: the default modifiers the loader sets removed first (the file has none).
 * Each query line "uv U V" (crgEvaluv2z) or "xy X Y" (crgEvalxy2z) gets one line: z, or nan. */
#include <stdio.h>
#include <string.h>

#include "crgBaseLib.h"

int main(int argc, char** argv)
{
    if (argc != 3)
    {
        fprintf(stderr, "usage: %s FILE.crg own|none < queries\n", argv[0]);
        return 2;
    }
    crgMsgSetLevel(0);
    int id = crgLoaderReadFile(argv[1]);
    if (id <= 0)
        return 1;
    if (strcmp(argv[2], "none") == 0)
        crgDataSetModifierRemoveAll(id);
    crgDataSetModifiersApply(id);
    int cp = crgContactPointCreate(id);
    char kind[8];
    double a, b, z;
    while (scanf("%7s %lf %lf", kind, &a, &b) == 3)
    {
        int ok = strcmp(kind, "uv") == 0 ? crgEvaluv2z(cp, a, b, &z) : crgEvalxy2z(cp, a, b, &z);
        if (ok)
            printf("%.17g\n", z);
        else
            printf("nan\n");
    }
    return 0;
}
