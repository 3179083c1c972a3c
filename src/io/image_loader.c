/*
 * image_loader.c — io.h's image functions, loading the OpenImageIO adapter
 * (image.cpp) only when an image is read or written.
 *
 * OpenImageIO 2.4 as Debian builds it needs about 260 shared libraries
 * (OpenCV, FFmpeg, DCMTK, OpenVDB, …), and relocating them costs the dynamic
 * loader about 0.3 s of CPU — more than most renders take.  So rayscad does
 * not link it: the adapter is a shared object of its own, embedded in the
 * binary at build time (the .incbin below, RAYSCAD_IMAGE_SO naming the file),
 * copied into a memfd and dlopened from there on first use, so the binary
 * stays one self-contained file.  Meshes, --measure, .echo, .csg and .pov
 * never load it.
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
#define _GNU_SOURCE /* memfd_create */
#include "io.h"

#include <dlfcn.h>
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/mman.h>
#include <unistd.h>

#ifdef RAYSCAD_IMAGE_SO
__asm__(".section .rodata\n"
        ".balign 64\n"
        "rayscad_image_so:\n"
        ".incbin \"" RAYSCAD_IMAGE_SO "\"\n"
        "rayscad_image_so_end:\n"
        ".previous\n");
extern const unsigned char rayscad_image_so[], rayscad_image_so_end[];
#endif
#ifdef RAYSCAD_IMAGE_DEPS
__asm__(".section .rodata\n"
        "rayscad_image_deps:\n"
        ".incbin \"" RAYSCAD_IMAGE_DEPS "\"\n"
        ".byte 0\n"
        ".previous\n");
extern const char rayscad_image_deps[];
#endif

typedef int (*write_fn)(const char *, int, int, int, const float *, char *, size_t);
typedef int (*read_fn)(const char *, int *, int *, int *, float **, char *, size_t);
typedef int (*supported_fn)(const char *);

static pthread_once_t once = PTHREAD_ONCE_INIT;
static struct {
    write_fn write;
    read_fn read;
    supported_fn supported;
} fn;
static char load_err[256]; /* empty when the adapter loaded */

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
            if (!dlopen(path, RTLD_LAZY | RTLD_LOCAL)) (void)dlerror();
        }
        p += n;
        if (*p) p++;
    }
#endif
}

/* dlopen the embedded adapter; fills fn or load_err.  Runs once. */
static void load(void)
{
#ifdef RAYSCAD_IMAGE_SO
    preload();
    const unsigned char *p = rayscad_image_so;
    size_t left = (size_t)(rayscad_image_so_end - rayscad_image_so);
    int fd = memfd_create("rayscad-image.so", MFD_CLOEXEC);
    if (fd < 0) {
        snprintf(load_err, sizeof load_err, "cannot load the image adapter: memfd_create: %s",
                 strerror(errno));
        return;
    }
    while (left > 0) {
        ssize_t w = write(fd, p, left);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) {
            snprintf(load_err, sizeof load_err, "cannot load the image adapter: write: %s",
                     strerror(errno));
            close(fd);
            return;
        }
        p += w;
        left -= (size_t)w;
    }
    char path[64];
    snprintf(path, sizeof path, "/proc/self/fd/%d", fd);
    void *h = dlopen(path, RTLD_LAZY | RTLD_LOCAL);
    close(fd); /* the mapping keeps what dlopen needs */
    if (!h) {
        const char *e = dlerror();
        snprintf(load_err, sizeof load_err, "cannot load the image adapter: %s",
                 e ? e : "dlopen failed");
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
#else
    snprintf(load_err, sizeof load_err, "this build has no image adapter (OpenImageIO)");
#endif
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
