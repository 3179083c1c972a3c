/*
 * memory.c — the command's memory policy (--max-memory): its default from
 * the machine, the process's data limit (RLIMIT_DATA) set before the model
 * is evaluated, the limit lifted around the foreign work it must not see
 * (loading OpenImageIO, its reads of a PNG), and the note that names the
 * limit on an "out of memory" error.
 *
 * The data limit rather than the address-space one (RLIMIT_AS): Linux's
 * data count (VmData) is the heap, the thread stacks and the libraries'
 * writable data — memory that can be written to — while the address space
 * also holds the code of every library (the image adapter maps about
 * 370 MB of them) and glibc's 64 MiB reservations per thread arena, none of
 * it the model's doing, which would leave a small limit unable to write a
 * PNG.  Thread stacks do count: the evaluator's thread reserves 1 GiB
 * (src/scad/scad.c); under a smaller limit it cannot be made, and the
 * evaluator runs on the main thread's stack, where deep recursion stops
 * sooner with its named error.  AddressSanitizer reserves terabytes of
 * shadow memory, so a sanitizer build leaves the limit off.
 */
#include "memory.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_ASAN 1
#endif
#endif

/* The cgroup v2 memory.max of this process, or 0 when there is none (no
 * cgroup v2, "max", unreadable).  A container's limit is the memory there
 * is, whatever the host has. */
static unsigned long long cgroup_memory_max(void)
{
    FILE *f = fopen("/sys/fs/cgroup/memory.max", "r");
    if (!f) return 0;
    unsigned long long v = 0;
    if (fscanf(f, "%llu", &v) != 1) v = 0;
    fclose(f);
    return v;
}

unsigned long long cli_default_max_memory(const cli_options *o)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    unsigned long long ram = pages > 0 && page > 0 ? (unsigned long long)pages * page : 0;
    unsigned long long cg = cgroup_memory_max();
    if (cg && (!ram || cg < ram)) ram = cg;
    if (!ram) ram = 4ULL << 30; /* unknown: a small machine's worth */
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    unsigned long long workers = cores > 0 ? (unsigned long long)cores : 1;
    if (o->threads > 0 && (unsigned long long)o->threads > workers) workers = o->threads;
    /* A thread's default stack is RLIMIT_STACK's size (glibc), 8 MiB
     * unless set otherwise. */
    struct rlimit rl;
    unsigned long long stack = 8ULL << 20;
    if (getrlimit(RLIMIT_STACK, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur > 0)
        stack = rl.rlim_cur;
    return ram / 4 * 3 + (1ULL << 30) + 2 * workers * stack;
}

void cli_format_size(unsigned long long bytes, char *buf, size_t len)
{
    static const char units[] = "TGMK";
    for (int i = 0; i < 4; i++) {
        unsigned long long u = 1ULL << (10 * (4 - i));
        if (bytes >= u && bytes % u == 0) {
            snprintf(buf, len, "%llu%c", bytes / u, units[i]);
            return;
        }
    }
    for (int i = 0; i < 4; i++) {
        unsigned long long u = 1ULL << (10 * (4 - i));
        if (bytes >= u) {
            snprintf(buf, len, "%.1f%c", (double)bytes / (double)u, units[i]);
            return;
        }
    }
    snprintf(buf, len, "%llu", bytes);
}

const char *cli_memory_note(const cli_options *o, const char *msg, char *buf, size_t len)
{
    if (!o->max_memory_enforced || !strstr(msg, "out of memory")) return "";
    char size[32];
    cli_format_size(o->max_memory, size, sizeof size);
    if (o->max_memory_enforced == 2)
        snprintf(buf, len, " (more than the data limit rayscad was started under, %s)", size);
    else
        snprintf(buf, len, " (more than --max-memory %s)", size);
    return buf;
}

void cli_print_error(const cli_options *o, const char *msg)
{
    char note[96];
    fprintf(stderr, "rayscad: error: %s%s\n", msg, cli_memory_note(o, msg, note, sizeof note));
}

int cli_data_limit_lift(struct rlimit *was)
{
    if (getrlimit(RLIMIT_DATA, was) != 0 || was->rlim_cur == was->rlim_max) return 0;
    struct rlimit open = *was;
    open.rlim_cur = was->rlim_max;
    return setrlimit(RLIMIT_DATA, &open) == 0;
}

void cli_data_limit_restore(int lifted, const struct rlimit *was)
{
    if (lifted) setrlimit(RLIMIT_DATA, was);
}

void cli_load_image_adapter(void)
{
    struct rlimit was;
    int lifted = cli_data_limit_lift(&was);
    (void)rayscad_image_load(NULL, 0); /* a failure shows again at the write */
    cli_data_limit_restore(lifted, &was);
}

/* Cap the process's data memory at o->max_memory (its default when the
 * flag was not given), or keep a lower limit the caller already set;
 * records which in o->max_memory_enforced.  The top of this file says why
 * RLIMIT_DATA. */
void cli_apply_memory_limit(cli_options *o)
{
    if (!o->max_memory_given) o->max_memory = cli_default_max_memory(o);
#ifdef UNDER_ASAN
    if (o->max_memory_given)
        fprintf(stderr, "rayscad: warning: --max-memory is not enforced in an AddressSanitizer "
                        "build (its shadow memory would count)\n");
    return;
#else
    struct rlimit rl;
    if (getrlimit(RLIMIT_DATA, &rl) != 0) return;
    if (rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur < o->max_memory) {
        o->max_memory = rl.rlim_cur;
        o->max_memory_enforced = 2;
        return;
    }
    rlim_t want = (rlim_t)o->max_memory;
    if (rl.rlim_max != RLIM_INFINITY && want > rl.rlim_max) want = rl.rlim_max;
    rl.rlim_cur = want;
    if (setrlimit(RLIMIT_DATA, &rl) != 0) return;
    o->max_memory = want;
    o->max_memory_enforced = 1;
#endif
}

/* ---- OpenImageIO under the limit --------------------------------------------------- */

/* The width and height of a PNG file from its IHDR chunk: 0, or -1 when
 * path is not a readable PNG. */
static int png_size(const char *path, unsigned long *w, unsigned long *h)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char b[24];
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    size_t n = fread(b, 1, sizeof b, f);
    fclose(f);
    if (n != sizeof b || memcmp(b, sig, 8) || memcmp(b + 12, "IHDR", 4)) return -1;
    *w =
        (unsigned long)b[16] << 24 | (unsigned long)b[17] << 16 | (unsigned long)b[18] << 8 | b[19];
    *h =
        (unsigned long)b[20] << 24 | (unsigned long)b[21] << 16 | (unsigned long)b[22] << 8 | b[23];
    return 0;
}

/* The process's data memory as RLIMIT_DATA counts it (VmData), in bytes;
 * 0 when unknown. */
static unsigned long long data_in_use(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    if (!f) return 0;
    char line[256];
    unsigned long long kb = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "VmData: %llu kB", &kb) == 1) break;
    fclose(f);
    return kb * 1024;
}

/* surface() runs while --max-memory applies, and OpenImageIO does not
 * survive that: its libraries' initialisers, and the first read (its
 * plugin catalogue and thread pool: about 100 MB of VmData), throw where
 * they cannot unwind or dereference null below about 150 MiB.  So the
 * adapter is loaded with the limit lifted (cli_load_image_adapter), and a
 * PNG is read with it lifted too, but only when its pixels fit under the
 * limit beside what the process holds: twice the image as 4 floats a
 * pixel (ours and OpenImageIO's scanlines), else out of memory.  Other
 * files are read under the limit. */
int cli_read_image(void *ud, const char *path, int *width, int *height, int *channels,
                   float **pixels, char *err, size_t errlen)
{
    (void)ud;
    cli_load_image_adapter();
    unsigned long w, h;
    struct rlimit was;
    if (png_size(path, &w, &h) != 0 || getrlimit(RLIMIT_DATA, &was) != 0 ||
        was.rlim_cur == was.rlim_max)
        return rayscad_image_read(path, width, height, channels, pixels, err, errlen) == 0 ? 0 : -1;
    unsigned long long need = 2ULL * w * h * 4 * sizeof(float), used = data_in_use();
    if (!used || need > (unsigned long long)was.rlim_cur - used || used > was.rlim_cur) {
        snprintf(err, errlen, "%s: out of memory for a %lux%lu image", path, w, h);
        *pixels = NULL;
        return -1;
    }
    int lifted = cli_data_limit_lift(&was);
    int rc = rayscad_image_read(path, width, height, channels, pixels, err, errlen) == 0 ? 0 : -1;
    cli_data_limit_restore(lifted, &was);
    return rc;
}
