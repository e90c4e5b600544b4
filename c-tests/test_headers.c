/* The three headers (crgBaseLib.h, crgBaseLibPrivate.h, crgOdr.h), each included twice,
 * compile without a warning as C89 (-ansi), C99, C11, C17 and C++98 to C++20 under
 * -Wall -Wextra -Werror -pedantic-errors, and a program calling one function of each
 * links and runs. test_headers.cpp is this file as C++. */
#include "crgBaseLib.h"
#include "crgBaseLib.h"
#include "crgBaseLibPrivate.h"
#include "crgBaseLibPrivate.h"
#include "crgOdr.h"
#include "crgOdr.h"

int main(void)
{
    double z = 0.0;
    int refused;
    crgMsgSetLevel(dCrgMsgLevelNone);
    refused = crgEvaluv2z(-1, 0.0, 0.0, &z) == 0 && crgOdrProbeRelease(-1) == 0;
    return refused ? 0 : 1;
}
