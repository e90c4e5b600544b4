/* Drives along a road: elevation, heading and curvature every metre of the
 * reference line, 0.8 m to its left, looked up by x/y as a vehicle model would.
 * usage: eval_path FILE */
#include <stdio.h>
#include "crgBaseLib.h"

int main(int argc, char **argv)
{
    const char *file = argc > 1 ? argv[1] : "examples/data/demo_road.crg";
    double uMin, uMax, u;
    int id, cp;

    crgMsgSetLevel(dCrgMsgLevelWarn);
    if ((id = crgLoaderReadFile(file)) <= 0 || !crgCheck(id))
        return 1;
    crgDataSetModifiersApply(id);
    if ((cp = crgContactPointCreate(id)) < 0)
        return 1;
    crgDataSetGetURange(id, &uMin, &uMax);
    printf("%8s %10s %10s %9s %8s %9s\n", "u", "x", "y", "z", "phi", "curv");
    for (u = uMin; u <= uMax; u += 10.0) {
        double x, y, z, phi, curv;
        crgEvaluv2xy(cp, u, 0.8, &x, &y);      /* where the wheel is */
        if (!crgEvalxy2z(cp, x, y, &z) || !crgEvalxy2pk(cp, x, y, &phi, &curv))
            return 1;
        printf("%8.2f %10.3f %10.3f %9.5f %8.4f %9.6f\n", u, x, y, z, phi, curv);
    }
    crgContactPointDelete(cp);
    crgMemRelease();
    return 0;
}
