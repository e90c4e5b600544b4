/* test_headers.c as C++. */
#include "test_headers.c"
