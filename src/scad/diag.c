/*
 * diag.c — formatting of messages for the caller's callback.
 *
 * Errors and rayscad's own notes are compiler-style "file:line:col: error:
 * …" / "…: warning: …"; OpenSCAD's warnings follow
 * OpenSCAD 2021.01 ("WARNING: … in file x.scad, line N") so that an .echo
 * file written by openscad compares line for line.  Counters in scad_diag
 * say how many of each were sent; nothing here prints.
 */
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "ast.h"

enum { LINE_MAX_BYTES = 4096, REPEATS_SHOWN = 5 };

/* FNV-1a of a line: repeats of one warning are told apart by it. */
static uint64_t line_hash(const char *s)
{
    uint64_t h = 14695981039346656037ull;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 1099511628211ull;
    return h;
}

void scad_diag_line(scad_diag *d, scad_msg_kind kind, const char *line)
{
    if (d->stopped) return;
    if ((kind == RAYSCAD_MSG_WARNING && strncmp(line, "WARNING: ", 9) == 0) ||
        (kind == RAYSCAD_MSG_TRACE && strncmp(line, "TRACE: ", 7) == 0)) {
        /* OpenSCAD 2021.01 prints a warning or trace line at most 5 times
         * in a row (echo output between the repeats does not count; another
         * warning or trace line does) */
        uint64_t h = line_hash(line);
        if (d->warning_repeats > 0 && h == d->last_warning) {
            if (++d->warning_repeats > REPEATS_SHOWN) return;
        } else {
            d->last_warning = h;
            d->warning_repeats = 1;
        }
    }
    if (kind == RAYSCAD_MSG_WARNING) d->warnings++;
    if (kind == RAYSCAD_MSG_ERROR) d->errors++;
    if (d->opt && d->opt->message) d->opt->message(d->opt->ud, kind, line);
    if (kind == RAYSCAD_MSG_WARNING && d->hard_stop && d->opt && d->opt->hard_warnings &&
        strncmp(line, "WARNING: ", 9) == 0)
        d->hard_stop(d->hard_ud);
}

/* "file:line:col: <label>: <message>" as one line of the given kind. */
static void compiler_style(scad_diag *d, scad_msg_kind kind, const char *label, scad_loc loc,
                           const char *fmt, va_list ap)
{
    char msg[LINE_MAX_BYTES], line[LINE_MAX_BYTES + 256];
    vsnprintf(msg, sizeof msg, fmt, ap);
    snprintf(line, sizeof line, "%s:%d:%d: %s: %s", loc.file ? loc.file : "?", loc.line, loc.col,
             label, msg);
    scad_diag_line(d, kind, line);
}

void scad_diag_error(scad_diag *d, scad_loc loc, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    compiler_style(d, RAYSCAD_MSG_ERROR, "error", loc, fmt, ap);
    va_end(ap);
}

void scad_diag_note(scad_diag *d, scad_loc loc, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    compiler_style(d, RAYSCAD_MSG_NOTE, "note", loc, fmt, ap);
    va_end(ap);
}

/* The components of path (absolute, or relative to cwd), lexically
 * normalized: no ".", no empty ones, ".." taking one away (none above the
 * root), as OpenSCAD's paths are (symbolic links are not resolved).  Their
 * starts and lengths go to at/len; returns their count (at most max). */
static int components(const char *cwd, const char *path, const char **at, size_t *len, int max)
{
    int n = 0;
    for (int pass = path[0] == '/' ? 1 : 0; pass < 2; pass++) {
        const char *p = pass == 0 ? cwd : path;
        while (*p) {
            while (*p == '/')
                p++;
            const char *e = p;
            while (*e && *e != '/')
                e++;
            size_t l = (size_t)(e - p);
            if (l == 2 && p[0] == '.' && p[1] == '.') {
                if (n > 0) n--;
            } else if (l > 0 && !(l == 1 && p[0] == '.') && n < max) {
                at[n] = p;
                len[n++] = l;
            }
            p = e;
        }
    }
    return n;
}

void scad_diag_document(scad_diag *d, const char *file, const char *doc_dir)
{
    if (!d->arena || scad_diag_doc_dir(d, file) != d->base_dir) return;
    if (d->ndocs == d->capdocs) {
        int cap = d->capdocs ? 2 * d->capdocs : 16;
        const char **f = scad_arena_alloc_raw(d->arena, sizeof *f * (size_t)cap);
        const char **g = scad_arena_alloc_raw(d->arena, sizeof *g * (size_t)cap);
        if (!f || !g) return;
        if (d->ndocs) {
            memcpy(f, d->doc_files, sizeof *f * (size_t)d->ndocs);
            memcpy(g, d->doc_dirs, sizeof *g * (size_t)d->ndocs);
        }
        d->doc_files = f;
        d->doc_dirs = g;
        d->capdocs = cap;
    }
    d->doc_files[d->ndocs] = file;
    d->doc_dirs[d->ndocs++] = doc_dir;
}

const char *scad_diag_doc_dir(const scad_diag *d, const char *file)
{
    for (int i = 0; file && i < d->ndocs; i++)
        if (d->doc_files[i] == file || strcmp(d->doc_files[i], file) == 0) return d->doc_dirs[i];
    return d->base_dir;
}

/* A file name as OpenSCAD prints it: relative to the main file's folder
 * (own_doc: to its own document folder), with "../" where it lies outside,
 * into buf. */
static const char *file_shown(const scad_diag *d, const char *file, int own_doc, char *buf,
                              size_t size)
{
    enum { MAXC = 256 };
    if (!file) return "?";
    const char *base = own_doc ? scad_diag_doc_dir(d, file) : d->base_dir;
    if (!d->cwd) { /* no working directory known: the folder's prefix off */
        size_t n = base ? strlen(base) : 0;
        return n && strncmp(file, base, n) == 0 ? file + n : file;
    }
    const char *fa[MAXC], *ba[MAXC];
    size_t fl[MAXC], bl[MAXC];
    int nf = components(d->cwd, file, fa, fl, MAXC);
    int nb = components(d->cwd, base ? base : "", ba, bl, MAXC);
    int common = 0;
    while (common < nf - 1 && common < nb && fl[common] == bl[common] &&
           memcmp(fa[common], ba[common], fl[common]) == 0)
        common++;
    size_t k = 0;
    for (int i = common; i < nb && k + 3 < size; i++, k += 3)
        memcpy(buf + k, "../", 3);
    for (int i = common; i < nf && k + fl[i] + 1 < size; i++) {
        memcpy(buf + k, fa[i], fl[i]);
        k += fl[i];
        if (i + 1 < nf) buf[k++] = '/';
    }
    buf[k] = 0;
    return buf;
}

static const char *shown_file(const scad_diag *d, const char *file, char *buf, size_t size)
{
    return file_shown(d, file, 0, buf, size);
}

const char *scad_diag_file_name(const scad_diag *d, const char *file, char *buf, size_t size)
{
    return shown_file(d, file, buf, size);
}

const char *scad_diag_file_key(const scad_diag *d, const char *file, char *buf, size_t size)
{
    enum { MAXC = 256 };
    const char *at[MAXC];
    size_t len[MAXC];
    int n = components(d->cwd ? d->cwd : "", file, at, len, MAXC);
    size_t k = 0;
    for (int i = 0; i < n && k + len[i] + 2 < size; i++) {
        buf[k++] = '/';
        memcpy(buf + k, at[i], len[i]);
        k += len[i];
    }
    buf[k] = 0;
    return buf;
}

/* OpenSCAD says each deprecation once: a DEPRECATED line already sent is
 * dropped (kept in the arena; without one, every line is sent). */
static int said_before(scad_diag *d, const char *line)
{
    if (strncmp(line, "DEPRECATED: ", 12) != 0 || !d->arena) return 0;
    for (int i = 0; i < d->ndeprecated; i++)
        if (strcmp(d->deprecated[i], line) == 0) return 1;
    if (d->ndeprecated == d->capdeprecated) {
        int cap = d->capdeprecated ? 2 * d->capdeprecated : 16;
        const char **v = scad_arena_alloc_raw(d->arena, sizeof *v * (size_t)cap);
        if (!v) return 0;
        if (d->ndeprecated) memcpy(v, d->deprecated, sizeof *v * (size_t)d->ndeprecated);
        d->deprecated = v;
        d->capdeprecated = cap;
    }
    const char *copy = scad_arena_strndup(d->arena, line, strlen(line));
    if (copy) d->deprecated[d->ndeprecated++] = copy;
    return 0;
}

void scad_diag_deprecated_line(scad_diag *d, const char *line)
{
    if (!said_before(d, line)) scad_diag_line(d, RAYSCAD_MSG_WARNING, line);
}

/* "<prefix>: <message> in file <name>, line N", the file named relative to
 * the main file's folder (own_doc: to its own document folder). */
static void located(scad_diag *d, scad_loc loc, const char *prefix, int own_doc, const char *fmt,
                    va_list ap)
{
    char msg[LINE_MAX_BYTES], line[LINE_MAX_BYTES + 256], name[1024];
    vsnprintf(msg, sizeof msg, fmt, ap);
    snprintf(line, sizeof line, "%s: %s in file %s, line %d", prefix, msg,
             file_shown(d, loc.file, own_doc, name, sizeof name), loc.line);
    scad_diag_deprecated_line(d, line);
}

void scad_diag_trace(scad_diag *d, scad_loc loc, const char *fmt, ...)
{
    char msg[LINE_MAX_BYTES], line[LINE_MAX_BYTES + 256], name[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(line, sizeof line, "%s in file %s, line %d", msg,
             shown_file(d, loc.file, name, sizeof name), loc.line);
    scad_diag_line(d, RAYSCAD_MSG_TRACE, line);
}

void scad_diag_syntax(scad_diag *d, scad_loc loc)
{
    if (!d->first_syntax.file) d->first_syntax = loc;
}

void scad_diag_lex_error(scad_diag *d, scad_loc loc, int openscad_line, const char *what,
                         const char *msg)
{
    if (!d->first_syntax.file) {
        d->first_syntax = loc;
        d->first_syntax.line = openscad_line;
        d->lex_error = what;
    }
    scad_diag_error(d, loc, "%s", msg);
}

/* Unlike its other messages, openscad's parser names files as given. */
void scad_diag_parse_failed(scad_diag *d, const char *main_file)
{
    char line[LINE_MAX_BYTES];
    if (d->lex_error) {
        snprintf(line, sizeof line, "ERROR: Parser error: %s in file %s, line %d", d->lex_error,
                 d->first_syntax.file, d->first_syntax.line);
        scad_diag_line(d, RAYSCAD_MSG_TRACE, line);
    }
    if (d->first_syntax.file) {
        snprintf(line, sizeof line, "ERROR: Parser error: syntax error in file %s, line %d",
                 d->first_syntax.file, d->first_syntax.line);
        scad_diag_line(d, RAYSCAD_MSG_TRACE, line);
    }
    snprintf(line, sizeof line, "Can't parse file '%s'!", main_file);
    scad_diag_line(d, RAYSCAD_MSG_TRACE, line);
    scad_diag_line(d, RAYSCAD_MSG_TRACE, ""); /* openscad ends it with an empty line */
}

void scad_diag_warning_own_doc(scad_diag *d, scad_loc loc, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    located(d, loc, "WARNING", 1, fmt, ap);
    va_end(ap);
}

void scad_diag_warning(scad_diag *d, scad_loc loc, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    located(d, loc, "WARNING", 0, fmt, ap);
    va_end(ap);
}

void scad_diag_deprecated(scad_diag *d, scad_loc loc, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    located(d, loc, "DEPRECATED", 0, fmt, ap);
    va_end(ap);
}
