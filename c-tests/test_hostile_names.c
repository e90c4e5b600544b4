/* The header among names a program may use for itself: macros named like message
 * levels (a -DDEBUG build, glog, COVISE's enum), which the header must neither define
 * nor use. Built as C99, C11, C++11 and C++17 with -Wall -Wextra -Werror -pedantic. */
#define DEBUG 1
#define INFO "information"
#define NONE
#include "crgBaseLib.h"

enum SurfaceWrapMode { FATAL, WARN, NOTICE, WRAP };

int main(void)
{
    enum SurfaceWrapMode mode = WRAP;
    double z = 0.0;
    int ok;
    crgMsgSetLevel(dCrgMsgLevelNone);
    ok = crgEvaluv2z(-1, 0.0, 0.0, &z) == 0; /* no contact point: refused */
    return (ok && DEBUG == 1 && mode == WRAP) ? 0 : 1;
}
