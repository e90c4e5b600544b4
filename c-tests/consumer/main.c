/* Loads a road and evaluates one point: proof that the installed package works. */
#include <stdio.h>
#include "crgBaseLib.h"

int main(int argc, char **argv)
{
    double z = 0.0;
    int id, cp;
    crgMsgSetLevel(dCrgMsgLevelNone);
    id = crgLoaderReadFile(argc > 1 ? argv[1] : "road.crg");
    cp = crgContactPointCreate(id);
    if (id <= 0 || cp < 0 || !crgEvaluv2z(cp, 10.0, 0.5, &z)) {
        printf("consumer: failed\n");
        return 1;
    }
    printf("consumer: z(10, 0.5) = %.6f\n", z);
    crgMemRelease();
    return 0;
}
