/*
 * print.c — the pieces of OpenSCAD 2021.01's .csg headers that several
 * builtin modules print: numbers as an ostream writes them (printf "%g":
 * "1e+06", "-0"), booleans, the $fn/$fa/$fs triple, and the file, layer and origin
 * of import() and the extrusions, with file names relative to the main
 * file's folder.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "builtins.h"

void scad_print_g(scad_buf *b, double x)
{
    scad_buf_printf(b, "%g", x);
}

void scad_print_bool(scad_buf *b, int x)
{
    scad_buf_puts(b, x ? "true" : "false");
}

void scad_print_facets(scad_buf *b, scad_facet_params f, const char *before, const char *after)
{
    scad_buf_puts(b, before);
    scad_buf_puts(b, "$fn = ");
    scad_print_g(b, f.fn);
    scad_buf_puts(b, ", $fa = ");
    scad_print_g(b, f.fa);
    scad_buf_puts(b, ", $fs = ");
    scad_print_g(b, f.fs);
    scad_buf_puts(b, after);
}

/* Lexically normalised absolute form of path (no symlinks resolved). */
static char *absolute(const char *path)
{
    char cwd[PATH_MAX];
    size_t n = strlen(path);
    char *joined;
    if (path[0] == '/') {
        joined = malloc(n + 1);
        if (!joined) return NULL;
        memcpy(joined, path, n + 1);
    } else {
        if (!getcwd(cwd, sizeof cwd)) return NULL;
        size_t c = strlen(cwd);
        joined = malloc(c + n + 2);
        if (!joined) return NULL;
        memcpy(joined, cwd, c);
        joined[c] = '/';
        memcpy(joined + c + 1, path, n + 1);
    }
    /* squeeze "//", "/./" and "/x/../" */
    char *out = malloc(strlen(joined) + 2);
    if (!out) {
        free(joined);
        return NULL;
    }
    size_t k = 0;
    const char *p = joined;
    while (*p) {
        while (*p == '/')
            p++;
        if (!*p) break;
        const char *e = strchr(p, '/');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == 1 && p[0] == '.') {
            /* nothing */
        } else if (len == 2 && p[0] == '.' && p[1] == '.') {
            while (k > 0 && out[k - 1] != '/')
                k--;
            if (k > 0) k--;
        } else {
            out[k++] = '/';
            memcpy(out + k, p, len);
            k += len;
        }
        p += len;
    }
    if (k == 0) out[k++] = '/';
    out[k] = 0;
    free(joined);
    return out;
}

void scad_lookup_file(scad_eval *ev, const char *from, const char *name, scad_buf *out)
{
    if (!name[0] || name[0] == '/') {
        scad_buf_puts(out, name);
        return;
    }
    const char *slash = strrchr(from, '/');
    if (slash) scad_buf_put(out, from, (size_t)(slash - from + 1));
    scad_buf_puts(out, name);
    if (scad_file_stat(ev->d->opt, scad_buf_str(out), NULL)) return;
    /* 2021.01 falls back on the main file's folder, and says so */
    scad_buf root = {0};
    scad_buf_puts(&root, ev->d->base_dir ? ev->d->base_dir : "");
    scad_buf_puts(&root, name);
    if (strcmp(scad_buf_str(&root), scad_buf_str(out)) != 0 &&
        scad_file_stat(ev->d->opt, scad_buf_str(&root), NULL)) {
        char line[700];
        snprintf(line, sizeof line,
                 "DEPRECATED: Imported file (%.500s) found in document root instead of relative to "
                 "the importing module. This behavior is deprecated",
                 name);
        scad_diag_deprecated_line(ev->d, line);
        out->n = 0;
        scad_buf_puts(out, scad_buf_str(&root));
    }
    scad_buf_free(&root);
}

void scad_print_path(scad_eval *ev, const char *from, const char *name, scad_buf *out,
                     long long *mtime)
{
    scad_buf full = {0};
    scad_lookup_file(ev, from, name, &full);
    scad_file_stat(ev->d->opt, scad_buf_str(&full), mtime);
    scad_buf base = {0};
    scad_buf_puts(&base, ev->d->base_dir && ev->d->base_dir[0] ? ev->d->base_dir : ".");
    char *t = absolute(scad_buf_str(&full));
    char *d = absolute(scad_buf_str(&base));
    if (!t || !d) {
        scad_buf_puts(out, name);
    } else {
        /* common prefix by whole components */
        size_t i = 0, last = 0;
        size_t dl = strlen(d);
        if (dl == 1) dl = 0; /* the root folder */
        while (i < dl && t[i] == d[i]) {
            i++;
            if (d[i] == '/' || i == dl) last = i;
        }
        if (i == dl && (t[i] == '/' || t[i] == 0)) last = dl;
        for (size_t k = last; k < dl; k++)
            if (d[k] == '/') scad_buf_puts(out, "../");
        const char *rest = t + last;
        if (*rest == '/') rest++;
        scad_buf_puts(out, rest);
    }
    free(t);
    free(d);
    scad_buf_free(&full);
    scad_buf_free(&base);
}

void scad_file_path(scad_call *c, const char *name, scad_buf *out)
{
    scad_lookup_file(c->ev, c->st->loc.file ? c->st->loc.file : "", name, out);
}

void scad_file_arg_read(scad_call *c, int file, int layer, int origin, int alt_file, int alt_layer,
                        const char *who, scad_file_arg *out)
{
    scad_value f = c->arg[file];
    if (f.kind != SV_STR && alt_file >= 0) f = c->arg[alt_file];
    out->name = f.kind == SV_STR ? f.u.str->s : NULL;
    out->layer = c->arg[layer];
    if (out->layer.kind == SV_UNDEF && alt_layer >= 0) out->layer = c->arg[alt_layer];
    out->origin[0] = out->origin[1] = 0;
    scad_value o = c->arg[origin];
    double v[2];
    int ok = scad_arg_vec(o, 2, v);
    if (ok) out->origin[0] = v[0], out->origin[1] = v[1];
    if (who && o.kind != SV_UNDEF && !(ok && isfinite(v[0]) && isfinite(v[1]))) {
        scad_buf b = {0};
        scad_value_format(&b, o, 1);
        scad_diag_warning(c->ev->d, c->st->loc, "%s(..., origin=%s) could not be converted", who,
                          scad_buf_str(&b));
        scad_buf_free(&b);
    }
}

void scad_file_arg_print(scad_call *c, const scad_file_arg *f, scad_buf *b, long long *mtime)
{
    scad_buf path = {0};
    scad_print_path(c->ev, c->st->loc.file ? c->st->loc.file : "", f->name, &path, mtime);
    scad_buf_puts(b, "file = ");
    scad_quote_escaped(b, scad_buf_str(&path), strlen(scad_buf_str(&path)));
    scad_buf_free(&path);
    scad_buf_puts(b, ", layer = ");
    if (f->layer.kind == SV_STR) {
        scad_quote_escaped(b, f->layer.u.str->s, f->layer.u.str->len);
    } else if (f->layer.kind == SV_UNDEF) {
        scad_quote_escaped(b, "", 0);
    } else {
        scad_buf s = {0};
        scad_value_format(&s, f->layer, 0);
        scad_quote_escaped(b, scad_buf_str(&s), strlen(scad_buf_str(&s)));
        scad_buf_free(&s);
    }
    scad_buf_puts(b, ", origin = [");
    scad_print_g(b, f->origin[0]);
    scad_buf_puts(b, ", ");
    scad_print_g(b, f->origin[1]);
    scad_buf_puts(b, "]");
}
