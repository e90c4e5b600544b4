/* Converts x/y points to u/v on a road.
 * usage: xy_to_uv FILE [X Y]... */
#include <stdio.h>
#include <stdlib.h>
#include "crgBaseLib.h"

int main(int argc, char **argv)
{
    const char *file = argc > 1 ? argv[1] : "examples/data/demo_road.crg";
    int id, cp, i;

    crgMsgSetLevel(dCrgMsgLevelWarn);
    if ((id = crgLoaderReadFile(file)) <= 0)
        return 1;
    crgDataSetModifiersApply(id);
    cp = crgContactPointCreate(id);
    if (argc < 4) {
        double x, y, u, v;
        for (i = 0; i <= 4; i++) {   /* no points given: round trip a few */
            crgEvaluv2xy(cp, 25.0 * i, -1.0, &x, &y);
            crgEvalxy2uv(cp, x, y, &u, &v);
            printf("x %10.4f y %10.4f -> u %9.4f v %7.4f\n", x, y, u, v);
        }
    }
    for (i = 2; i + 1 < argc; i += 2) {
        double x = atof(argv[i]), y = atof(argv[i + 1]), u, v;
        if (crgEvalxy2uv(cp, x, y, &u, &v))
            printf("x %10.4f y %10.4f -> u %9.4f v %7.4f\n", x, y, u, v);
    }
    crgMemRelease();
    return 0;
}
