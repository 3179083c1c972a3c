/*
 * services.c — scad_services for the command: meshes and images through
 * src/io.
 *
 * OpenSCAD writes OFF files with the counts on the header line ("OFF 8 6
 * 0"), which OpenMesh 9.0's reader takes for something else and runs out of
 * memory on (REFERENCE.md).  read_mesh gives such a file to io_mesh_read as
 * a copy in a private temporary folder with the header split into "OFF" and
 * a line of counts — the form OpenMesh reads.
 */
#include "services.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../io/io.h"
#include "geometry_services.h"

/* The whole file at path, malloc'ed, its length in *n; NULL on failure. */
static char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 16, len = 0;
    char *b = malloc(cap);
    while (b) {
        len += fread(b + len, 1, cap - len, f);
        if (len < cap) break;
        char *nb = realloc(b, cap * 2);
        if (!nb) {
            free(b);
            b = NULL;
            break;
        }
        b = nb;
        cap *= 2;
    }
    if (b && ferror(f)) {
        free(b);
        b = NULL;
    }
    fclose(f);
    *n = len;
    return b;
}

/* Where the counts start when the first line of an OFF file holds its
 * keyword (OFF, COFF, NOFF, STOFF …) followed by numbers; 0 when the
 * header is already on a line of its own. */
static size_t off_counts_on_header(const char *b, size_t n)
{
    size_t i = 0;
    while (i < n && isalpha((unsigned char)b[i]))
        i++;
    if (i < 3 || memcmp(b + i - 3, "OFF", 3) != 0) return 0;
    size_t j = i;
    while (j < n && (b[j] == ' ' || b[j] == '\t'))
        j++;
    return j > i && j < n && isdigit((unsigned char)b[j]) ? i : 0;
}

static int has_off_extension(const char *path)
{
    size_t n = strlen(path);
    if (n < 4 || path[n - 4] != '.') return 0;
    return tolower((unsigned char)path[n - 3]) == 'o' &&
           tolower((unsigned char)path[n - 2]) == 'f' && tolower((unsigned char)path[n - 1]) == 'f';
}

static int read_mesh(void *ud, const char *path, float **v, int *nv, int32_t **t, int *nt,
                     char *err, size_t errlen)
{
    (void)ud;
    if (!has_off_extension(path)) return io_mesh_read(path, v, nv, t, nt, err, errlen);
    size_t n = 0;
    char *b = slurp(path, &n);
    size_t split = b ? off_counts_on_header(b, n) : 0;
    if (!split) {
        free(b);
        return io_mesh_read(path, v, nv, t, nt, err, errlen);
    }
    /* the copy: "OFF\n" and the rest of the file from the counts on */
    const char *tmp = getenv("TMPDIR");
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/rayscad-off-XXXXXX", tmp && *tmp ? tmp : "/tmp");
    int rc = -1;
    if (!mkdtemp(dir)) {
        snprintf(err, errlen, "%s: cannot make a temporary folder to read it", path);
    } else {
        char copy[4200];
        snprintf(copy, sizeof copy, "%s/mesh.off", dir);
        FILE *f = fopen(copy, "wb");
        size_t rest = split;
        while (rest < n && (b[rest] == ' ' || b[rest] == '\t'))
            rest++;
        int ok = f && fwrite(b, 1, split, f) == split && fputc('\n', f) != EOF &&
                 fwrite(b + rest, 1, n - rest, f) == n - rest;
        if (f && fclose(f) != 0) ok = 0;
        if (ok) {
            rc = io_mesh_read(copy, v, nv, t, nt, err, errlen);
            /* messages name the user's file, not the copy */
            char *at = rc ? strstr(err, copy) : NULL;
            if (at) {
                char rest_msg[1024];
                snprintf(rest_msg, sizeof rest_msg, "%s", at + strlen(copy));
                snprintf(err, errlen, "%s%s", path, rest_msg);
            }
        } else {
            snprintf(err, errlen, "%s: cannot copy it to a temporary file to read it", path);
        }
        remove(copy);
        rmdir(dir);
    }
    free(b);
    return rc;
}

static int read_image(void *ud, const char *path, int *width, int *height, int *channels,
                      float **pixels, char *err, size_t errlen)
{
    (void)ud;
    return io_image_read(path, width, height, channels, pixels, err, errlen);
}

const scad_services *cli_services(void)
{
    static const scad_services s = {
        .read_mesh = read_mesh,
        .read_image = read_image,
        .paths_clip = cli_paths_clip,
        .paths_offset = cli_paths_offset,
        .paths_minkowski = cli_paths_minkowski,
        .mesh_tree = cli_mesh_tree,
        .text = cli_text,
    };
    return &s;
}
