/*
 * files.c — the language's files: the main file, include <…> and use <…>
 * (found in OpenSCAD's order), and the files builtins read (DXF drawings,
 * heightmaps), all through the caller's services (scad_services.read_file
 * and stat_file), never the file system directly, so a test or a fuzzer can
 * serve them from memory.  Without those services no file can be read: the
 * call fails with its message.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ast.h"

/* A source this long is not a model. */
#define MAX_SOURCE_BYTES ((size_t)1 << 28)

char *scad_file_read(const scad_options *opt, const char *path, size_t max, size_t *len, char *err,
                     size_t errlen)
{
    const scad_services *s = opt ? opt->services : NULL;
    if (!s || !s->read_file) {
        snprintf(err, errlen, "no file service");
        return NULL;
    }
    char *data = NULL;
    *len = 0;
    if (s->read_file(s->ud, path, max, &data, len, err, errlen) != 0) {
        free(data);
        return NULL;
    }
    return data;
}

char *scad_read_file(scad_arena *a, const scad_options *opt, const char *path, char *err,
                     size_t errlen)
{
    size_t len;
    char *data = scad_file_read(opt, path, MAX_SOURCE_BYTES, &len, err, errlen);
    if (!data) return NULL;
    char *out = scad_arena_strndup(a, data, len);
    free(data);
    if (!out) snprintf(err, errlen, "out of memory");
    return out;
}

int scad_file_stat(const scad_options *opt, const char *path, long long *mtime)
{
    const scad_services *s = opt ? opt->services : NULL;
    if (mtime) *mtime = 0;
    return s && s->stat_file && s->stat_file(s->ud, path, mtime);
}

void scad_file_want(const scad_options *opt, const char *path)
{
    const scad_services *s = opt ? opt->services : NULL;
    if (s && s->want_file) s->want_file(s->ud, path);
}

static char *join_path(scad_arena *a, const char *dir, size_t dl, const char *name)
{
    size_t nl = strlen(name);
    int sep = dl > 0 && dir[dl - 1] != '/';
    char *p = scad_arena_alloc(a, dl + (size_t)sep + nl + 1);
    if (!p) return NULL;
    memcpy(p, dir, dl);
    if (sep) p[dl] = '/';
    memcpy(p + dl + (size_t)sep, name, nl + 1);
    return p;
}

char *scad_find_library(scad_arena *a, const scad_options *opt, const char *from, const char *name)
{
    if (name[0] == '/')
        return scad_file_stat(opt, name, NULL) ? scad_arena_strndup(a, name, strlen(name)) : NULL;
    const char *slash = strrchr(from, '/');
    char *p = join_path(a, from, slash ? (size_t)(slash - from + 1) : 0, name);
    if (p && scad_file_stat(opt, p, NULL)) return p;
    const char *dirs = opt && opt->library_path ? opt->library_path : getenv("OPENSCADPATH");
    while (dirs && *dirs) {
        const char *end = strchr(dirs, ':');
        size_t n = end ? (size_t)(end - dirs) : strlen(dirs);
        if (n > 0) {
            p = join_path(a, dirs, n, name);
            if (p && scad_file_stat(opt, p, NULL)) return p;
        }
        dirs += n + (end ? 1 : 0);
    }
    /* then the user's library folder, then the installation's */
    const char *home = getenv("HOME");
    if (home && *home) {
        char *user = join_path(a, home, strlen(home), ".local/share/OpenSCAD/libraries");
        p = user ? join_path(a, user, strlen(user), name) : NULL;
        if (p && scad_file_stat(opt, p, NULL)) return p;
    }
    p = join_path(a, "/usr/share/openscad/libraries", 29, name);
    if (p && scad_file_stat(opt, p, NULL)) return p;
    return NULL;
}
