/* Run with OPENCRG_COMPAT set to a value that names no profile: loading is refused
 * and the message names the variable and the accepted values.
 * usage: test_compat ROAD.crg */
#include <string.h>
#include "crgBaseLib.h"
#include "check.h"

static char g_text[4096];

static int on_message(int level, char *message)
{
    if (level == dCrgMsgLevelFatal)
        strncat(g_text, message, sizeof g_text - strlen(g_text) - 1);
    return 0;
}

int main(int argc, char **argv)
{
    const char *road = argc > 1 ? argv[1] : "examples/data/demo_road.crg";
    crgMsgSetCallback(on_message);
    CHECK(crgLoaderReadFile(road) == 0);
    CHECK(strstr(g_text, "OPENCRG_COMPAT") != NULL);
    CHECK(strstr(g_text, "'2.0'") != NULL);
    CHECK(strstr(g_text, "2.0.1") != NULL && strstr(g_text, "1.2.0") != NULL);
    /* Read once: the second load is refused the same way. */
    CHECK(crgLoaderReadFile(road) == 0);
    return check_summary("test_compat");
}
