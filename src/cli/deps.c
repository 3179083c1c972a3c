/*
 * deps.c — see deps.h.
 */
#include "deps.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* path as the rule names it: the main file as given, others absolute. */
static char *rule_name(const cli_deps *d, const char *path)
{
    if (path[0] == '/' || (d->input && strcmp(path, d->input) == 0)) return strdup(path);
    char cwd[4096];
    if (!getcwd(cwd, sizeof cwd)) return strdup(path);
    size_t n = strlen(cwd) + strlen(path) + 2;
    char *s = malloc(n);
    if (s) snprintf(s, n, "%s/%s", cwd, path);
    return s;
}

static void file_read(void *ud, const char *path)
{
    cli_deps *d = ud;
    char *name = rule_name(d, path);
    if (!name) {
        d->oom = 1;
        return;
    }
    for (int i = 0; i < d->n; i++)
        if (strcmp(d->paths[i], name) == 0) {
            free(name);
            return;
        }
    if (d->n == d->cap) {
        int cap = d->cap ? 2 * d->cap : 16;
        char **p = realloc(d->paths, (size_t)cap * sizeof *p);
        if (!p) {
            free(name);
            d->oom = 1;
            return;
        }
        d->paths = p;
        d->cap = cap;
    }
    d->paths[d->n++] = name;
}

/* openscad's handle_dep: make_cmd 'path' through the shell, the path
 * absolute (as openscad gives it) and its quotes escaped; its outcome shows
 * when the file is read. */
static void make_file(void *ud, const char *given)
{
    const cli_deps *d = ud;
    char *path = rule_name(d, given);
    if (!path) return;
    size_t n = strlen(d->make_cmd) + 4 * strlen(path) + 4;
    char *cmd = malloc(n), *w = cmd;
    if (!cmd) {
        free(path);
        return;
    }
    w += sprintf(w, "%s '", d->make_cmd);
    for (const char *p = path; *p; p++) {
        if (*p == '\'') {
            memcpy(w, "'\\''", 4);
            w += 4;
        } else {
            *w++ = *p;
        }
    }
    strcpy(w, "'");
    fflush(stdout);
    int rc = system(cmd);
    (void)rc; /* a failed make leaves the file missing: the read says so */
    free(cmd);
    free(path);
}

void cli_deps_hook(cli_deps *d, rayscad_services *services)
{
    services->ud = d;
    services->file_read = file_read;
    if (d->make_cmd) services->make_file = make_file;
}

static void put_escaped(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == ' ' || *s == '#') fputc('\\', f);
        if (*s == '$') fputc('$', f);
        fputc(*s, f);
    }
}

int cli_deps_write(const cli_deps *d, const char *path, const char *const *targets, int ntargets,
                   char *err, size_t errlen)
{
    if (d->oom) {
        snprintf(err, errlen, "%s: out of memory listing the files read", path);
        return -1;
    }
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    for (int i = 0; i < ntargets; i++) {
        if (i) fputc(' ', f);
        put_escaped(f, targets[i]);
    }
    fputs(":", f);
    for (int i = 0; i < d->n; i++) {
        fputs(" \\\n\t", f);
        put_escaped(f, d->paths[i]);
    }
    fputs("\n", f);
    fclose(f);
    rayscad_status rc = text ? rayscad_file_write(path, text, len, err, errlen) : RAYSCAD_ERROR;
    if (!text) snprintf(err, errlen, "%s: out of memory", path);
    free(text);
    return rc == RAYSCAD_OK ? 0 : -1;
}

void cli_deps_free(cli_deps *d)
{
    for (int i = 0; i < d->n; i++)
        free(d->paths[i]);
    free(d->paths);
    d->paths = NULL;
    d->n = d->cap = 0;
}
