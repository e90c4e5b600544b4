/* The one thing crgBaseLib.h takes from <stdlib.h> (size_t), for the import library test,
 * which is built without Microsoft's C runtime and SDK headers. */
#include <stddef.h>
