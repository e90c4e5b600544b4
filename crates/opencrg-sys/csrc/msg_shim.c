/*
 * crgMsgPrint is variadic, which stable Rust cannot define. This shim formats the
 * message and hands the text to the Rust side, which either passes it to the
 * application's callback or asks for it to be printed here, on C's stdout, so that
 * it interleaves correctly with the application's own printf output.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

/* Rust side: is a message of this level wanted at all? */
int opencrg_msg_wanted(int level);
/* Rust side: route the text; returns 1 when the shim should print it. */
int opencrg_msg_route(int level, char *text);
/* Rust side: the level's display name. */
const char *opencrg_msg_level_name(int level);

void crgMsgPrint(int level, const char *format, ...)
{
    char small[1024];
    char *text = small;
    va_list ap;
    int n;

    if (!format || !opencrg_msg_wanted(level))
        return;
    va_start(ap, format);
    n = vsnprintf(small, sizeof small, format, ap);
    va_end(ap);
    if (n < 0)
        return;
    if ((size_t)n >= sizeof small) {
        char *big = malloc((size_t)n + 1);
        if (big) {
            va_start(ap, format);
            vsnprintf(big, (size_t)n + 1, format, ap);
            va_end(ap);
            text = big;
        }
    }
    if (opencrg_msg_route(level, text)) {
        printf("%7s: %s", opencrg_msg_level_name(level), text);
        fflush(stdout);
    }
    if (text != small)
        free(text);
}
