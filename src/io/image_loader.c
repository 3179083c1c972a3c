/*
 * image_loader.c — io.h's image functions, loading the OpenImageIO adapter
 * (image.cpp) only when an image is read or written.
 *
 * OpenImageIO 2.4 as Debian builds it needs about 260 shared libraries
 * (OpenCV, FFmpeg, DCMTK, OpenVDB, …), and relocating them costs the dynamic
 * loader about 0.3 s of CPU — more than most renders take.  So rayscad does
 * not link it: the adapter is a shared object of its own, rayscad-image.so,
 * dlopened on first use.  It is found from where the code that loads it
 * lives (dladdr: librayscad.so, or the program it is linked into): beside
 * it (the build tree), in rayscad/ below it (an installed lib/) or in
 * ../lib/rayscad/ (an installed bin/), so an installation works from any
 * prefix and no build path is built in.  Meshes, --measure, .echo, .csg and
 * .pov never load it.
 *
 * Most of that time is symbol lookup: a dlopen relocates every library it
 * brings in against one search list, the adapter's breadth-first dependency
 * order, so a library deep in that order walks past a couple of hundred
 * others' hash tables for each of its own symbols.  Opening the libraries
 * one by one first, leaves first (the list the build took from ldd, embedded
 * beside the adapter as RAYSCAD_IMAGE_DEPS; sanitizer builds go without,
 * the Makefile says why), relocates each against its own short list
 * instead: 0.37 s → 0.20 s for the whole load.  Those opens only
 * warm the loader; any of them may fail (a library moved, or one that
 * depends on a symbol it does not link), and the adapter's own dlopen then
 * finds or loads the rest in the usual way and reports any real failure.
 *
 * Loading in the background while the model renders was measured and does
 * not pay: the render threads then run 5–8× slower (the loader's hundreds of
 * mmap and mprotect calls stall their page faults), and the whole process
 * takes as long as loading at the end.
 *
 * Invariant: the load runs once (pthread_once); afterwards `fn` and
 * `load_err` never change, so every thread reads them freely.
 */
#define _GNU_SOURCE /* dladdr */
#include "io.h"
#include "versions.h"

#include <dlfcn.h>
#include <errno.h>
#include <pthread.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <stdint.h>
#include <unistd.h>

#ifdef RAYSCAD_IMAGE_DEPS
__asm__(".section .rodata\n"
        "rayscad_image_deps:\n"
        ".incbin \"" RAYSCAD_IMAGE_DEPS "\"\n"
        ".byte 0\n"
        ".previous\n");
extern const char rayscad_image_deps[];
#endif

/* The adapter's file name. */
#define ADAPTER "rayscad-image.so"

/* RTLD_DEEPBIND: the adapter's libraries look their symbols up in their own
 * dependencies first, not through every library the program was linked
 * with (the viewer's SDL2, X11, PulseAudio, Wayland …): a PNG of
 * bench/scenes/few.scad took 0.31 s a run without it, 0.21 s with it.  The
 * sanitizers' runtimes refuse it. */
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAYSCAD_NO_DEEPBIND 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(RAYSCAD_NO_DEEPBIND)
#define LOAD_FLAGS (RTLD_LAZY | RTLD_LOCAL)
#else
#define LOAD_FLAGS (RTLD_LAZY | RTLD_LOCAL | RTLD_DEEPBIND)
#endif

typedef int (*write_fn)(const char *, int, int, int, const float *, char *, size_t);
typedef int (*read_fn)(const char *, int *, int *, int *, float **, char *, size_t);
typedef int (*supported_fn)(const char *);
typedef const char *(*version_fn)(void);

static pthread_once_t once = PTHREAD_ONCE_INIT;
static struct {
    write_fn write;
    read_fn read;
    supported_fn supported;
    version_fn version; /* may be NULL */
} fn;
static char load_err[2048]; /* empty when the adapter loaded */

/* Open the adapter's libraries leaves first, one path per line of the
 * embedded list, ignoring failures (see the top of the file).  The handles
 * are kept: the adapter holds the libraries for the life of the process. */
static void preload(void)
{
#ifdef RAYSCAD_IMAGE_DEPS
    for (const char *p = rayscad_image_deps; *p;) {
        size_t n = strcspn(p, "\n");
        char path[4096];
        if (n > 0 && n < sizeof path) {
            memcpy(path, p, n);
            path[n] = 0;
            if (!dlopen(path, LOAD_FLAGS)) (void)dlerror();
        }
        p += n;
        if (*p) p++;
    }
#endif
}

/* The folder of the object this code is linked into (librayscad.so, or
 * the program), with its '/', into dir; 0, or -1 when unknown.  The
 * program's own name may be relative to a folder it has since left, so its
 * path comes from /proc/self/exe. */
static int own_folder(char *dir, size_t n)
{
    Dl_info info;
    char path[4096];
    if (dladdr((void *)(uintptr_t)own_folder, &info) && info.dli_fname &&
        info.dli_fname[0] == '/') {
        snprintf(path, sizeof path, "%s", info.dli_fname);
    } else {
        ssize_t k = readlink("/proc/self/exe", path, sizeof path - 1);
        if (k <= 0) return -1;
        path[k] = 0;
    }
    char *slash = strrchr(path, '/');
    if (!slash || (size_t)(slash - path + 2) > n) return -1;
    slash[1] = 0;
    snprintf(dir, n, "%s", path);
    return 0;
}

/* dlopen the adapter; fills fn or load_err.  Runs once. */
static void load(void)
{
    static const char *const below[] = {"", "rayscad/", "../lib/rayscad/"};
    char dir[4096], path[4200];
    void *h = NULL;
    if (own_folder(dir, sizeof dir) != 0) {
        snprintf(load_err, sizeof load_err,
                 "cannot load the image adapter: cannot tell where rayscad is installed");
        return;
    }
    preload();
    for (size_t i = 0; i < sizeof below / sizeof below[0] && !h; i++) {
        snprintf(path, sizeof path, "%s%s" ADAPTER, dir, below[i]);
        if (access(path, R_OK) != 0) continue;
        h = dlopen(path, LOAD_FLAGS);
        if (!h) {
            const char *e = dlerror();
            snprintf(load_err, sizeof load_err, "cannot load the image adapter %.1000s: %.1000s",
                     path, e ? e : "dlopen failed");
            return;
        }
    }
    if (!h) {
        snprintf(load_err, sizeof load_err,
                 "cannot load the image adapter: no " ADAPTER " in %.600s, %.600srayscad/ or "
                 "%.600s../lib/rayscad/",
                 dir, dir, dir);
        return;
    }
    /* POSIX allows converting dlsym's object pointer to a function pointer;
     * the memcpy keeps ISO C's -Wpedantic quiet about it. */
    void *w = dlsym(h, "io_image_write"), *r = dlsym(h, "io_image_read"),
         *s = dlsym(h, "io_image_format_supported");
    if (!w || !r || !s) {
        snprintf(load_err, sizeof load_err, "cannot load the image adapter: a symbol is missing");
        return;
    }
    memcpy(&fn.write, &w, sizeof w);
    memcpy(&fn.read, &r, sizeof r);
    memcpy(&fn.supported, &s, sizeof s);
    void *v = dlsym(h, "io_image_version");
    if (v) memcpy(&fn.version, &v, sizeof v);
}

/* Load the adapter unless done already.  Returns 0, or -1 with the reason
 * in err. */
static int ready(char *err, size_t errlen)
{
    pthread_once(&once, load);
    if (load_err[0]) {
        if (err && errlen) snprintf(err, errlen, "%s", load_err);
        return -1;
    }
    return 0;
}

int io_image_load(char *err, size_t errlen)
{
    return ready(err, errlen);
}

const char *io_image_library_version(void)
{
    if (ready(NULL, 0) != 0) return load_err;
    return fn.version ? fn.version() : "unknown";
}

int io_image_write(const char *path, int width, int height, int channels, const float *pixels,
                   char *err, size_t errlen)
{
    if (ready(err, errlen) != 0) return -1;
    return fn.write(path, width, height, channels, pixels, err, errlen);
}

int io_image_read(const char *path, int *width, int *height, int *channels, float **pixels,
                  char *err, size_t errlen)
{
    if (ready(err, errlen) != 0) {
        *pixels = NULL;
        return -1;
    }
    return fn.read(path, width, height, channels, pixels, err, errlen);
}

int io_image_format_supported(const char *path)
{
    /* OpenImageIO 2.x cannot be built without PNG, JPEG, TIFF and OpenEXR
     * (tests/test_io.c writes each), so these are answered without loading
     * it: a model that fails to evaluate then exits without the load.  Any
     * other extension asks OpenImageIO itself. */
    static const char *const common[] = {"png", "jpg", "jpeg", "tif", "tiff", "exr"};
    const char *slash = path ? strrchr(path, '/') : NULL;
    const char *dot = path ? strrchr(path, '.') : NULL;
    if (!dot || (slash && dot < slash) || !dot[1]) return 0;
    for (size_t i = 0; i < sizeof common / sizeof *common; i++) {
        if (strcasecmp(dot + 1, common[i]) == 0) return 1;
    }
    if (ready(NULL, 0) != 0) return 0;
    return fn.supported(path);
}
