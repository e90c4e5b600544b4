/*
 * crgMsgPrint is variadic, which stable Rust cannot define: the exported symbol is a
 * Rust entry (src/msg_entry.rs) that jumps to opencrg_msg_print here. This shim formats the
 * message and hands the text to the Rust side (src/msg.rs), which either passes it to
 * the application's callback or has it printed here, on stderr, with the level's name
 * in front, as the reference library prints its messages.
 *
 * The Rust side installs its two hooks when the library is loaded. The hooks are
 * hidden symbols, so the library exports exactly the API. Without them (a program
 * linking the static library and calling nothing but crgMsgPrint) messages up to the
 * default level NOTICE are printed.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

/* A DLL exports only what its .def file lists; ELF libraries hide the hooks this way. */
#if defined(_WIN32)
#define HIDDEN
#else
#define HIDDEN __attribute__((visibility("hidden")))
#endif

/* Is a message of this level wanted at all? */
HIDDEN int (*opencrg_msg_wanted_hook)(int level) = NULL;
/* Routes the text; returns 1 when the shim should print it. */
HIDDEN int (*opencrg_msg_route_hook)(int level, char *text) = NULL;

static const char *level_name(int level)
{
    switch (level) {
    case 0: return "NONE";
    case 1: return "FATAL";
    case 2: return "WARNING";
    case 3: return "NOTICE";
    case 4: return "INFO";
    case 5: return "DEBUG";
    default: return "unknown level";
    }
}

HIDDEN void opencrg_msg_print(int level, const char *format, ...)
{
    char small[1024];
    char *text = small;
    va_list ap;
    int n;

    if (!format)
        return;
    if (opencrg_msg_wanted_hook ? !opencrg_msg_wanted_hook(level) : level > 3)
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
    if (!opencrg_msg_route_hook || opencrg_msg_route_hook(level, text)) {
        fprintf(stderr, "%7s: %s", level_name(level), text);
        fflush(stderr);
    }
    if (text != small)
        free(text);
}
