/*
 * Loading the binary of an FMU written by `opencrg fmu` and its FMI 2.0 functions, as an
 * importer does: dlopen/dlsym, LoadLibrary/GetProcAddress on Windows (the one place the
 * platforms differ). Also the resource location URI of an unpacked FMU and the token its
 * resources hold (the model description's guid, by construction).
 *
 * The value references of `opencrg fmu` (docs/fmu.md): wheel i's quantity q is
 * 100 * i + q, with x 0, y 1, z 2, friction 3, nx 4, ny 5, nz 6, onRoad 7.
 */
#ifndef OPENCRG_FMU_LOAD_H
#define OPENCRG_FMU_LOAD_H
#if !defined(_WIN32) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE /* realpath */
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _WIN32
#include <windows.h>
#else
#include <dlfcn.h>
#endif

enum { FMI2_MODEL_EXCHANGE = 0, FMI2_CO_SIMULATION = 1 };
enum { Q_X = 0, Q_Y = 1, Q_Z = 2, Q_FRICTION = 3, Q_NX = 4, Q_NY = 5, Q_NZ = 6, Q_ON_ROAD = 7 };
#define VR(wheel, q) (100u * (unsigned)(wheel) + (unsigned)(q))

typedef void (*Fmi2Logger)(void *env, const char *instance, int status, const char *category, const char *message,
                           ...);
typedef struct {
    Fmi2Logger logger;
    void *(*allocate)(size_t, size_t);
    void (*free)(void *);
    void (*step_finished)(void *, int);
    void *env;
} Fmi2Callbacks;

/* The FMI 2 functions a host needs. */
struct Fmi2 {
    void *(*instantiate)(const char *, int, const char *, const char *, const Fmi2Callbacks *, int, int);
    void (*free_instance)(void *);
    int (*setup_experiment)(void *, int, double, double, int, double);
    int (*enter_initialization)(void *);
    int (*exit_initialization)(void *);
    int (*set_real)(void *, const unsigned *, size_t, const double *);
    int (*get_real)(void *, const unsigned *, size_t, double *);
    int (*get_boolean)(void *, const unsigned *, size_t, int *);
    int (*do_step)(void *, double, double, int);
    int (*terminate)(void *);
};

#ifdef _WIN32
typedef HMODULE Library;
static Library library_open(const char *path) { return LoadLibraryA(path); }
static void *library_symbol(Library l, const char *name)
{
    /* (ISO C converts no function pointer to an object pointer: its bytes are copied.) */
    FARPROC found = GetProcAddress(l, name);
    void *symbol;
    memcpy(&symbol, &found, sizeof symbol);
    return symbol;
}
#else
typedef void *Library;
static Library library_open(const char *path) { return dlopen(path, RTLD_NOW | RTLD_LOCAL); }
static void *library_symbol(Library l, const char *name) { return dlsym(l, name); }
#endif

/* Loads `binary` and its functions into `f`; 0 (saying what is missing) when it cannot. */
static int fmi2_load(const char *binary, struct Fmi2 *f)
{
    Library l = library_open(binary);
    if (!l) {
        fprintf(stderr, "fmu: cannot load %s\n", binary);
        return 0;
    }
    struct {
        const char *name;
        void **slot;
    } wanted[] = {
        {"fmi2Instantiate", (void **)&f->instantiate},
        {"fmi2FreeInstance", (void **)&f->free_instance},
        {"fmi2SetupExperiment", (void **)&f->setup_experiment},
        {"fmi2EnterInitializationMode", (void **)&f->enter_initialization},
        {"fmi2ExitInitializationMode", (void **)&f->exit_initialization},
        {"fmi2SetReal", (void **)&f->set_real},
        {"fmi2GetReal", (void **)&f->get_real},
        {"fmi2GetBoolean", (void **)&f->get_boolean},
        {"fmi2DoStep", (void **)&f->do_step},
        {"fmi2Terminate", (void **)&f->terminate},
    };
    for (size_t i = 0; i < sizeof wanted / sizeof wanted[0]; i++) {
        *wanted[i].slot = library_symbol(l, wanted[i].name);
        if (!*wanted[i].slot) {
            fprintf(stderr, "fmu: %s lacks %s\n", binary, wanted[i].name);
            return 0;
        }
    }
    return 1;
}

/* The file: URI of the folder `unpacked`/resources, percent-encoded, from the folder's
 * full path (on Windows with its drive letter), as an importer makes it. */
static void resource_uri(const char *unpacked, char *out, size_t size)
{
    char full[4096];
#ifdef _WIN32
    if (!GetFullPathNameA(unpacked, sizeof full, full, NULL))
        snprintf(full, sizeof full, "%s", unpacked);
    for (char *c = full; *c; c++)
        if (*c == '\\')
            *c = '/';
#else
    if (!realpath(unpacked, full))
        snprintf(full, sizeof full, "%s", unpacked);
#endif
    size_t n = (size_t)snprintf(out, size, "file://%s", full[0] == '/' ? "" : "/");
    for (const unsigned char *c = (const unsigned char *)full; *c && n + 4 < size; c++) {
        if ((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') || strchr("/-_.~:", *c))
            out[n++] = (char)*c;
        else
            n += (size_t)snprintf(out + n, size - n, "%%%02X", *c);
    }
    snprintf(out + n, size - n, "/resources");
}

/* The token in `unpacked`/resources/opencrg-fmu.txt; 0 when there is none. */
static int read_token(const char *unpacked, char *out, size_t size)
{
    char path[4096], line[512];
    snprintf(path, sizeof path, "%s/resources/opencrg-fmu.txt", unpacked);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    int found = 0;
    while (!found && fgets(line, sizeof line, f)) {
        if (strncmp(line, "token = ", 8) == 0) {
            size_t len = strcspn(line + 8, "\r\n");
            if (len >= size)
                len = size - 1;
            memcpy(out, line + 8, len);
            out[len] = 0;
            found = 1;
        }
    }
    fclose(f);
    return found;
}
#endif
